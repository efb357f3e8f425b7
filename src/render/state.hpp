// What every pass of the renderer shares (src/render, private): the Vulkan objects of a renderer
// that are not one feature's (Renderer::State: context, commands, targets, the simulation's
// images, the scene set and pipelines, the patch mesh, the frame uniforms' buffer), its formats
// and limits, the passes (passes.hpp: one object per feature, pass.hpp their shape) and the steps
// the public methods are built from, one concern per file:
//   targets.cpp      the state's lifetime and the HDR, depth and sRGB targets
//   descriptors.cpp  the shared samplers, the scene set (its layout from the passes' bindings)
//   pipelines.cpp    shader modules, the scene pipeline layout, the sky/ocean/wireframe pipelines
//   mesh.cpp         the static patch mesh and the per-frame skirt vertices
//   inputs.cpp       the simulation's images: own ones filled by upload, or borrowed ones
//   uniforms.cpp     the per-frame uniforms every pass shares
//   frame.cpp        the recorded frame: LOD selection, the passes' uploads, HDR pass, post pass
//   relative.cpp     large worlds and curvature: positions relative to the grid centre
//   renderer.cpp     construction, resizing, submission, read-back
// and the passes' own files (src/render/README.md lists them).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "formats.hpp"
#include "ocean/render.hpp"
#include "ocean/sphere.hpp"
#include "passes.hpp"
#include "pipeline_desc.hpp"
#include "shaders/render_shared.h"
#include "shaders/tessellation.h"
#include "tessellation_push.hpp"

namespace ocean::render {

inline constexpr auto kSkirtLevel = static_cast<std::uint8_t>(OCEAN_RENDER_SKIRT_LEVEL);

struct Renderer::State {
  const vk::Context* ctx = nullptr;
  vk::Commands commands;
  // Targets.
  vk::Image2D hdr, depth, srgb;
  vk::Buffer readback;  // large enough for the HDR image (8 bytes per pixel)
  // Simulation inputs: own images (upload path) or borrowed ones (GPU path).
  vk::Image displacement, normal_foam;
  vk::Buffer staging;
  bool upload_pending = false;
  bool borrowed = false;
  VkImageView displacement_view = VK_NULL_HANDLE, normal_view = VK_NULL_HANDLE;
  std::uint32_t sim_size = 0, sim_layers = 0, sim_mips = 0;
  // Shared path (shared_inputs.cpp): the exported buffer the simulation writes, the semaphores,
  // and the commands that copy it into the images.
  vk::Buffer shared;
  VkSemaphore shared_written = VK_NULL_HANDLE, shared_read = VK_NULL_HANDLE;
  bool shared_timeline = false;
  vk::Commands shared_commands;
  bool shared_in_flight = false;
  // Samplers, descriptors, pipelines.
  VkSampler displacement_sampler = VK_NULL_HANDLE, normal_sampler = VK_NULL_HANDLE,
            hdr_sampler = VK_NULL_HANDLE;
  bool scene_images_ready = false;  // every pass has made its images: the scene set may be written
  VkDescriptorSetLayout scene_layout = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkDescriptorSet scene_set = VK_NULL_HANDLE;
  VkPipelineLayout scene_pipeline_layout = VK_NULL_HANDLE;
  VkPipeline sky = VK_NULL_HANDLE, ocean = VK_NULL_HANDLE, wire = VK_NULL_HANDLE;
  std::vector<VkShaderModule> modules;
  vk::Buffer uniforms;
  // Geometry.
  int vertices = 0;                    // V of the patch mesh now built
  vk::Buffer patch_vertices, indices;  // static
  std::array<std::uint32_t, lod::kConfigurations> index_first{}, index_count{};
  std::uint32_t skirt_first = 0, skirt_count = 0;
  vk::Buffer instances, skirt_vertices;  // per frame, host-visible
  lod::LodSelection selection;
  lod::SkirtMesh skirt;
  double skirt_size = -1.0, skirt_extent = -1.0;
  vk::Timestamps timestamps;
  bool has_timestamps = false;
  // From configure().
  int cascades = 0;
  std::array<shader::CascadeUniforms, kMaxCascades> cascade_params{};
  std::array<double, kMaxCascades> patch_size_m{};  // L_c in double, for the origin's phase (R.16)
  double hs_m = 1.0;
  double crest_bound_m = 1.7;       // SurfaceDescription's bound on |h|, m
  double horizontal_reach_m = 1.0;  // SurfaceDescription's bound on |(Dx, Dz)|, m
  double choppiness = 1.0;
  std::optional<double> unresolved_slope_variance;  // SurfaceDescription's, from configure()
  double map_base_normal_length = 1.0;              // SurfaceDescription's, from configure()
  std::array<double, 2> foam_ramp{0.8, 0.5};  // FoamParams' J start and full, from configure()
  std::vector<double> foam_weights;  // SurfaceDescription's (empty: the cascades' foam united)
  std::array<double, 2> foam_drift_mps{0.0, 0.0};  // SurfaceDescription's, from configure()
  double foam_decay_time_s = 0.0;                  // SurfaceDescription's, from configure()
  double peak_period_s = 0.0;  // SurfaceDescription's T_p: the swash's period (W.40–W.43)
  Passes passes;                     // one object per feature (passes.hpp)

  ~State();
  void destroy_targets();
  void destroy_sim_images();
  void destroy_shared();
};

// The pass P of the renderer (passes.hpp).
template <class P>
P& pass(Renderer::State& st) {
  return std::get<P>(st.passes);
}
template <class P>
const P& pass(const Renderer::State& st) {
  return std::get<P>(st.passes);
}
// Calls f(pass) on each pass, in the order of passes.hpp.
template <class F>
void for_each_pass(Renderer::State& st, F&& f) {
  std::apply([&](auto&... p) { (f(p), ...); }, st.passes);
}
template <class F>
void for_each_pass(const Renderer::State& st, F&& f) {
  std::apply([&](const auto&... p) { (f(p), ...); }, st.passes);
}

// targets.cpp: whether targets of this size fit the device and memory (Renderer::resize's
// refusals, after its [1, kMaxTargetSize] check); allocates nothing.
Status check_target_size(const vk::Context& ctx, int width, int height);
// The HDR, depth and sRGB targets and the read-back buffer; points the tone map's descriptor at
// the new HDR image.
Status create_targets(Renderer::State& st, int width, int height);

// descriptors.cpp: samplers, both set layouts, the pool and the two sets.
Status create_descriptors(Renderer::State& st);
// The scene set's uniform buffer and sky table, and the simulation images when there are any.
void write_scene_images(Renderer::State& st);
// One image the renderer drew (SHADER_READ_ONLY_OPTIMAL, the HDR sampler) into a set's binding.
void write_rendered_image(const Renderer::State& st, VkDescriptorSet set, std::uint32_t binding,
                          VkImageView view);

// pipelines.cpp: pipeline layouts, shader modules and the four pipelines (the wireframe one only
// where the device has fillModeNonSolid).
Status create_pipelines(Renderer::State& st);

// mesh.cpp: the patch mesh of V quads per side — vertices and the 16 index lists, plus the
// skirt's indices (4 rotated copies of its kSkirtTessellation grid over per-frame vertices).
inline constexpr lod::SkirtTessellation kSkirtTessellation{.segments = 64, .rings = 40};
inline constexpr int kSkirtVertices =
    4 * (kSkirtTessellation.segments + 1) * (kSkirtTessellation.rings + 1);
Status build_patch_buffers(Renderer::State& st, int vertices);
// The skirt's vertices relative to the frame's origin (the selection's grid centre), out to
// `extent_m` (skirt_extent_m), rebuilding the skirt when the ocean size or the extent changed.
Status write_skirt_vertices(Renderer::State& st, const View& view, double extent_m);

// relative.cpp: large worlds and the planet's curvature (R.15, R.16). The frame's origin is the
// selection's grid centre; everything handed to the GPU is relative to it.
// The camera moved by −origin (its view-projection is what the GPU draws with).
lod::Camera relative_camera(const lod::Camera& camera, const lod::LodSelection& selection);
// The selection's instances relative to the origin, written to `out` (sel.instances.size()).
void write_relative_instances(const lod::LodSelection& selection, double ocean_size_m,
                              lod::PatchInstance* out);
// The skirt's outer half-extent: the view's, or where it is ≤ 0 the larger of 10·S and 1.25
// times the horizon's distance √(2R(h + Hs)), rounded up to a power of two (R.15).
double skirt_extent_m(const View& view, double hs_m);
// How far the curvature drops the sea inside the ocean square below the camera's tangent
// plane, at most (widens the culling boxes).
double curvature_drop_bound_m(const View& view);
// FrameUniforms::planet and cascade_origin for this frame.
void fill_origin_uniforms(const Renderer::State& st, const View& view, shader::FrameUniforms& u);

// sphere.cpp: the sea on a sphere (R.30–R.38, the pass: sphere.hpp). Selects the cube-sphere's
// patches and writes their instances; sets `vp` (relative to the
// camera, local axes) and the uniforms that differ from the flat sea's.
Status prepare_sphere(Renderer::State& st, const View& view, lod::Mat4& vp,
                      shader::FrameUniforms& u);

// inputs.cpp: copies the staged CPU frame into the own images (GENERAL).
void record_uploads(Renderer::State& st, VkCommandBuffer cmd);
// The same copies from `source`, a buffer in interop::inputs_layout (inputs.cpp).
void record_uploads(Renderer::State& st, VkCommandBuffer cmd, VkBuffer source);

// tessellation.cpp: the tessellated mesh (its pass: tessellation.hpp) and its push range in the
// scene layout.
// `unsupported` when the parameters ask for the tessellated mesh on a device without tessellation
// shaders or with a maxTessellationGenerationLevel below N; nothing for the quadtree.
Status check_tessellation(const vk::Context& ctx, const TessellationParams& params);
VkPushConstantRange tessellation_push_range();

// uniforms.cpp: the frame's uniforms every pass shares.
void fill_uniforms(const Renderer::State& st, const View& view, const lod::Mat4& vp,
                   shader::FrameUniforms& u);
// Inverse of a 4×4 column-major matrix by cofactors (double precision).
std::array<double, 16> inverse(const std::array<double, 16>& m);

// stereo.cpp: releases the layered targets (with `all`, the multiview pipelines too).
void destroy_stereo(Renderer::State& st, bool all);
// motion.cpp: releases the motion target and the previous frame (with `all`, the pipelines,
// layouts and descriptors too).
void destroy_motion(Renderer::State& st, bool all);

}  // namespace ocean::render
