// The shared path of the simulation's inputs (ocean/interop.hpp): a buffer another API on the same
// GPU (CUDA) writes, exported with two semaphores, and the per-frame copy of it into the sampled
// images between a wait for "written" and a signal of "read" (Vulkan spec 1.3, "Semaphores",
// timeline semaphores and VkTimelineSemaphoreSubmitInfo; "Copying Data Between Buffers and
// Images").
#include <string>

#include "ocean/vk/external.hpp"
#include "state.hpp"

namespace ocean::render {

void Renderer::State::destroy_shared() {
  if (ctx == nullptr) return;
  if (shared_in_flight) (void)vk::wait(*ctx, shared_commands);
  shared_in_flight = false;
  vk::destroy_commands(*ctx, shared_commands);
  for (VkSemaphore* s : {&shared_written, &shared_read}) {
    if (*s != VK_NULL_HANDLE) vkDestroySemaphore(ctx->device, *s, nullptr);
    *s = VK_NULL_HANDLE;
  }
  vk::destroy_buffer(*ctx, shared);
}

namespace {

// A timeline semaphore of this device only (initial value 0).
Result<VkSemaphore> create_timeline_semaphore(const vk::Context& ctx) {
  const VkSemaphoreTypeCreateInfo type{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO,
                                       .semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE};
  const VkSemaphoreCreateInfo info{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO,
                                   .pNext = &type};
  VkSemaphore semaphore = VK_NULL_HANDLE;
  if (Status s =
          vk::check(vkCreateSemaphore(ctx.device, &info, nullptr, &semaphore), "vkCreateSemaphore");
      !s.ok())
    return s;
  return semaphore;
}

}  // namespace

std::array<VkSemaphore, 2> Renderer::shared_semaphores() const {
  return {state_->shared_written, state_->shared_read};
}

Result<interop::SharedInputs> Renderer::share_inputs() {
  State& st = *state_;
  if (st.displacement.image == VK_NULL_HANDLE)
    return invalid_argument("renderer: share_inputs() before configure()");
  vkDeviceWaitIdle(st.ctx->device);
  st.destroy_shared();
  interop::SharedInputs out;
  out.layout =
      interop::inputs_layout(static_cast<int>(st.sim_size), static_cast<int>(st.sim_layers));
  if (!st.ctx->external_memory_fd)
    return unsupported("Vulkan device '" + st.ctx->info.name +
                       "': VK_KHR_external_memory_fd is not enabled "
                       "(ContextParams::external_interop)");
  // Exported semaphores where the device can (timeline ones where those export); else local
  // timeline semaphores, for a producer on the host or on this device (shared_semaphores()).
  const bool exported_semaphores = st.ctx->external_semaphore_fd;
  out.timeline = exported_semaphores ? st.ctx->timeline_exportable : st.ctx->timeline_semaphore;
  if (!exported_semaphores && !out.timeline)
    return unsupported("Vulkan device '" + st.ctx->info.name +
                       "' lacks VK_KHR_external_semaphore_fd and timeline semaphores");
  vk::ExportedAllocation allocation;
  Result<vk::Buffer> buffer = vk::create_exportable_buffer(
      *st.ctx, out.layout.bytes(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, allocation);
  Status s = buffer.status();
  if (s.ok()) {
    st.shared = buffer.value();
    out.memory_bytes = allocation.bytes;
    out.dedicated = allocation.dedicated;
    Result<int> fd = vk::export_memory_fd(*st.ctx, st.shared.memory);
    s = fd.status();
    if (s.ok()) out.memory_fd = fd.value();
  }
  for (auto [semaphore, fd] :
       {std::pair{&st.shared_written, &out.written_fd}, std::pair{&st.shared_read, &out.read_fd}}) {
    if (!s.ok()) break;
    Result<VkSemaphore> made = exported_semaphores
                                   ? vk::create_exportable_semaphore(*st.ctx, out.timeline)
                                   : create_timeline_semaphore(*st.ctx);
    s = made.status();
    if (!s.ok()) break;
    *semaphore = made.value();
    if (!exported_semaphores) continue;
    Result<int> exported = vk::export_semaphore_fd(*st.ctx, *semaphore);
    s = exported.status();
    if (s.ok()) *fd = exported.value();
  }
  if (s.ok()) {
    Result<vk::Commands> commands = vk::create_commands(*st.ctx);
    s = commands.status();
    if (s.ok()) st.shared_commands = commands.value();
  }
  if (!s.ok()) {
    interop::close_unimported(out);
    st.destroy_shared();
    return s;
  }
  st.shared_timeline = out.timeline;
  return out;
}

Status Renderer::take_shared(std::uint64_t frame) {
  State& st = *state_;
  if (st.shared.buffer == VK_NULL_HANDLE)
    return invalid_argument("renderer: take_shared() before share_inputs()");
  if (frame == 0) return invalid_argument("renderer: take_shared(0): frames count from 1");
  if (st.shared_in_flight) {
    if (Status s = vk::wait(*st.ctx, st.shared_commands); !s.ok()) return s;
    st.shared_in_flight = false;
  }
  VkCommandBuffer cmd = st.shared_commands.buffer;
  if (Status s = vk::check(vkResetCommandBuffer(cmd, 0), "vkResetCommandBuffer"); !s.ok()) return s;
  const VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                       .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
  if (Status s = vk::check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer"); !s.ok())
    return s;
  // The simulation's writes are made visible by the semaphore wait (its memory dependency
  // covers every access); the copy's barrier to the shaders reaches the later draws, which come
  // after it in submission order.
  record_uploads(st, cmd, st.shared.buffer);
  if (Status s = vk::check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer"); !s.ok()) return s;
  const VkPipelineStageFlags wait_stage = VK_PIPELINE_STAGE_TRANSFER_BIT;
  const VkTimelineSemaphoreSubmitInfo values{
      .sType = VK_STRUCTURE_TYPE_TIMELINE_SEMAPHORE_SUBMIT_INFO,
      .waitSemaphoreValueCount = 1,
      .pWaitSemaphoreValues = &frame,
      .signalSemaphoreValueCount = 1,
      .pSignalSemaphoreValues = &frame};
  const VkSubmitInfo submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
                            .pNext = st.shared_timeline ? &values : nullptr,
                            .waitSemaphoreCount = 1,
                            .pWaitSemaphores = &st.shared_written,
                            .pWaitDstStageMask = &wait_stage,
                            .commandBufferCount = 1,
                            .pCommandBuffers = &cmd,
                            .signalSemaphoreCount = 1,
                            .pSignalSemaphores = &st.shared_read};
  if (Status s = vk::check(vkQueueSubmit(st.ctx->queue, 1, &submit, st.shared_commands.fence),
                           "vkQueueSubmit (shared inputs)");
      !s.ok())
    return s;
  st.shared_in_flight = true;
  st.upload_pending = false;
  if (st.borrowed) {
    st.borrowed = false;
    st.displacement_view = st.displacement.view;
    st.normal_view = st.normal_foam.view;
    write_scene_images(st);
  }
  return {};
}

}  // namespace ocean::render
