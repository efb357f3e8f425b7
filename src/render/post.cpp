// The tone map (post.hpp): the HDR image through shaders/tonemap.frag into the sRGB target, one
// fullscreen triangle with the exposure pushed (shaders/render_shared.h's TonemapPush).
#include "post.hpp"

#include "pipeline_desc.hpp"
#include "spirv.hpp"
#include "state.hpp"

namespace ocean::render {

Status PostPass::create(Renderer::State& st) {
  const std::uint32_t binding = OCEAN_RENDER_BINDING_HDR;
  return make_fullscreen(st,
                         {.frag = spirv::tonemap_frag(),
                          .colour = kSrgbFormat,
                          .samplers = {&binding, 1},
                          .push_bytes = sizeof(shader::TonemapPush)},
                         objects, {&set, 1});
}

void PostPass::destroy(Renderer::State& st) { destroy_fullscreen(st.ctx->device, objects); }

Status PostPass::resize(Renderer::State& st) {
  write_rendered_image(st, set, OCEAN_RENDER_BINDING_HDR, st.hdr.view);
  return {};
}

void PostPass::record(Renderer::State& st, VkCommandBuffer cmd, const FrameContext& frame) {
  const std::uint32_t w = st.hdr.width, h = st.hdr.height;
  vk::image_barrier(cmd, st.srgb.image, VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                    VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
  const shader::TonemapPush push{static_cast<float>(frame.view.shading.exposure)};
  draw_fullscreen(cmd, {.target = st.srgb.view,
                        .width = w,
                        .height = h,
                        .pipeline = objects.pipeline,
                        .layout = objects.layout,
                        .set = set,
                        .push = &push,
                        .push_bytes = sizeof(push)});
  ++frame.stats.draw_calls;
  vk::image_barrier(cmd, st.srgb.image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_TRANSFER_READ_BIT);
}

}  // namespace ocean::render
