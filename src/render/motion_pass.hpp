// Motion vectors (src/render, private; docs/rendering.md R.26): the RG16F target the motion pass
// draws into, its pipelines and layout, and the previous frame it reprojects to — a copy of the
// cascades' displacement array and the camera. Made by Renderer::set_motion_vectors(true).
#pragma once

#include <array>
#include <optional>

#include "ocean/lod.hpp"
#include "ocean/vk.hpp"
#include "pass.hpp"

namespace ocean::render {

// render pass 1100: MotionPass — motion vectors (R.26)
struct MotionPass : Pass {
  bool enabled = false;
  vk::Image2D target;           // RG16F, NDC motion (now − previous), the renderer's size
  vk::Image previous;           // the displacement array of the previous frame (GENERAL)
  bool previous_valid = false;  // `previous` and `camera` hold the last drawn frame
  lod::Camera camera;           // the previous frame's camera, world metres
  // A stereo frame (R.61): the eyes of the previous one (valid when previous_stereo), the
  // multiview pipelines and the layered target of one eye's size, made on the first.
  bool previous_stereo = false;
  std::array<lod::Camera, 2> eye_cameras;
  vk::Image2D stereo_target;
  VkPipeline sky_mv = VK_NULL_HANDLE, ocean_mv = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline sky = VK_NULL_HANDLE, ocean = VK_NULL_HANDLE;

  void destroy(Renderer::State& st);          // everything
  void release_targets(Renderer::State& st);  // the target and the previous frame
  // After the HDR pass, with motion vectors on: the motion pass over st.depth (record_motion).
  void record(Renderer::State& st, VkCommandBuffer cmd, const FrameContext& frame);
};

}  // namespace ocean::render
