// The object pass of the renderer (src/render, private; docs/rendering.md R.20–R.21): the meshes
// given to Renderer::set_meshes in device-local buffers, their pipeline, and the recording of
// View::objects inside the HDR pass, after the water, depth-tested with it.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ocean/render.hpp"
#include "pass.hpp"

namespace ocean::render {

// render pass 900: ObjectPass — the objects and their reflection (R.20–R.21, R.53)
struct ObjectPass : Pass {
  struct MeshBuffers {
    vk::Buffer vertices, indices;  // interleaved (position, normal) floats; uint32 indices
    std::uint32_t index_count = 0;
    Material material;
  };
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  std::vector<MeshBuffers> meshes;
  // The objects mirrored in the sea level (R.53, reflection.cpp): half-resolution colour (alpha:
  // coverage) and depth while there are meshes, 1×1 otherwise.
  vk::Image2D reflection, reflection_depth;
  // Bilinear through the reflection's mip chain (R.53b): each water pixel reads it over the
  // footprint its reflected rays cover.
  VkSampler reflection_sampler = VK_NULL_HANDLE;

  // The pipeline layout (the scene set, ObjectPush) and the pipeline.
  Status create(Renderer::State& st);
  void destroy(Renderer::State& st);
  // The reflection target at the picture's size (size_reflection).
  Status resize(Renderer::State& st);
  void release_targets(Renderer::State& st);
  void scene_images(const Renderer::State& st, SceneImages& images) const;  // the reflection
};

// An object pipeline on that layout from these shaders, drawing the views of `view_mask`
// (0: one view; the stereo pass builds its multiview one this way). Owned by the caller.
Result<VkPipeline> make_object_pipeline(Renderer::State& st, std::span<const std::uint32_t> vert,
                                        std::span<const std::uint32_t> frag,
                                        std::uint32_t view_mask);
// Draws view.objects (mesh indices checked by validate_objects) inside the HDR pass, whose
// viewport and scene set are bound, with `pipeline` (null: the mono one). Returns the draws and
// triangles added. With `mirrored`, the objects mirrored in y = 0 for the reflection target (R.53).
void record_objects(Renderer::State& st, VkCommandBuffer cmd, const View& view, RenderStats& stats,
                    VkPipeline pipeline = VK_NULL_HANDLE, bool mirrored = false);
// reflection.cpp (R.53): the reflection target sized for the picture (half its resolution while
// there are meshes, 1×1 otherwise) and written into the scene set; and its pass, recorded
// outside any render pass before the HDR pass.
Status size_reflection(Renderer::State& st);
void record_reflection(Renderer::State& st, VkCommandBuffer cmd, const View& view,
                       RenderStats& stats);
// invalid_argument for an instance whose mesh index is not below the meshes set.
Status validate_objects(const Renderer::State& st, const View& view);
// Releases the meshes (and, with `all`, the pipeline and its layout).
void destroy_objects(Renderer::State& st, bool all);

}  // namespace ocean::render
