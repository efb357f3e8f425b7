// Height queries on the published frame: bilinear displacement sampling with wrap (as a GPU
// samples the maps), each cascade weighed by the damping's band weight, and the inverse of the
// horizontal displacement for buoyancy. Equations: docs/math.md (M.7.6), (M.7.7); docs/waves.md
// (W.13).
#include <cmath>
#include <limits>

#include "local_surface.hpp"
#include "ocean/sim.hpp"
#include "ocean/waves.hpp"

namespace ocean {

namespace {

// Adds weight × the float3 array `field` of cascade c (displacement or velocity) at (x, z).
void add_bilinear(const CascadeFrame& c, const LargeVector<float>& field, double x, double z,
                  double weight, std::array<double, 3>& sum) {
  const int n = c.resolution;
  const double scale = n / c.patch_size_m;  // texels per metre
  const double u = x * scale;
  const double v = z * scale;
  const double u0 = std::floor(u), v0 = std::floor(v);
  const double fu = u - u0, fv = v - v0;
  const auto wrap = [n](double t) {
    const long long i = static_cast<long long>(t) % n;
    return static_cast<std::size_t>(i < 0 ? i + n : i);
  };
  const std::size_t c0 = wrap(u0), c1 = wrap(u0 + 1.0);
  const std::size_t r0 = wrap(v0), r1 = wrap(v0 + 1.0);
  const auto texel = [&](std::size_t col, std::size_t row, int comp) {
    return static_cast<double>(
        field[3 * (row * static_cast<std::size_t>(n) + col) + static_cast<std::size_t>(comp)]);
  };
  for (int comp = 0; comp < 3; ++comp) {
    const double top = texel(c0, r0, comp) * (1.0 - fu) + texel(c1, r0, comp) * fu;
    const double bottom = texel(c0, r1, comp) * (1.0 - fu) + texel(c1, r1, comp) * fu;
    sum[static_cast<std::size_t>(comp)] += weight * (top * (1.0 - fv) + bottom * fv);  // (M.7.6)
  }
}

// Solves p + D_xz(p) = t for every query (M.7.7): Newton on the bilinear field, with a
// fixed-point step p ← t − D_xz(p) wherever the map is near a fold (det ≤ 0.1).
template <typename Displacement>
void invert(const Displacement& displacement_at, std::span<const std::array<double, 2>> xz,
            std::span<HeightSample> out) {
  constexpr int kMaxIterations = 40;
  constexpr double kTolerance_m = 1e-6;
  const std::size_t count = std::min(xz.size(), out.size());
  for (std::size_t q = 0; q < count; ++q) {
    const double tx = xz[q][0], tz = xz[q][1];
    double px = tx, pz = tz;
    std::array<double, 3> d = displacement_at(px, pz);
    int iteration = 0;
    for (; iteration < kMaxIterations; ++iteration) {
      const double rx = px + d[0] - tx, rz = pz + d[2] - tz;
      if (std::abs(rx) < kTolerance_m && std::abs(rz) < kTolerance_m) break;
      constexpr double h = 1e-4;  // m; exact for the piecewise-bilinear field inside a cell
      const auto dxp = displacement_at(px + h, pz), dxm = displacement_at(px - h, pz);
      const auto dzp = displacement_at(px, pz + h), dzm = displacement_at(px, pz - h);
      const double a = 1.0 + (dxp[0] - dxm[0]) / (2 * h), b = (dzp[0] - dzm[0]) / (2 * h);
      const double c = (dxp[2] - dxm[2]) / (2 * h), e = 1.0 + (dzp[2] - dzm[2]) / (2 * h);
      const double det = a * e - b * c;
      if (det > 0.1) {
        px -= (e * rx - b * rz) / det;
        pz -= (a * rz - c * rx) / det;
      } else {
        px = tx - d[0];
        pz = tz - d[2];
      }
      d = displacement_at(px, pz);
    }
    out[q] = {.height_m = d[1], .displacement = d, .source_xz = {px, pz}, .iterations = iteration};
  }
}

// The half-width of the time difference of a local layer's velocity, s: its displacement is
// smooth in time, so the central difference errs by (δt²/6)·|∂³D/∂t³| ≈ 1.7e-7·ω²·|V|, far below
// the float precision of the cascades' velocity for every wave period above 0.1 s.
constexpr double kLayerVelocityStep_s = 1e-3;

}  // namespace

namespace detail {

std::array<double, 3> surface_velocity(const Frame& frame, const waves::Damping* damping,
                                       const waves::LocalLayer* layer, double x, double z) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::array<double, 3> sum{0.0, 0.0, 0.0};
  std::array<double, waves::kMaxBands> weight;
  weight.fill(1.0);
  if (damping != nullptr) damping->band_weights(x, z, weight);  // (W.13)
  for (std::size_t c = 0; c < frame.cascades.size(); ++c) {
    if (frame.cascades[c].velocity.empty()) return {kNaN, kNaN, kNaN};
    add_bilinear(frame.cascades[c], frame.cascades[c].velocity, x, z,
                 c < weight.size() ? weight[c] : 1.0, sum);
  }
  if (layer != nullptr) {
    const double dt = kLayerVelocityStep_s;
    const std::array<double, 3> later = layer->displacement_at(x, z, frame.time_s + dt);
    const std::array<double, 3> earlier = layer->displacement_at(x, z, frame.time_s - dt);
    for (std::size_t k = 0; k < 3; ++k) sum[k] += (later[k] - earlier[k]) / (2.0 * dt);
  }
  return sum;
}

std::array<double, 3> surface_displacement(const Frame& frame, const waves::Damping* damping,
                                           const waves::LocalLayer* layer, double x, double z) {
  std::array<double, 3> sum{0.0, 0.0, 0.0};
  std::array<double, waves::kMaxBands> weight;
  weight.fill(1.0);
  if (damping != nullptr) damping->band_weights(x, z, weight);  // (W.13)
  for (std::size_t c = 0; c < frame.cascades.size(); ++c)
    add_bilinear(frame.cascades[c], frame.cascades[c].displacement, x, z,
                 c < weight.size() ? weight[c] : 1.0, sum);
  if (layer != nullptr) {
    const std::array<double, 3> local = layer->displacement_at(x, z, frame.time_s);
    for (std::size_t k = 0; k < 3; ++k) sum[k] += local[k];
  }
  return sum;
}

}  // namespace detail

void Simulator::set_damping(std::shared_ptr<const waves::Damping> damping) {
  damping_ = std::move(damping);
}

std::array<double, 3> Simulator::displacement_at(double x, double z) const {
  return detail::surface_displacement(frame(), damping_.get(), local_layer_.get(), x, z);
}

void Simulator::heights_at(std::span<const std::array<double, 2>> xz,
                           std::span<HeightSample> out) const {
  invert([this](double x, double z) { return displacement_at(x, z); }, xz, out);
}

void Simulator::surface_at(std::span<const std::array<double, 2>> xz,
                           std::span<SurfaceSample> out) const {
  const auto displacement = [this](double x, double z) { return displacement_at(x, z); };
  const std::size_t count = std::min(xz.size(), out.size());
  for (std::size_t q = 0; q < count; ++q) {
    HeightSample h;
    invert(displacement, xz.subspan(q, 1), std::span(&h, 1));  // heights_at's inverse, exactly
    const double px = h.source_xz[0], pz = h.source_xz[1];
    // The tangents of the displaced surface p ↦ p + D(p) along px and pz (central differences,
    // exact for the piecewise-bilinear field inside a cell, as the inverse's Newton step); their
    // cross product T_z × T_x is (−∂η/∂x, 1, −∂η/∂z)·det of the horizontal map (M.7.11).
    constexpr double step = 1e-4;  // m
    const auto dxp = displacement(px + step, pz), dxm = displacement(px - step, pz);
    const auto dzp = displacement(px, pz + step), dzm = displacement(px, pz - step);
    std::array<double, 3> tx, tz;
    for (std::size_t k = 0; k < 3; ++k) {
      tx[k] = (dxp[k] - dxm[k]) / (2 * step);
      tz[k] = (dzp[k] - dzm[k]) / (2 * step);
    }
    tx[0] += 1.0;
    tz[2] += 1.0;
    const std::array<double, 3> n{tz[1] * tx[2] - tz[2] * tx[1], tz[2] * tx[0] - tz[0] * tx[2],
                                  tz[0] * tx[1] - tz[1] * tx[0]};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    out[q].height_m = h.height_m;
    out[q].normal = length > 0.0
                        ? std::array<double, 3>{n[0] / length, n[1] / length, n[2] / length}
                        : std::array<double, 3>{0.0, 1.0, 0.0};
    out[q].velocity = detail::surface_velocity(frame(), damping_.get(), local_layer_.get(), px, pz);
  }
}

bool Simulator::has_velocity() const {
  const Frame& f = frame();
  return !f.cascades.empty() && !f.cascades.front().velocity.empty();
}

void heights_at(const waves::LocalLayer& layer, double time_s,
                std::span<const std::array<double, 2>> xz, std::span<HeightSample> out) {
  invert([&](double x, double z) { return layer.displacement_at(x, z, time_s); }, xz, out);
}

}  // namespace ocean
