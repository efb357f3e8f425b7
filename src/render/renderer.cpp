// The Vulkan ocean renderer (ocean/render.hpp): construction, resizing, submission and read-back.
// The pieces live beside it (state.hpp lists them); shaders in shaders/ (ocean.*, sky.*,
// tonemap.frag, wire.frag); equations R.n in docs/rendering.md.
#include <cstring>
#include <string>

#include "ocean/half.hpp"
#include "state.hpp"

namespace ocean::render {

Result<std::unique_ptr<Renderer>> Renderer::make(std::shared_ptr<vk::Context> context,
                                                 const RendererParams& params) {
  if (context == nullptr) return invalid_argument("renderer: no Vulkan context");
  if (!context->graphics)
    return unsupported("renderer: the Vulkan context was created without a graphics queue");
  std::unique_ptr<Renderer> r(new Renderer());
  r->context_ = std::move(context);
  r->state_ = std::make_unique<State>();
  State& st = *r->state_;
  st.ctx = r->context_.get();
  Result<vk::Commands> commands = vk::create_commands(*st.ctx);
  if (!commands.ok()) return commands.status();
  st.commands = commands.value();
  if (Status s = create_descriptors(st); !s.ok()) return s;
  if (Status s = create_pipelines(st); !s.ok()) return s;
  Result<vk::Buffer> ubo =
      vk::create_buffer(*st.ctx, sizeof(shader::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                        vk::MemoryUse::upload);
  if (!ubo.ok()) return ubo.status();
  st.uniforms = ubo.value();
  Status created;
  for_each_pass(st, [&](auto& p) {
    if (created.ok()) created = p.create(st);
  });
  if (!created.ok()) return created;
  st.scene_images_ready = true;
  if (Status s = r->set_environment(nullptr); !s.ok()) return s;  // writes the scene's set
  // Instances: the most any selection can hold (W² at S = 8192) and the skirt's one.
  if (Status s = lod::reserve_selection(st.selection, lod::kMaxOceanSize_m); !s.ok()) return s;
  const int w = 1 << lod::max_level(lod::kMaxOceanSize_m);
  Result<vk::Buffer> inst =
      vk::create_buffer(*st.ctx, static_cast<VkDeviceSize>(w * w + 1) * sizeof(lod::PatchInstance),
                        VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, vk::MemoryUse::upload);
  if (!inst.ok()) return inst.status();
  st.instances = inst.value();
  Result<vk::Buffer> skirt =
      vk::create_buffer(*st.ctx, kSkirtVertices * 2 * sizeof(float),
                        VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, vk::MemoryUse::upload);
  if (!skirt.ok()) return skirt.status();
  st.skirt_vertices = skirt.value();
  if (st.ctx->timestamps) {
    Result<vk::Timestamps> ts = vk::create_timestamps(*st.ctx, 2);
    if (ts.ok()) st.timestamps = ts.value(), st.has_timestamps = true;
  }
  if (Status s = r->resize(params.width, params.height); !s.ok()) return s;
  return r;
}

Renderer::~Renderer() = default;

Status Renderer::resize(int width, int height) {
  if (width < 1 || height < 1 || width > kMaxTargetSize || height > kMaxTargetSize)
    return invalid_argument("image size " + std::to_string(width) + "x" + std::to_string(height) +
                            " must be between 1x1 and " + std::to_string(kMaxTargetSize) + "x" +
                            std::to_string(kMaxTargetSize));
  if (Status s = check_target_size(*state_->ctx, width, height); !s.ok()) return s;
  vkDeviceWaitIdle(state_->ctx->device);
  state_->destroy_targets();
  return create_targets(*state_, width, height);
}

int Renderer::width() const { return static_cast<int>(state_->hdr.width); }
int Renderer::height() const { return static_cast<int>(state_->hdr.height); }
VkImage Renderer::srgb_image() const { return state_->srgb.image; }
double Renderer::significant_wave_height_m() const { return state_->hs_m; }

Result<double> Renderer::read_gpu_ms() {
  State& st = *state_;
  if (!st.has_timestamps) return 0.0;
  double ms[2];
  if (Status s = vk::read_timestamps_ms(*st.ctx, st.timestamps, ms); !s.ok()) return s;
  stats_.gpu_ms = ms[1];
  return ms[1];
}

Status Renderer::draw(const View& view) {
  State& st = *state_;
  // Mesh changes upload through the renderer's own command buffer: before recording into it.
  if (Status s = prepare(view); !s.ok()) return s;
  Status recorded;
  const Status run = vk::run_once(*st.ctx, st.commands,
                                  [&](VkCommandBuffer cmd) { recorded = record(cmd, view); });
  if (!recorded.ok()) return recorded;
  if (!run.ok()) return run;
  return read_gpu_ms().status();
}

Status Renderer::read_srgb(std::vector<std::uint8_t>& rgba) {
  State& st = *state_;
  const std::uint32_t w = st.srgb.width, h = st.srgb.height;
  const Status s = vk::run_once(*st.ctx, st.commands, [&](VkCommandBuffer cmd) {
    const VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                   .imageExtent = {w, h, 1}};
    vkCmdCopyImageToBuffer(cmd, st.srgb.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           st.readback.buffer, 1, &region);
    vk::barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT);
  });
  if (!s.ok()) return s;
  rgba.resize(static_cast<std::size_t>(w) * h * 4);
  std::memcpy(rgba.data(), st.readback.mapped, rgba.size());
  return {};
}

Status Renderer::read_hdr(std::vector<float>& rgba) {
  State& st = *state_;
  const std::uint32_t w = st.hdr.width, h = st.hdr.height;
  const Status s = vk::run_once(*st.ctx, st.commands, [&](VkCommandBuffer cmd) {
    vk::image_barrier(cmd, st.hdr.image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                      0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    const VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                   .imageExtent = {w, h, 1}};
    vkCmdCopyImageToBuffer(cmd, st.hdr.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           st.readback.buffer, 1, &region);
    vk::barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT);
    vk::image_barrier(cmd, st.hdr.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                      VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0);
  });
  if (!s.ok()) return s;
  const std::size_t n = static_cast<std::size_t>(w) * h * 4;
  rgba.resize(n);
  const auto* half = static_cast<const std::uint16_t*>(st.readback.mapped);
  for (std::size_t i = 0; i < n; ++i) rgba[i] = half_to_float(half[i]);
  return {};
}

}  // namespace ocean::render
