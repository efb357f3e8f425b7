// The renderer's shared inputs (Renderer::share_inputs / take_shared, ocean/vk/external.hpp) on a
// real device: a second VkDevice stands in for CUDA, imports the exported memory, writes CPU
// frames into the buffer, and the renderer's pictures must equal, byte for byte, those of the
// same frames uploaded the ordinary way (the images hold the same bytes either way). The
// synchronisation is checked both ways: the renderer's copy of frame 1, submitted before the
// producer has signalled `written`, must not run (its `read` signal stays 0) until the producer
// signals, and the producer's frame 2 waits for `read` ≥ 1 and must not show in frame 1's
// picture. Where the device exports semaphores (VK_KHR_external_semaphore_fd: NVIDIA's driver)
// the producer imports them and waits and signals on its GPU queue; where it does not (Mesa
// 22's lavapipe exports memory but no semaphore) the producer signals and waits on the host
// with the renderer's timeline semaphores (vkSignalSemaphore, vkWaitSemaphores), which tests
// the renderer's side of the exchange the same way. Skips with the reason where the device
// lacks memory export or timeline semaphores, or no Vulkan device exists (fails then with
// OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstring>
#include <iostream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "ocean/vk/external.hpp"
#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"

namespace {

using namespace ocean;
using render::testing::eye_level_view;
using render::testing::small_config;

constexpr int kSharedWidth = 96, kSharedHeight = 54;

std::shared_ptr<vk::Context> shared_context(bool graphics) {
  auto ctx =
      vk::create_context({.validation = true, .graphics = graphics, .external_interop = true});
  if (!ctx.ok()) return nullptr;
  return std::shared_ptr<vk::Context>(std::move(ctx).value());
}

// The frame's renderer inputs in interop::inputs_layout, written into `out`.
void pack_shared(const Frame& frame, const interop::InputsLayout& layout, void* out) {
  auto* bytes = static_cast<std::byte*>(out);
  for (int c = 0; c < layout.cascades; ++c) {
    const CascadeFrame& f = frame.cascades[static_cast<std::size_t>(c)];
    ASSERT_EQ(f.displacement_half.size() * 2, layout.displacement_bytes);
    ASSERT_EQ(f.packed_mips.size() * 4, layout.mips_bytes);
    std::memcpy(bytes + layout.displacement_offset(c), f.displacement_half.data(),
                layout.displacement_bytes);
    std::memcpy(bytes + layout.mips_offset(c), f.packed_mips.data(), layout.mips_bytes);
  }
}

// The stand-in for CUDA: one device that imported the shared buffer (and the semaphores, where
// they were exported; else it uses the renderer's own from the host).
struct SharedProducer {
  std::shared_ptr<vk::Context> ctx;
  vk::Buffer shared;
  VkSemaphore written = VK_NULL_HANDLE, read = VK_NULL_HANDLE;  // imported
  bool timeline = false;
  std::array<VkSemaphore, 2> host{};  // {written, read} of the renderer, without imports
  ~SharedProducer() {
    if (ctx == nullptr) return;
    vkDeviceWaitIdle(ctx->device);
    for (VkSemaphore s : {written, read})
      if (s != VK_NULL_HANDLE) vkDestroySemaphore(ctx->device, s, nullptr);
    vk::destroy_buffer(*ctx, shared);
  }
  // Copies `staging` into the shared buffer once `read` reaches wait_value (0: no wait), then
  // signals `written` = signal_value. With imported semaphores it returns at once; without, it
  // waits on the host for `read`, for its copy, then signals.
  Status write(const vk::Buffer& staging, const vk::Commands& cmds, std::uint64_t wait_value,
               std::uint64_t signal_value, const vk::Context& renderer) const {
    const bool imported = written != VK_NULL_HANDLE;
    if (!imported && wait_value > 0) {
      const VkSemaphoreWaitInfo wait{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO,
                                     .semaphoreCount = 1,
                                     .pSemaphores = &host[1],
                                     .pValues = &wait_value};
      if (Status s = vk::check(vkWaitSemaphores(renderer.device, &wait, 10'000'000'000),
                               "vkWaitSemaphores");
          !s.ok())
        return s;
    }
    VkCommandBuffer cmd = cmds.buffer;
    const VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    if (Status s = vk::check(vkBeginCommandBuffer(cmd, &begin), "begin"); !s.ok()) return s;
    const VkBufferCopy region{0, 0, staging.size};
    vkCmdCopyBuffer(cmd, staging.buffer, shared.buffer, 1, &region);
    if (Status s = vk::check(vkEndCommandBuffer(cmd), "end"); !s.ok()) return s;
    const VkPipelineStageFlags stage = VK_PIPELINE_STAGE_TRANSFER_BIT;
    const bool waits = imported && wait_value > 0;
    const VkTimelineSemaphoreSubmitInfo values{
        .sType = VK_STRUCTURE_TYPE_TIMELINE_SEMAPHORE_SUBMIT_INFO,
        .waitSemaphoreValueCount = waits ? 1u : 0u,
        .pWaitSemaphoreValues = &wait_value,
        .signalSemaphoreValueCount = imported ? 1u : 0u,
        .pSignalSemaphoreValues = &signal_value};
    const VkSubmitInfo submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
                              .pNext = imported && timeline ? &values : nullptr,
                              .waitSemaphoreCount = waits ? 1u : 0u,
                              .pWaitSemaphores = &read,
                              .pWaitDstStageMask = &stage,
                              .commandBufferCount = 1,
                              .pCommandBuffers = &cmd,
                              .signalSemaphoreCount = imported ? 1u : 0u,
                              .pSignalSemaphores = &written};
    if (Status s = vk::check(vkQueueSubmit(ctx->queue, 1, &submit, cmds.fence), "vkQueueSubmit");
        !s.ok())
      return s;
    if (imported) return {};
    if (Status s = vk::wait(*ctx, cmds); !s.ok()) return s;  // the copy is in the buffer
    const VkSemaphoreSignalInfo signal{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SIGNAL_INFO,
                                       .semaphore = host[0],
                                       .value = signal_value};
    return vk::check(vkSignalSemaphore(renderer.device, &signal), "vkSignalSemaphore");
  }
};

// The value of the renderer's timeline semaphore `s`.
std::uint64_t semaphore_value(const vk::Context& ctx, VkSemaphore s) {
  std::uint64_t value = 0;
  EXPECT_EQ(vkGetSemaphoreCounterValue(ctx.device, s, &value), VK_SUCCESS);
  return value;
}

std::vector<std::uint8_t> draw_shared(render::Renderer& r) {
  std::vector<std::uint8_t> srgb;
  EXPECT_TRUE(r.draw(eye_level_view(kSharedWidth, kSharedHeight)).ok());
  EXPECT_TRUE(r.read_srgb(srgb).ok());
  return srgb;
}

TEST(SharedInputs, ASecondDeviceWritesWhatTheRendererSamplesInStep) {
  std::shared_ptr<vk::Context> ctx = shared_context(true);
  if (ctx == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  if (!ctx->external_memory_fd)
    GTEST_SKIP() << "Vulkan device '" << ctx->info.name << "' lacks VK_KHR_external_memory_fd";
  if (!ctx->external_semaphore_fd && !ctx->timeline_semaphore)
    GTEST_SKIP() << "Vulkan device '" << ctx->info.name
                 << "' has neither exportable nor timeline semaphores";
  const SimulationConfig config = small_config();
  auto renderer = render::Renderer::make(ctx, {.width = kSharedWidth, .height = kSharedHeight});
  ASSERT_TRUE(renderer.ok()) << renderer.status().message();
  render::Renderer& r = *renderer.value();
  ASSERT_TRUE(r.configure(ocean::SimulationPlan::make(config).value().surface()).ok());

  // Two frames a second apart, and the pictures of them uploaded the ordinary way.
  auto sim = Simulator::make(config, make_backend("cpu").value());
  ASSERT_TRUE(sim.ok());
  sim.value()->step(1.0);
  const Frame first = sim.value()->frame();
  sim.value()->step(2.0);
  const Frame second = sim.value()->frame();
  ASSERT_TRUE(r.upload(first).ok());
  const std::vector<std::uint8_t> expected_first = draw_shared(r);
  ASSERT_TRUE(r.upload(second).ok());
  const std::vector<std::uint8_t> expected_second = draw_shared(r);
  ASSERT_NE(expected_first, expected_second);

  Result<interop::SharedInputs> exported = r.share_inputs();
  ASSERT_TRUE(exported.ok()) << exported.status().message();
  interop::SharedInputs shared = exported.value();
  EXPECT_GE(shared.memory_bytes, shared.layout.bytes());
  EXPECT_EQ(shared.written_fd >= 0, ctx->external_semaphore_fd);
  std::cout << "semaphores: "
            << (shared.written_fd >= 0
                    ? "exported, imported by the producer"
                    : "not exportable here: the producer uses them from the host")
            << (shared.timeline ? " (timeline)" : " (binary)") << "\n";

  SharedProducer p;
  p.ctx = shared_context(false);
  ASSERT_NE(p.ctx, nullptr);
  ASSERT_EQ(p.ctx->device_uuid, ctx->device_uuid);
  p.timeline = shared.timeline;
  p.host = r.shared_semaphores();
  Result<vk::Buffer> imported = vk::import_buffer(
      *p.ctx, shared.memory_fd, {.bytes = shared.memory_bytes, .dedicated = shared.dedicated},
      shared.layout.bytes(), VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  ASSERT_TRUE(imported.ok()) << imported.status().message();
  p.shared = imported.value();
  shared.memory_fd = -1;  // the import owns it
  for (auto [fd, semaphore] :
       {std::pair{&shared.written_fd, &p.written}, std::pair{&shared.read_fd, &p.read}}) {
    if (*fd < 0) continue;
    Result<VkSemaphore> s = vk::import_semaphore(*p.ctx, *fd, shared.timeline);
    ASSERT_TRUE(s.ok()) << s.status().message();
    *semaphore = s.value();
    *fd = -1;
  }
  std::vector<vk::Buffer> staging;
  std::vector<vk::Commands> commands;
  for (const Frame* f : {&first, &second}) {
    auto b = vk::create_buffer(*p.ctx, shared.layout.bytes(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                               vk::MemoryUse::upload);
    ASSERT_TRUE(b.ok());
    staging.push_back(b.value());
    pack_shared(*f, shared.layout, b.value().mapped);
    commands.push_back(vk::create_commands(*p.ctx).value());
  }

  const bool host = p.written == VK_NULL_HANDLE;
  if (host) {
    // The renderer's copy of frame 1 waits for `written` ≥ 1: submitted first, it must not run
    // (`read` stays 0) until the producer has written the frame and signalled.
    ASSERT_TRUE(r.take_shared(1).ok());
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    EXPECT_EQ(semaphore_value(*ctx, p.host[1]), 0u);
    ASSERT_TRUE(p.write(staging[0], commands[0], 0, 1, *ctx).ok());
    // Frame 2 waits for `read` ≥ 1 (the copy of frame 1) on the host before writing.
    ASSERT_TRUE(p.write(staging[1], commands[1], 1, 2, *ctx).ok());
    EXPECT_EQ(semaphore_value(*ctx, p.host[0]), 2u);
    EXPECT_EQ(semaphore_value(*ctx, p.host[1]), 1u);
    // Frame 1's picture was copied before frame 2 was written: a draw now still shows frame 1
    // (at frame 1's time, which the far field and the short waves take from the frame).
    ASSERT_TRUE(r.set_far_noise(first).ok());
    EXPECT_EQ(draw_shared(r), expected_first);
  } else {
    ASSERT_TRUE(p.write(staging[0], commands[0], 0, 1, *ctx).ok());
    if (shared.timeline) {
      // Frame 2's write waits for the renderer to have read frame 1: it must not run before.
      ASSERT_TRUE(p.write(staging[1], commands[1], 1, 2, *ctx).ok());
      EXPECT_EQ(vkWaitForFences(p.ctx->device, 1, &commands[1].fence, VK_TRUE, 200'000'000),
                VK_TIMEOUT);
    }
    ASSERT_TRUE(r.take_shared(1).ok());
    ASSERT_TRUE(r.set_far_noise(first).ok());
    EXPECT_EQ(draw_shared(r),
              expected_first);  // frame 1, whole: frame 2 did not overwrite it early
    if (!shared.timeline) {     // a binary signal must be waited for before it is signalled again
      ASSERT_TRUE(p.write(staging[1], commands[1], 1, 2, *ctx).ok());
    }
    ASSERT_TRUE(vk::wait(*p.ctx, commands[1]).ok());
    ASSERT_TRUE(vk::wait(*p.ctx, commands[0]).ok());
  }
  ASSERT_TRUE(r.take_shared(2).ok());
  ASSERT_TRUE(r.set_far_noise(second).ok());
  EXPECT_EQ(draw_shared(r), expected_second);
  if (shared.timeline) {
    EXPECT_EQ(semaphore_value(*ctx, p.host[1]), 2u);
  }

  for (vk::Buffer& b : staging) vk::destroy_buffer(*p.ctx, b);
  for (vk::Commands& c : commands) vk::destroy_commands(*p.ctx, c);
  EXPECT_EQ(ctx->validation_messages.load(), 0u) << ctx->last_validation_message;
  EXPECT_EQ(p.ctx->validation_messages.load(), 0u) << p.ctx->last_validation_message;
}

TEST(SharedInputs, NeedsTheExtensionsAndAConfiguration) {
  auto plain = vk::create_context({.validation = true, .graphics = true});
  if (!plain.ok()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  std::shared_ptr<vk::Context> ctx(std::move(plain).value());
  auto renderer = render::Renderer::make(ctx, {.width = 16, .height = 16});
  ASSERT_TRUE(renderer.ok());
  Result<interop::SharedInputs> early = renderer.value()->share_inputs();
  EXPECT_EQ(early.status().code(), ErrorCode::invalid_argument);
  ASSERT_TRUE(renderer.value()
                  ->configure(ocean::SimulationPlan::make(small_config()).value().surface())
                  .ok());
  Result<interop::SharedInputs> refused = renderer.value()->share_inputs();
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.status().code(), ErrorCode::unsupported);
  EXPECT_NE(refused.status().message().find("VK_KHR_external_memory_fd"), std::string::npos)
      << refused.status().message();
  EXPECT_EQ(renderer.value()->take_shared(1).code(), ErrorCode::invalid_argument);
}

}  // namespace
