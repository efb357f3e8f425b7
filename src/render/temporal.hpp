// Temporal anti-aliasing (src/render, private; View::temporal_aa; docs/rendering.md R.61), a pass
// written whole in this header (pass.hpp): its hooks are templates on the renderer's state,
// instantiated where the renderer calls them.
//
// Each mono frame's projection is moved by a sub-pixel offset of the Halton (2, 3) sequence
// (Halton 1964), so that 16 successive frames sample each pixel at 16 well-spread points. After
// the HDR pass and the motion vectors (R.26), shaders/temporal.frag blends the frame into the
// history — the last result, fetched where the pixel's surface point was a frame ago and clipped
// to the colour box of the frame's 3 × 3 neighbourhood (Salvi 2016, variance clipping) in Karis's
// (2014) luminance-weighted space — and the result, kept for the next frame, replaces the HDR
// image before the tone map. Pixels that hold still (the frame's alpha: the sky, and the sea
// where a pixel spans the finest cascade's tile) blend with a fifth of the weight in a wider box.
// A stereo frame's eyes, side by side, are jittered each in its own pixels and blended each on
// its own, along its own motion vectors (stereo.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "motion_pass.hpp"
#include "pass.hpp"
#include "pipeline_desc.hpp"
#include "spirv.hpp"

OCEAN_RENDER_SPIRV(temporal_frag)

namespace ocean::render {

// The radical inverse of i in `base` (Halton 1964): 1 → ½, 2 → ¼, 3 → ¾ … in base 2.
inline double radical_inverse(int i, int base) {
  double f = 1.0, r = 0.0;
  for (; i > 0; i /= base) {
    f /= base;
    r += f * (i % base);
  }
  return r;
}

// render pass 1200: TemporalPass — temporal anti-aliasing of the HDR image (R.61)
struct TemporalPass : Pass {
  static constexpr int kJitterPositions = 16;  // the Halton points before the sequence repeats
  // The colour box's half-width in standard deviations of the frame's 3 × 3 neighbourhood: one
  // (Salvi's) clips a still's 16-draw mean to 0.5–0.6 of the plain picture's error, two to 0.3
  // (tests/render/supersample_render_test.cpp).
  static constexpr float kClipSigmas = 2.0f;
  // Where the frame's pixel spans the finest cascade's tile (its alpha, ocean.frag) or shows the
  // sky, the picture changes little from frame to frame and the history holds: the frame weighs a
  // fifth of current_weight (the default 0.2 → 0.04, an exponential mean of (2 − α)/α = 49
  // frames, three jitter cycles) and the box is widened to 3 σ, so that neither each jittered
  // frame's share nor the clip to each frame's noisy box flickers there
  // (tests/render/supersample_render_test.cpp).
  static constexpr double kSteadyShare = 0.2;
  static constexpr float kSteadyClipSigmas = 3.0f;
  vk::Image2D history[2];  // RGBA16F, the picture's size, written in turn
  VkImageLayout history_layout[2] = {VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_UNDEFINED};
  int written = 0;       // the history image the last frame wrote
  int frames = 0;        // frames blended since the history was started (0: none)
  int jitter_index = 0;  // the next frame's Halton point, 0 … kJitterPositions − 1
  int history_eyes = 1;  // the pictures side by side in the history (2: a stereo frame's eyes)
  // The images each set was last written with (set i reads history[1 − i]).
  VkImageView set_hdr[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
  VkImageView set_motion[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
  VkSampler history_sampler = VK_NULL_HANDLE;  // bilinear, clamped to the edge
  FullscreenObjects objects;  // the blend's set layout, pool, pipeline layout and pipeline
  VkDescriptorSet sets[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};

  // The frame's sub-pixel offset, pixels, in [−½, ½)².
  std::array<double, 2> jitter_px() const {
    return {radical_inverse(jitter_index + 1, 2) - 0.5, radical_inverse(jitter_index + 1, 3) - 0.5};
  }

  // What it cannot draw (the weight's range is validate(View)'s, with the view's other values).
  template <class State>
  Status check(const State& st, const View& view) const {
    const View::TemporalAntiAliasing& t = view.temporal_aa;
    if (!t.enabled) return {};
    if (view.sphere.enabled || view.tessellation.mesh == MeshMode::tessellation)
      return unsupported(std::string("temporal anti-aliasing: not drawn for ") +
                         (view.sphere.enabled ? "the sea on a sphere" : "the tessellated mesh") +
                         " (it draws no motion vectors)");
    if (!std::get<MotionPass>(st.passes).enabled)
      return invalid_argument(
          "temporal anti-aliasing: needs motion vectors (Renderer::set_motion_vectors(true))");
    return {};
  }

  template <class State>
  Status create(State& st) {
    const vk::Context& ctx = *st.ctx;
    Result<VkSampler> sampler = make_sampler(ctx, true, false, false, 1.0f);
    if (!sampler.ok()) return sampler.status();
    history_sampler = sampler.value();
    const std::uint32_t bindings[3] = {0, 1, 2};  // the frame, the history, the motion
    return make_fullscreen(st,
                           {.frag = spirv::temporal_frag(),
                            .colour = kHdrFormat,
                            .samplers = bindings,
                            .push_bytes = 6 * sizeof(float)},
                           objects, sets);
  }

  template <class State>
  void release_targets(State& st) {
    for (vk::Image2D& h : history) vk::destroy_image(*st.ctx, h);
    history_layout[0] = history_layout[1] = VK_IMAGE_LAYOUT_UNDEFINED;
    set_hdr[0] = set_hdr[1] = set_motion[0] = set_motion[1] = VK_NULL_HANDLE;
    frames = 0;
  }

  template <class State>
  void destroy(State& st) {
    release_targets(st);
    const VkDevice d = st.ctx->device;
    destroy_fullscreen(d, objects);
    if (history_sampler != VK_NULL_HANDLE) vkDestroySampler(d, history_sampler, nullptr);
  }

  // The jitter: clip x and y move by the offset's NDC share times w, row 3 of the matrix
  // (column-major) added to rows 0 and 1. The motion vectors subtract it again (ocean.vert), so
  // that a still camera's are 0 and the history is read at pixel centres, not resampled.
  template <class State>
  void fill_uniforms(const State& st, const View& view, shader::FrameUniforms& u) const {
    if (!view.temporal_aa.enabled) return;
    const std::array<double, 2> j = jitter_px();
    const auto dx = static_cast<float>(2.0 * j[0] / st.hdr.width);
    const auto dy = static_cast<float>(2.0 * j[1] / st.hdr.height);
    for (int c = 0; c < 4; ++c) {
      u.view_proj.m[c * 4 + 0] += dx * u.view_proj.m[c * 4 + 3];
      u.view_proj.m[c * 4 + 1] += dy * u.view_proj.m[c * 4 + 3];
    }
    u.jitter_ndc_x = dx;
    u.jitter_ndc_y = dy;
    u.footprint_scale = static_cast<float>(1.0 / std::sqrt(double{kJitterPositions}));
  }

  // Stereo (R.25): each eye's matrix moved by the same offset in its own pixels (the eyes side by
  // side, each half the HDR image's width), after fill_uniforms.
  template <class State>
  void jitter_eyes(const State& st, const View& view, shader::FrameUniforms& u) const {
    if (!view.temporal_aa.enabled) return;
    const std::array<double, 2> j = jitter_px();
    const auto dx = static_cast<float>(2.0 * j[0] / (st.hdr.width / 2));
    const auto dy = static_cast<float>(2.0 * j[1] / st.hdr.height);
    for (shader::EyeUniforms& eye : u.eyes)
      for (int c = 0; c < 4; ++c) {
        eye.view_proj.m[c * 4 + 0] += dx * eye.view_proj.m[c * 4 + 3];
        eye.view_proj.m[c * 4 + 1] += dy * eye.view_proj.m[c * 4 + 3];
      }
    u.jitter_ndc_x = dx;
    u.jitter_ndc_y = dy;
  }

  template <class State>
  Status after_scene(State& st, VkCommandBuffer cmd, const FrameContext& frame) {
    if (!frame.view.temporal_aa.enabled) {
      frames = 0;
      return {};
    }
    const std::uint32_t w = st.hdr.width, h = st.hdr.height;
    for (vk::Image2D& image : history) {  // made on first use and after a resize
      if (image.image != VK_NULL_HANDLE && image.width == w && image.height == h) continue;
      release_targets(st);
      for (vk::Image2D& made : history) {
        Result<vk::Image2D> r =
            vk::create_image_2d(*st.ctx, kHdrFormat, w, h,
                                VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                    VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
        if (!r.ok()) return r.status();
        made = r.value();
      }
      break;
    }
    if (history_eyes != frame.eyes) frames = 0;  // mono after stereo or back: a new history
    history_eyes = frame.eyes;
    const MotionPass& motion = std::get<MotionPass>(st.passes);
    const int now = 1 - written, before = written;
    if (set_hdr[now] != st.hdr.view || set_motion[now] != motion.target.view) {
      const VkDescriptorImageInfo images[3] = {
          {st.hdr_sampler, st.hdr.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
          {history_sampler, history[before].view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
          {st.hdr_sampler, motion.target.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}};
      VkWriteDescriptorSet writes[3];
      for (std::uint32_t b = 0; b < 3; ++b)
        writes[b] = {.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                     .dstSet = sets[now],
                     .dstBinding = b,
                     .descriptorCount = 1,
                     .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                     .pImageInfo = &images[b]};
      vkUpdateDescriptorSets(st.ctx->device, 3, writes, 0, nullptr);
      set_hdr[now] = st.hdr.view;
      set_motion[now] = motion.target.view;
    }
    // The frame, its motion and the last result become shader inputs; the new result a target.
    vk::image_barrier(cmd, st.hdr.image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                      VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                      VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                      VK_ACCESS_SHADER_READ_BIT);
    vk::image_barrier(cmd, motion.target.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                      VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
    vk::image_barrier(cmd, history[before].image, history_layout[before],
                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                      VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
    vk::image_barrier(cmd, history[now].image, VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                      VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                      VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    // The first frames are their plain mean; then the configured weight (a fifth of it where the
    // picture holds still).
    const float push[6] = {static_cast<float>(frame.view.temporal_aa.current_weight),
                           static_cast<float>(1.0 / static_cast<double>(frames + 1)),
                           kClipSigmas,
                           static_cast<float>(kSteadyShare * frame.view.temporal_aa.current_weight),
                           kSteadyClipSigmas,
                           static_cast<float>(frame.eyes)};
    draw_fullscreen(cmd, {.target = history[now].view,
                          .width = w,
                          .height = h,
                          .pipeline = objects.pipeline,
                          .layout = objects.layout,
                          .set = sets[now],
                          .push = push,
                          .push_bytes = sizeof(push)});
    ++frame.stats.draw_calls;
    // The result into the HDR image, which goes on as the HDR pass left it; the motion back to
    // where read_motion() copies it from.
    vk::image_barrier(cmd, history[now].image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                      VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                      VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                      VK_ACCESS_TRANSFER_READ_BIT);
    vk::image_barrier(cmd, st.hdr.image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                      VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                      0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    const VkImageCopy region{.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                             .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                             .extent = {w, h, 1}};
    vkCmdCopyImage(cmd, history[now].image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, st.hdr.image,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    vk::image_barrier(cmd, st.hdr.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                      VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                      VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    vk::image_barrier(cmd, motion.target.image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                      0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    history_layout[now] = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    history_layout[before] = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    written = now;
    ++frames;
    jitter_index = (jitter_index + 1) % kJitterPositions;
    return {};
  }
};

}  // namespace ocean::render
