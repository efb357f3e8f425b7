// The local layer's pass (local_layer.hpp, docs/rendering.md R.19): its image filled through a
// staging buffer from the composited local surface (set_local_surface, M.7.9–M.7.10) or from the
// layer alone (set_local_layer). Until the first call it is 1×1 of zeros and the uniforms say "no
// layer", so the descriptor is always valid.
#include "local_layer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "ocean/half.hpp"
#include "state.hpp"
#include "world_grid.hpp"

namespace ocean::render {

namespace {

constexpr std::uint32_t kLayers = 2;

// The image and its staging buffer for a side × side layer; the old ones are destroyed first.
Status allocate_local(Renderer::State& st, std::uint32_t side) {
  LocalSurfacePass& local = pass<LocalSurfacePass>(st);
  vkDeviceWaitIdle(st.ctx->device);
  vk::destroy_image(*st.ctx, local.image);
  vk::destroy_buffer(*st.ctx, local.staging);
  local.side = 0;
  Result<vk::Image> image =
      vk::create_image_array(*st.ctx, VK_FORMAT_R16G16B16A16_SFLOAT, side, kLayers, 1,
                             VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  if (!image.ok()) return image.status();
  local.image = image.value();
  const std::size_t bytes = static_cast<std::size_t>(side) * side * 8 * kLayers;
  Result<vk::Buffer> staging =
      vk::create_buffer(*st.ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryUse::upload);
  if (!staging.ok()) return staging.status();
  local.staging = staging.value();
  std::memset(local.staging.mapped, 0, bytes);
  local.side = side;
  local.pending = true;
  return {};
}

// Checks the grid and sizes the image for it; on failure the layer is switched off.
Status prepare_grid(Renderer::State& st, const std::array<double, 2>& origin_m, double size_m,
                    int resolution, std::size_t values, std::size_t per_cell) {
  if (Status s = check_world_grid("local layer", origin_m, size_m, resolution); !s.ok()) return s;
  const auto side = static_cast<std::uint32_t>(resolution);
  const std::size_t cells = static_cast<std::size_t>(side) * side;
  if (values != per_cell * cells)
    return invalid_argument("local layer: " + std::to_string(values) + " values for " +
                            std::to_string(side) + "² cells (" + std::to_string(per_cell) +
                            " each expected)");
  if (side != pass<LocalSurfacePass>(st).side) {
    if (Status s = allocate_local(st, side); !s.ok()) {
      pass<LocalSurfacePass>(st).uniforms.resolution = 0.0f;
      (void)allocate_local(st, 1);  // keep a valid, empty image behind the descriptor
      write_scene_images(st);
      return s;
    }
    write_scene_images(st);
  }
  return {};
}

void finish(Renderer::State& st, const std::array<double, 2>& origin_m, double size_m,
            int resolution) {
  LocalSurfacePass& local = pass<LocalSurfacePass>(st);
  local.origin_m = origin_m;
  local.uniforms.size_m = static_cast<float>(size_m);
  local.uniforms.resolution = static_cast<float>(resolution);
  local.pending = true;
}

// The surface gradient as the water shader sums it, (n_x/n_y, n_z/n_y), from a unit normal whose
// n_y is taken back from its x and z as the packed cascade maps give it (ocean.frag's shade_of:
// n_y = √max(1 − n_x² − n_z², 0.05)), so a fold's slope stays bounded as the cascades' does.
std::array<float, 2> slope_of(const float* n) {
  const float ny = std::sqrt(std::max(1.0f - n[0] * n[0] - n[2] * n[2], 0.05f));
  return {n[0] / ny, n[2] / ny};
}

// Writes cell i of layer 1: (Δs_x, Δs_z, Δf, 0).
void write_shade(std::uint16_t* out, std::size_t cells, std::size_t i, std::array<float, 2> ds,
                 float df) {
  std::uint16_t* t = out + 4 * (cells + i);
  t[0] = float_to_half(ds[0]);
  t[1] = float_to_half(ds[1]);
  t[2] = float_to_half(std::clamp(df, 0.0f, 1.0f));
  t[3] = 0;
}

void write_displacement(std::uint16_t* out, std::size_t i, const float* d) {
  for (std::size_t c = 0; c < 3; ++c) out[4 * i + c] = float_to_half(d[c]);
  out[4 * i + 3] = 0;
}

}  // namespace

Status LocalSurfacePass::create(Renderer::State& st) {
  Result<VkSampler> linear = make_sampler(*st.ctx, true, false, false, 1.0f);
  if (!linear.ok()) return linear.status();
  sampler = linear.value();
  uniforms = {};
  return allocate_local(st, 1);
}

void LocalSurfacePass::destroy(Renderer::State& st) {
  vk::destroy_image(*st.ctx, image);
  vk::destroy_buffer(*st.ctx, staging);
  if (sampler != VK_NULL_HANDLE) vkDestroySampler(st.ctx->device, sampler, nullptr);
}

void LocalSurfacePass::scene_images(const Renderer::State&, SceneImages& images) const {
  images.add(OCEAN_RENDER_BINDING_LOCAL, images.surface_stages,
             {sampler, image.view, VK_IMAGE_LAYOUT_GENERAL});
}

void LocalSurfacePass::fill_uniforms(const Renderer::State& st, const View&,
                                     shader::FrameUniforms& u) const {
  // Its origin relative to the frame's origin O, as every position (R.16).
  const lod::LodSelection& sel = st.selection;
  u.local = uniforms;
  u.local.origin_m = {static_cast<float>(origin_m[0] - sel.grid_centre_x_m),
                      static_cast<float>(origin_m[1] - sel.grid_centre_z_m)};
}

void LocalSurfacePass::upload(Renderer::State&, VkCommandBuffer cmd) {
  if (!pending) return;
  record_world_grid_upload(cmd, staging.buffer, image.image, side, kLayers);
  pending = false;
}

void Renderer::set_calm(bool calm) {
  pass<LocalSurfacePass>(*state_).uniforms.calm = calm ? 1.0f : 0.0f;
}

Status Renderer::set_local_layer(const LocalLayerGrid& grid) {
  State& st = *state_;
  if (grid.displacement.empty()) {  // no layer: the uniforms switch it off; the image may stay
    pass<LocalSurfacePass>(st).uniforms.resolution = 0.0f;
    return {};
  }
  if (Status s = prepare_grid(st, grid.origin_m, grid.size_m, grid.resolution,
                              grid.displacement.size(), 3);
      !s.ok())
    return s;
  const int n = grid.resolution;
  const auto cells = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  const double cell_m = grid.size_m / n;
  const auto j_start = static_cast<float>(st.foam_ramp[0]);
  const auto j_range = static_cast<float>(st.foam_ramp[0] - st.foam_ramp[1]);
  auto* out = static_cast<std::uint16_t*>(pass<LocalSurfacePass>(st).staging.mapped);
  const auto at = [&](int col, int row) {
    return grid.displacement.data() +
           3 * (static_cast<std::size_t>(row) * static_cast<std::size_t>(n) +
                static_cast<std::size_t>(col));
  };
  for (int row = 0; row < n; ++row) {
    for (int col = 0; col < n; ++col) {
      const std::size_t i = static_cast<std::size_t>(row) * static_cast<std::size_t>(n) +
                            static_cast<std::size_t>(col);
      write_displacement(out, i, at(col, row));
      // The layer's own gradients by central differences (one-sided at the grid's edges), its
      // normal and Jacobian as the simulator's (M.7.5, eq. 48; packing::surface_point), and
      // the instantaneous foam ramp on that J (M.7.4).
      const int c0 = std::max(col - 1, 0), c1 = std::min(col + 1, n - 1);
      const int r0 = std::max(row - 1, 0), r1 = std::min(row + 1, n - 1);
      const auto inv_x = c1 > c0 ? static_cast<float>(1.0 / ((c1 - c0) * cell_m)) : 0.0f;
      const auto inv_z = r1 > r0 ? static_cast<float>(1.0 / ((r1 - r0) * cell_m)) : 0.0f;
      float gx[3], gz[3];
      for (int k = 0; k < 3; ++k) {
        gx[k] = (at(c1, row)[k] - at(c0, row)[k]) * inv_x;
        gz[k] = (at(col, r1)[k] - at(col, r0)[k]) * inv_z;
      }
      const float jxx = 1.0f + gx[0], jzz = 1.0f + gz[2];
      const float jacobian = jxx * jzz - gz[0] * gx[2];
      float normal[3] = {gz[1] * gx[2] - jzz * gx[1], jacobian, gz[0] * gx[1] - gz[1] * jxx};
      const float length =
          std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
      for (float& v : normal) v = length > 0.0f ? v / length : 0.0f;
      if (!(length > 0.0f)) normal[1] = 1.0f;
      write_shade(out, cells, i, slope_of(normal),
                  std::clamp((j_start - jacobian) / j_range, 0.0f, 1.0f));
    }
  }
  finish(st, grid.origin_m, grid.size_m, grid.resolution);
  return {};
}

Status Renderer::set_local_surface(const LocalSurfaceFrame& local) {
  State& st = *state_;
  if (local.resolution == 0) {
    pass<LocalSurfacePass>(st).uniforms.resolution = 0.0f;
    return {};
  }
  const auto n = static_cast<std::size_t>(std::max(local.resolution, 0));
  const std::size_t cells = n * n;
  if (local.normal.size() != 3 * cells || local.sea_normal.size() != 3 * cells ||
      local.foam.size() != cells || local.sea_foam.size() != cells)
    return invalid_argument("local surface: its normal and foam arrays are not sized for " +
                            std::to_string(local.resolution) + "² cells");
  if (Status s = prepare_grid(st, local.origin_m, local.size_m, local.resolution,
                              local.layer_displacement.size(), 3);
      !s.ok())
    return s;
  auto* out = static_cast<std::uint16_t*>(pass<LocalSurfacePass>(st).staging.mapped);
  for (std::size_t i = 0; i < cells; ++i) {
    write_displacement(out, i, local.layer_displacement.data() + 3 * i);
    // What the layer changes (R.19): the composited surface's slope less the sea's on the same
    // grid, and the foam it adds to the sea's (never removes: the cascades' own foam is per band,
    // not the summed sea's of M.7.10, so it is not the sea_foam that could be taken away).
    const std::array<float, 2> sum = slope_of(local.normal.data() + 3 * i);
    const std::array<float, 2> sea = slope_of(local.sea_normal.data() + 3 * i);
    write_shade(out, cells, i, {sum[0] - sea[0], sum[1] - sea[1]},
                local.foam[i] - local.sea_foam[i]);
  }
  finish(st, local.origin_m, local.size_m, local.resolution);
  return {};
}

}  // namespace ocean::render
