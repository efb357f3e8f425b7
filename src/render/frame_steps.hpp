// The steps of a recorded frame (src/render, private), shared by the mono frame (frame.cpp) and
// the stereo frame drawn in one pass (stereo.cpp): LOD selection and the per-frame buffers,
// pending uploads, the HDR pass's draws, the tone map.
#pragma once

#include "state.hpp"

namespace ocean::render {

// The pipelines of the HDR pass: one view (mono) or both eyes at once (multiview).
struct ScenePipelines {
  VkPipeline sky = VK_NULL_HANDLE, ocean = VK_NULL_HANDLE, objects = VK_NULL_HANDLE;
  std::uint32_t sky_vertices = 3;  // the fullscreen triangle; the multiview sky's quad: 6
};

// The checks every recorded frame makes first: the view (validate), its objects' meshes and, for
// a wireframe view, a device that draws one.
Status check_view(const Renderer::State& st, const View& view);
// The frame's uniforms for the view-projection `vp` (relative to the grid centre, R.16): the
// shading, the cascades' origins, the environment and the water seen from below.
void fill_frame_uniforms(const Renderer::State& st, const View& view, const lod::Mat4& vp,
                         shader::FrameUniforms& u);
// LOD selection from `lod_position` culled by `frustum` (Aebi, VR Ocean, §5) with boxes that
// include the waves' reach; writes the instances (relative to the grid centre, R.16) and the
// skirt's vertices; returns the skirt's instance index. Sets stats.cpu_select_ms.
Result<std::uint32_t> select_frame(Renderer::State& st, const View& view, lod::Vec3 lod_position,
                                   const lod::Frustum& frustum, RenderStats& stats);
// The start timestamp, the pending uploads (sky table, local layer, damping, CPU frame) or the
// barrier after a backend's compute, and the barrier after the host's writes of this frame.
void begin_frame(Renderer::State& st, VkCommandBuffer cmd);
// Clears `colour` and `depth` (all their layers) and begins the HDR pass over them drawing the
// views of `view_mask`, with the flipped viewport and the scene set bound.
void begin_scene(Renderer::State& st, VkCommandBuffer cmd, const vk::Image2D& colour,
                 const vk::Image2D& depth, std::uint32_t view_mask);
// Inside the HDR pass: the sky, the patches by stitching configuration, the skirt, the objects.
void record_scene(Renderer::State& st, VkCommandBuffer cmd, const View& view,
                  const ScenePipelines& pipelines, const shader::SkyPush& sky_push,
                  std::uint32_t skirt_instance, RenderStats& stats);
// Inside a pass whose pipeline takes the patch layout: the patches by stitching configuration
// (without `quadtree`: none, the tessellated mesh drew the square) and the skirt (bound buffers,
// draws, and with `stats` their counts).
void record_patches(Renderer::State& st, VkCommandBuffer cmd, std::uint32_t skirt_instance,
                    RenderStats* stats, bool quadtree = true);
// motion.cpp: with motion vectors on, before recording: the target and the previous frame's
// array at the current sizes (allocates when they changed); unsupported on borrowed images.
Status prepare_motion(Renderer::State& st);
// After the HDR pass: the motion pass over st.depth (cleared again) into the motion target for
// `camera`, then this frame kept as the previous one.
void record_motion(Renderer::State& st, VkCommandBuffer cmd, const lod::Camera& camera,
                   std::uint32_t skirt_instance);
// Stereo (R.61): each eye's previous view-projection and sky reprojection into u.eyes (the eyes
// of the last stereo frame; none before one: no motion), before the uniforms are written.
void fill_stereo_motion(const Renderer::State& st, const std::array<lod::Camera, 2>& eyes,
                        shader::FrameUniforms& u);
// After the stereo HDR pass: both eyes' motion in one multiview pass over `depth` (the layered
// stereo depth, cleared again), side by side into the motion target; the frame kept as the
// previous one.
Status record_stereo_motion(Renderer::State& st, VkCommandBuffer cmd,
                            const std::array<lod::Camera, 2>& eyes, const lod::Camera& head,
                            const vk::Image2D& depth, std::uint32_t skirt_instance);
// stereo.cpp: a column-major double matrix as the shaders' float one.
shader::mat4 to_mat4(const std::array<double, 16>& m);
// Tone maps st.hdr (in `hdr_layout`, written by `src_stage`/`src_access`) into st.srgb with the
// post pass, leaves it in TRANSFER_SRC_OPTIMAL and writes the end timestamp.
void finish_frame(Renderer::State& st, VkCommandBuffer cmd, const View& view,
                  VkImageLayout hdr_layout, VkPipelineStageFlags src_stage,
                  VkAccessFlags src_access, RenderStats& stats);

}  // namespace ocean::render
