// The sea on a sphere in the renderer (docs/rendering.md R.30–R.38): the view's local axes at
// (latitude, longitude), the cube-sphere selection of ocean/sphere.hpp with culling planes in
// planet-centred metres, the patches' centres relative to the camera in double precision, the
// uniforms, and the pipeline and draws of shaders/sphere.vert and sphere.frag.
//
// Sources: Cozzi & Ring, "3D Engine Design for Virtual Globes" (2011), ch. 5 (rendering relative
// to the eye with positions chosen in double precision on the CPU).
#include "ocean/sphere.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "pipeline_desc.hpp"
#include "sphere.hpp"
#include "sphere_view.hpp"
#include "spirv.hpp"
#include "state.hpp"

namespace ocean::render {

namespace {

// What the GPU reads per patch (sphere.vert's instance attributes); 32 bytes.
struct SphereInstance {
  float centre_m[3];  // the patch's centre on the sphere relative to the camera, local axes
  float size;         // side in cube coordinates
  float cube[3];      // the centre's cube point, dyadic (exact)
  std::uint8_t face, level, config, pad;
};
static_assert(sizeof(SphereInstance) == 32);
// The most patches one frame draws; a view that selects more is refused.
constexpr std::size_t kMaxSphereInstances = 1u << 16;

}  // namespace

Status SpherePass::create(Renderer::State& st) {
  Result<vk::Buffer> inst = vk::create_buffer(
      *st.ctx, static_cast<VkDeviceSize>(kMaxSphereInstances * sizeof(SphereInstance)),
      VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, vk::MemoryUse::upload);
  if (!inst.ok()) return inst.status();
  instances = inst.value();
  Result<VkShaderModule> vert = shader_module(st, spirv::sphere_vert());
  if (!vert.ok()) return vert.status();
  Result<VkShaderModule> frag = shader_module(st, spirv::sphere_frag());
  if (!frag.ok()) return frag.status();
  const VkVertexInputBindingDescription bindings[] = {
      {0, 2 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX},
      {1, sizeof(SphereInstance), VK_VERTEX_INPUT_RATE_INSTANCE}};
  const VkVertexInputAttributeDescription attributes[] = {
      {0, 0, VK_FORMAT_R32G32_SFLOAT, 0},
      {1, 1, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(SphereInstance, centre_m)},
      {2, 1, VK_FORMAT_R32G32B32_SFLOAT, offsetof(SphereInstance, cube)},
      {3, 1, VK_FORMAT_R8G8B8A8_UINT, offsetof(SphereInstance, face)}};
  const VkPipelineVertexInputStateCreateInfo input{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
      .vertexBindingDescriptionCount = 2,
      .pVertexBindingDescriptions = bindings,
      .vertexAttributeDescriptionCount = 4,
      .pVertexAttributeDescriptions = attributes};
  Result<VkPipeline> p = make_pipeline(*st.ctx, {.vert = vert.value(),
                                                 .frag = frag.value(),
                                                 .layout = st.scene_pipeline_layout,
                                                 .vertex_input = &input});
  if (!p.ok()) return p.status();
  pipeline = p.value();
  return {};
}

void SpherePass::destroy(Renderer::State& st) {
  if (pipeline != VK_NULL_HANDLE) vkDestroyPipeline(st.ctx->device, pipeline, nullptr);
  vk::destroy_buffer(*st.ctx, instances);
}

Status prepare_sphere(Renderer::State& st, const View& view, lod::Mat4& vp,
                      shader::FrameUniforms& u) {
  const LocalAxes axes = local_axes(view.sphere);
  const lod::Vec3 eye = camera_planet(view, axes);
  const double r = view.planet_radius_m;
  // The GPU draws relative to the camera, in the local axes (R.38).
  lod::Camera rel = view.camera;
  rel.position_m = {0.0, 0.0, 0.0};
  rel.target_m = {view.camera.target_m.x - view.camera.position_m.x,
                  view.camera.target_m.y - view.camera.position_m.y,
                  view.camera.target_m.z - view.camera.position_m.z};
  vp = lod::view_projection(rel);
  // The culling planes in planet-centred metres: vp · (p ↦ axes·(p − eye)).
  lod::Mat4 planet_to_rel;
  const lod::Vec3 shifted = axes.apply(eye);
  const double t[3] = {shifted.x, shifted.y, shifted.z};
  for (std::size_t row = 0; row < 3; ++row) {
    const lod::Vec3& a = axes.rows[row];
    planet_to_rel.m[row] = a.x, planet_to_rel.m[4 + row] = a.y, planet_to_rel.m[8 + row] = a.z;
    planet_to_rel.m[12 + row] = -t[row];
  }
  planet_to_rel.m[15] = 1.0;
  // Σw ≤ √3 for weights whose squares sum to one (R.32): the tri-planar sea's reach.
  const double reach = std::sqrt(3.0);
  const sphere::SphereLodParams lp{
      .radius_m = r,
      .quality = view.quality,
      .camera_position_m = eye,
      .frustum = lod::frustum_from_view_projection(vp * planet_to_rel),
      .finest_patch_m = view.sphere.finest_patch_m,
      .max_vertical_displacement_m = reach * st.crest_bound_m,
      .max_horizontal_displacement_m = reach * st.choppiness * st.hs_m};
  SpherePass& sp = pass<SpherePass>(st);
  if (Status s = sphere::select_sphere_patches(lp, sp.selection); !s.ok()) return s;
  const sphere::SphereSelection& sel = sp.selection;
  if (sel.patches.size() > kMaxSphereInstances)
    return invalid_argument("the sphere's selection holds " + std::to_string(sel.patches.size()) +
                            " patches, more than " + std::to_string(kMaxSphereInstances) +
                            ": raise sphere.finest_patch_m");
  auto* out = static_cast<SphereInstance*>(sp.instances.mapped);
  for (std::size_t i = 0; i < sel.patches.size(); ++i) {
    const sphere::SpherePatch& p = sel.patches[i];
    const lod::Vec3 cube = sphere::cube_point(p.face, p.centre_u, p.centre_v);
    const lod::Vec3 d = sphere::cube_to_sphere(cube);
    const lod::Vec3 c = axes.apply({d.x * r - eye.x, d.y * r - eye.y, d.z * r - eye.z});
    out[i] = {
        .centre_m = {static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z)},
        .size = static_cast<float>(p.size),
        .cube = {static_cast<float>(cube.x), static_cast<float>(cube.y),
                 static_cast<float>(cube.z)},
        .face = p.face,
        .level = p.level,
        .config = p.config,
        .pad = 0};
  }
  for (int i = 0; i < 16; ++i)
    u.view_proj.m[i] = static_cast<float>(vp.m[static_cast<std::size_t>(i)]);
  u.camera_pos_m = {0.0f, 0.0f, 0.0f};
  for (int row = 0; row < 3; ++row)
    u.sphere.local_from_planet[row] = {static_cast<float>(axes.rows[row].x),
                                       static_cast<float>(axes.rows[row].y),
                                       static_cast<float>(axes.rows[row].z), 0.0f};
  u.sphere.radius_m = static_cast<float>(r);
  u.sphere.enabled = 1.0f;
  const lod::Vec3 centre = axes.apply({-eye.x, -eye.y, -eye.z});  // R.8c
  u.sphere.local_from_planet[0].w = static_cast<float>(centre.x);
  u.sphere.local_from_planet[1].w = static_cast<float>(centre.y);
  u.sphere.local_from_planet[2].w = static_cast<float>(centre.z);
  u.sphere.sun_top = static_cast<float>(view.shading.sun_irradiance);
  u.sphere.camera_altitude_m =
      static_cast<float>(std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z) - r);
  // The camera's position over L_c, wrapped to one period in double (R.38).
  const double e[3] = {eye.x, eye.y, eye.z};
  for (int c = 0; c < kMaxCascades; ++c) {
    const double size = st.patch_size_m[static_cast<std::size_t>(c)];
    float f[3] = {0.0f, 0.0f, 0.0f};
    if (c < st.cascades && size > 0.0)
      for (int k = 0; k < 3; ++k) f[k] = static_cast<float>(e[k] / size - std::floor(e[k] / size));
    u.cascade_origin[c] = {f[0], f[1], f[2], 0.0f};
  }
  return {};
}

void SpherePass::record(Renderer::State& st, VkCommandBuffer cmd, const FrameContext& frame) {
  RenderStats& stats = frame.stats;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
  const VkDeviceSize zero = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &st.patch_vertices.buffer, &zero);
  vkCmdBindVertexBuffers(cmd, 1, 1, &instances.buffer, &zero);
  vkCmdBindIndexBuffer(cmd, st.indices.buffer, 0, VK_INDEX_TYPE_UINT16);
  for (const lod::Batch& b : selection.batches) {
    vkCmdDrawIndexed(cmd, st.index_count[b.config], b.count, st.index_first[b.config], 0, b.first);
    ++stats.draw_calls;
    stats.patches += b.count;
    stats.triangles += static_cast<std::uint64_t>(st.index_count[b.config] / 3) * b.count;
  }
  for (const sphere::SpherePatch& p : selection.patches)
    if (p.level <= lod::kMaxLevels) ++stats.patches_per_level[p.level];
}

}  // namespace ocean::render
