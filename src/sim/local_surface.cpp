// The local surface (docs/math.md M.7.9): the sea's cascades sampled on the local layer's grid
// and added to the layer before the normal, Jacobian and foam are computed, so a wake folds and
// foams where it meets the sea's crests as the sea itself does (Mitchell 2005, §3.4: composited
// waveforms go through the same normal and foam pass as the synthesised sea).
//
// The cascades are periodic and the layer is not, so the sum lives on the layer's world grid and
// is computed here, from the published frame's arrays, rather than in each backend: every
// backend (CPU, Vulkan, CUDA) then gets the same local surface from its frame, and the local
// surface conforms as its cascades do (docs/vulkan.md, "Conformance bounds").
#include "local_surface.hpp"

#include <algorithm>
#include <cmath>

#include "packing.hpp"

namespace ocean {

namespace detail {

void allocate_local_surface(const waves::LocalArea& area, LocalSurfaceFrame& local) {
  const auto cells =
      static_cast<std::size_t>(area.resolution) * static_cast<std::size_t>(area.resolution);
  local.origin_m = area.origin_m;
  local.size_m = area.size_m;
  local.resolution = area.resolution;
  local.displacement.assign(3 * cells, 0.0f);
  local.normal.assign(3 * cells, 0.0f);
  local.jacobian.assign(cells, 1.0f);
  local.foam.assign(cells, 0.0f);
  local.layer_displacement.assign(3 * cells, 0.0f);
  local.sea_normal.assign(3 * cells, 0.0f);
  local.sea_foam.assign(cells, 0.0f);
}

namespace {

// ∂/∂x and ∂/∂z of (Dx, h, Dz) at cell (col, row): central differences inside, one-sided at the
// edges of the non-periodic grid.
packing::Gradients cell_gradients(const std::vector<float>& d, int n, int col, int row,
                                  double spacing_m) {
  const auto at = [&](int c, int r, int comp) {
    return d[3 * (static_cast<std::size_t>(r) * static_cast<std::size_t>(n) +
                  static_cast<std::size_t>(c)) +
             static_cast<std::size_t>(comp)];
  };
  const int c0 = std::max(col - 1, 0), c1 = std::min(col + 1, n - 1);
  const int r0 = std::max(row - 1, 0), r1 = std::min(row + 1, n - 1);
  const auto inv_x = static_cast<float>(1.0 / ((c1 - c0) * spacing_m));
  const auto inv_z = static_cast<float>(1.0 / ((r1 - r0) * spacing_m));
  float gx[3], gz[3];
  for (int comp = 0; comp < 3; ++comp) {
    gx[comp] = (at(c1, row, comp) - at(c0, row, comp)) * inv_x;
    gz[comp] = (at(col, r1, comp) - at(col, r0, comp)) * inv_z;
  }
  return {gx[0], gx[1], gx[2], gz[0], gz[1], gz[2]};
}

}  // namespace

void composite_local_surface(const SimulationPlan& plan, const waves::Damping* damping,
                             const waves::LocalLayer& layer, const LocalSurfaceFrame& previous,
                             double dt_s, bool reset_foam, Frame& frame, TaskRunner& runner) {
  LocalSurfaceFrame& local = frame.local;
  const int n = local.resolution;
  if (n <= 0) return;
  const waves::LocalArea& area = layer.params().area;
  const auto rows = static_cast<std::size_t>(n);
  runner.parallel_for(rows, 4, [&](std::size_t row_begin, std::size_t row_end) {
    for (auto row = static_cast<int>(row_begin); row < static_cast<int>(row_end); ++row) {
      for (int col = 0; col < n; ++col) {
        const std::array<double, 2> p = waves::cell_centre(area, col, row);
        const std::array<double, 3> sea = surface_displacement(frame, damping, nullptr, p[0], p[1]);
        const std::array<double, 3> own = layer.displacement_at(p[0], p[1], frame.time_s);
        const std::size_t i = static_cast<std::size_t>(row) * rows + static_cast<std::size_t>(col);
        for (std::size_t k = 0; k < 3; ++k) {
          local.displacement[3 * i + k] = static_cast<float>(sea[k] + own[k]);
          local.layer_displacement[3 * i + k] = static_cast<float>(own[k]);
        }
      }
    }
  });
  const double spacing_m = area.size_m / n;
  const SimulationConfig& config = plan.config();
  const packing::FoamTerms source = packing::foam_terms(config.foam, plan.foam().local);
  const auto decay = static_cast<float>(config.foam.decay_per_s * dt_s);
  const bool reset = reset_foam || previous.foam.size() != local.foam.size() ||
                     previous.sea_foam.size() != local.sea_foam.size();
  runner.parallel_for(rows, 8, [&](std::size_t row_begin, std::size_t row_end) {
    for (auto row = static_cast<int>(row_begin); row < static_cast<int>(row_end); ++row) {
      for (int col = 0; col < n; ++col) {
        const std::size_t i = static_cast<std::size_t>(row) * rows + static_cast<std::size_t>(col);
        const packing::Gradients sum = cell_gradients(local.displacement, n, col, row, spacing_m);
        const packing::SurfacePoint s = packing::surface_point(sum);
        local.jacobian[i] = s.jacobian;
        for (std::size_t k = 0; k < 3; ++k) local.normal[3 * i + k] = s.normal[k];
        // The hulls' waterline and trail foam (W.20–W.21) join this frame's source, so the
        // foam they leave ages with the sea's own decay once they have moved on.
        const std::array<double, 2> p = waves::cell_centre(area, col, row);
        const float now = std::max(packing::foam_source(s.jacobian, source),
                                   static_cast<float>(layer.foam_at(p[0], p[1], frame.time_s)));
        local.foam[i] =
            packing::accumulate_foam(now, reset ? 0.0f : previous.foam[i], reset, decay);
        // The sea alone (M.7.10): the sum's gradients less the layer's, exactly the sum's where
        // the layer's differences are 0.
        const packing::Gradients own =
            cell_gradients(local.layer_displacement, n, col, row, spacing_m);
        const packing::SurfacePoint sea = packing::surface_point(
            {sum.dx_dx - own.dx_dx, sum.h_dx - own.h_dx, sum.dz_dx - own.dz_dx,
             sum.dx_dz - own.dx_dz, sum.h_dz - own.h_dz, sum.dz_dz - own.dz_dz});
        for (std::size_t k = 0; k < 3; ++k) local.sea_normal[3 * i + k] = sea.normal[k];
        local.sea_foam[i] =
            packing::accumulate_foam(packing::foam_source(sea.jacobian, source),
                                     reset ? 0.0f : previous.sea_foam[i], reset, decay);
      }
    }
  });
}

}  // namespace detail

void Simulator::set_local_layer(std::shared_ptr<const waves::LocalLayer> layer) {
  wait();
  // A layer on the same grid as the one it replaces (a driven wake remade at a waypoint) keeps the
  // composited surface: its foam carries on accumulating instead of starting afresh.
  const bool same_grid = local_layer_ != nullptr && layer != nullptr &&
                         local_layer_->params().area.origin_m == layer->params().area.origin_m &&
                         local_layer_->params().area.size_m == layer->params().area.size_m &&
                         local_layer_->params().area.resolution == layer->params().area.resolution;
  local_layer_ = std::move(layer);
  if (same_grid) return;
  local_foam_reset_ = true;
  for (Frame& f : frames_) {
    if (local_layer_ != nullptr)
      detail::allocate_local_surface(local_layer_->params().area, f.local);
    else
      f.local = LocalSurfaceFrame{};
  }
}

void Simulator::compute_local_surface(Frame& back) {
  if (local_layer_ == nullptr) return;
  const Frame& front = frames_[front_];
  const bool reset = local_foam_reset_ || !(back.time_s > front.time_s);
  detail::composite_local_surface(*plan_, damping_.get(), *local_layer_, front.local,
                                  back.time_s - front.time_s, reset, back, *runner_);
  local_foam_reset_ = false;
}

}  // namespace ocean
