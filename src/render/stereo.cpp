// Stereo in one pass (Renderer::record_stereo; docs/rendering.md R.25): both eyes share the
// simulation's images, one LOD selection and every draw; VK_KHR_multiview runs each draw for
// view 0 (left eye) and view 1 (right eye) into the layers of one-eye targets, the shaders
// picking their eye's matrix and position by gl_ViewIndex (OCEAN_MULTIVIEW). The layers are then
// copied side by side into the HDR target and tone-mapped as a mono frame.
#include <cmath>
#include <cstring>
#include <string>

#include "frame_steps.hpp"
#include "pipeline_desc.hpp"
#include "spirv.hpp"
#include "state.hpp"

namespace ocean::render {

namespace {

constexpr std::uint32_t kBothEyes = 0b11;

// The multiview pipelines, once per renderer.
Status create_stereo_pipelines(Renderer::State& st) {
  StereoPass& sp = pass<StereoPass>(st);
  if (sp.ocean != VK_NULL_HANDLE) return {};
  Result<VkShaderModule> sky_vert = shader_module(st, spirv::sky_vert_mv());
  Result<VkShaderModule> sky_frag = shader_module(st, spirv::sky_frag_mv());
  Result<VkShaderModule> ocean_vert = shader_module(st, spirv::ocean_vert_mv());
  Result<VkShaderModule> ocean_frag = shader_module(st, spirv::ocean_frag_mv());
  Result<VkShaderModule> wire_frag = shader_module(st, spirv::wire_frag());
  for (const auto* m : {&sky_vert, &sky_frag, &ocean_vert, &ocean_frag, &wire_frag})
    if (!m->ok()) return m->status();
  const PipelineDesc sky{.vert = sky_vert.value(),
                         .frag = sky_frag.value(),
                         .layout = st.scene_pipeline_layout,
                         .depth_test = false,
                         .view_mask = kBothEyes};
  const PipelineDesc ocean{.vert = ocean_vert.value(),
                           .frag = ocean_frag.value(),
                           .layout = st.scene_pipeline_layout,
                           .mesh_input = true,
                           .view_mask = kBothEyes};
  PipelineDesc wire = ocean;
  wire.frag = wire_frag.value(), wire.lines = true;
  Result<VkPipeline> p = make_pipeline(*st.ctx, sky);
  if (p.ok()) sp.sky = p.value(), p = make_pipeline(*st.ctx, ocean);
  if (p.ok()) sp.ocean = p.value(), p = st.ctx->wireframe ? make_pipeline(*st.ctx, wire) : p;
  if (p.ok() && st.ctx->wireframe) sp.wire = p.value();
  if (p.ok())
    p = make_object_pipeline(st, spirv::object_vert_mv(), spirv::object_frag_mv(), kBothEyes);
  if (p.ok()) sp.objects = p.value();
  return p.status();
}

// Layered HDR and depth targets of one eye's size (after a resize, again).
Status create_stereo_targets(Renderer::State& st) {
  StereoPass& sp = pass<StereoPass>(st);
  const std::uint32_t w = st.hdr.width / 2, h = st.hdr.height;
  if (sp.hdr.image != VK_NULL_HANDLE && sp.hdr.width == w && sp.hdr.height == h) return {};
  destroy_stereo(st, false);
  Result<vk::Image2D> hdr =
      vk::create_image_2d(*st.ctx, kHdrFormat, w, h,
                          VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                          VK_IMAGE_ASPECT_COLOR_BIT, 2);
  if (!hdr.ok()) return hdr.status();
  sp.hdr = hdr.value();
  Result<vk::Image2D> depth =
      vk::create_image_2d(*st.ctx, kDepthFormat, w, h, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                          VK_IMAGE_ASPECT_DEPTH_BIT, 2);
  if (!depth.ok()) return depth.status();
  sp.depth = depth.value();
  return {};
}

}  // namespace

shader::mat4 to_mat4(const std::array<double, 16>& m) {
  shader::mat4 out{};
  for (std::size_t i = 0; i < 16; ++i) out.m[i] = static_cast<float>(m[i]);
  return out;
}

Result<std::array<lod::Camera, 2>> stereo_eyes(const lod::Camera& head, double ipd_m) {
  if (!std::isfinite(ipd_m) || ipd_m < 0.0)
    return invalid_argument("IPD " + excerpt(std::to_string(ipd_m)) + " m must be finite and ≥ 0");
  const lod::Vec3 p = head.position_m, t = head.target_m;
  const double fx = t.x - p.x, fy = t.y - p.y, fz = t.z - p.z;
  // Right = forward × up (the head's up, +y unless it rolls), as lod::look_at; looking along
  // up, forward × −z.
  const lod::Vec3 u = head.up;
  double rx = fy * u.z - fz * u.y, ry = fz * u.x - fx * u.z, rz = fx * u.y - fy * u.x;
  if (rx * rx + ry * ry + rz * rz < 1e-24 * (fx * fx + fy * fy + fz * fz))
    rx = -fy, ry = fx, rz = 0.0;
  const double len = std::sqrt(rx * rx + ry * ry + rz * rz);
  std::array<lod::Camera, 2> eyes{head, head};
  for (int e = 0; e < 2; ++e) {
    const double s = (e == 0 ? -0.5 : 0.5) * ipd_m / (len > 0.0 ? len : 1.0);
    lod::Camera& c = eyes[static_cast<std::size_t>(e)];
    c.position_m = {p.x + s * rx, p.y + s * ry, p.z + s * rz};
    c.target_m = {t.x + s * rx, t.y + s * ry, t.z + s * rz};
  }
  return eyes;
}

void destroy_stereo(Renderer::State& st, bool all) {
  StereoPass& sp = pass<StereoPass>(st);
  vk::destroy_image(*st.ctx, sp.hdr);
  vk::destroy_image(*st.ctx, sp.depth);
  if (!all) return;
  for (VkPipeline* p : {&sp.sky, &sp.ocean, &sp.wire, &sp.objects}) {
    if (*p != VK_NULL_HANDLE) vkDestroyPipeline(st.ctx->device, *p, nullptr);
    *p = VK_NULL_HANDLE;
  }
}

void StereoPass::destroy(Renderer::State& st) { destroy_stereo(st, true); }
void StereoPass::release_targets(Renderer::State& st) { destroy_stereo(st, false); }

Status Renderer::record_stereo(VkCommandBuffer cmd, const View& view, double ipd_m) {
  Result<std::array<lod::Camera, 2>> eyes = stereo_eyes(view.camera, ipd_m);
  if (!eyes.ok()) return eyes.status();
  return record_stereo(cmd, view, eyes.value());
}

Status Renderer::record_stereo(VkCommandBuffer cmd, const View& view,
                               const std::array<lod::Camera, 2>& eyes) {
  State& st = *state_;
  if (!st.ctx->multiview)
    return unsupported("stereo: the Vulkan device '" + st.ctx->info.name +
                       "' lacks multiview (VK_KHR_multiview)");
  for (std::size_t e = 0; e < 2; ++e) {
    if (Status s = lod::validate(eyes[e]); !s.ok())
      return invalid_argument(std::string(e == 0 ? "left" : "right") + " eye: " + s.message());
  }
  if (st.hdr.width % 2 != 0)
    return invalid_argument("stereo: the image width " + std::to_string(st.hdr.width) +
                            " must be even (two eyes side by side)");
  if (Status s = check_view(st, view); !s.ok()) return s;
  if (view.sphere.enabled) return unsupported("stereo: not drawn for the sea on a sphere");
  if (view.tessellation.mesh == MeshMode::tessellation)
    return unsupported("stereo: not drawn with the tessellated mesh");
  if (Status s = create_stereo_pipelines(st); !s.ok()) return s;
  if (Status s = create_stereo_targets(st); !s.ok()) return s;
  if (Status s = prepare(view); !s.ok()) return s;
  if (Status s = prepare_motion(st); !s.ok()) return s;
  // One selection for both eyes: distances from the head, culled by the planes that bound both
  // frusta (R.25, docs/lod.md L.13): for parallel eyes the left eye's left plane, the right
  // eye's right plane and the shared others; for a headset's canted, rolled eyes each side's
  // plane moved out past the other eye's corners.
  Result<std::uint32_t> skirt_instance = select_frame(
      st, view, view.camera.position_m, lod::bounding_frustum(eyes[0], eyes[1]), stats_);
  if (!skirt_instance.ok()) return skirt_instance.status();
  const lod::LodSelection& sel = st.selection;
  shader::FrameUniforms u{};
  fill_frame_uniforms(st, view, lod::view_projection(relative_camera(view.camera, sel)), u);
  for (std::size_t e = 0; e < 2; ++e) {
    const lod::Camera eye = relative_camera(eyes[e], sel);
    const lod::Mat4 vp = lod::view_projection(eye);
    u.eyes[e].view_proj = to_mat4(vp.m);
    u.eyes[e].inverse_view_proj = to_mat4(inverse(vp.m));
    u.eyes[e].camera_pos_m = {static_cast<float>(eye.position_m.x),
                              static_cast<float>(eye.position_m.y),
                              static_cast<float>(eye.position_m.z), 0.0f};
  }
  // Temporal anti-aliasing (R.61): each eye jittered in its own pixels; the motion vectors
  // reproject each eye to where it was a frame ago.
  pass<TemporalPass>(st).jitter_eyes(st, view, u);
  fill_stereo_motion(st, eyes, u);
  std::memcpy(st.uniforms.mapped, &u, sizeof(u));

  begin_frame(st, cmd);
  // The planar reflection (R.53) is one view's: in stereo the water mirrors no object (the target
  // is cleared and the water shows the sky's reflection).
  View unmirrored = view;
  unmirrored.object_reflections = false;
  record_reflection(st, cmd, unmirrored, stats_);
  const StereoPass& sp = pass<StereoPass>(st);
  begin_scene(st, cmd, sp.hdr, sp.depth, kBothEyes);
  record_scene(st, cmd, view,
               {.sky = sp.sky,
                .ocean = view.debug == DebugView::wireframe ? sp.wire : sp.ocean,
                .objects = sp.objects,
                .sky_vertices = 6},
               shader::SkyPush{}, skirt_instance.value(), stats_);
  vkCmdEndRendering(cmd);
  // The eyes' layers side by side into the HDR target.
  vk::image_barrier(cmd, sp.hdr.image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_TRANSFER_READ_BIT);
  vk::image_barrier(cmd, st.hdr.image, VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0,
                    VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
  VkImageCopy regions[2];
  for (std::uint32_t e = 0; e < 2; ++e)
    regions[e] = {.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, e, 1},
                  .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                  .dstOffset = {static_cast<std::int32_t>(e * sp.hdr.width), 0, 0},
                  .extent = {sp.hdr.width, sp.hdr.height, 1}};
  vkCmdCopyImage(cmd, sp.hdr.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, st.hdr.image,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 2, regions);
  if (pass<MotionPass>(st).enabled) {
    // Both eyes' motion side by side as the picture is, then the temporal blend per eye (R.61),
    // which takes and leaves the HDR image as a colour attachment.
    if (Status s =
            record_stereo_motion(st, cmd, eyes, view.camera, sp.depth, skirt_instance.value());
        !s.ok())
      return s;
    vk::image_barrier(cmd, st.hdr.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                      VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                      VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    const FrameContext frame{view, stats_, skirt_instance.value(), 2};
    if (Status s = pass<TemporalPass>(st).after_scene(st, cmd, frame); !s.ok()) return s;
    finish_frame(st, cmd, view, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                 VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                 VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, stats_);
    return {};
  }
  finish_frame(st, cmd, view, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
               VK_ACCESS_TRANSFER_WRITE_BIT, stats_);
  return {};
}

Status Renderer::draw_stereo(const View& view, double ipd_m) {
  Result<std::array<lod::Camera, 2>> eyes = stereo_eyes(view.camera, ipd_m);
  if (!eyes.ok()) return eyes.status();
  return draw_stereo(view, eyes.value());
}

Status Renderer::draw_stereo(const View& view, const std::array<lod::Camera, 2>& eyes) {
  State& st = *state_;
  if (Status s = prepare(view); !s.ok()) return s;
  Status recorded;
  const Status run = vk::run_once(*st.ctx, st.commands, [&](VkCommandBuffer cmd) {
    recorded = record_stereo(cmd, view, eyes);
  });
  if (!recorded.ok()) return recorded;
  if (!run.ok()) return run;
  return read_gpu_ms().status();
}

}  // namespace ocean::render
