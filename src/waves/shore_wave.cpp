// src/waves/shore_wave.cpp — one wave train refracted and shoaled over a bathymetry (W.32–W.37):
// its local wavenumber from the linear dispersion relation, its phase from the eikonal equation
// solved by fast sweeping from the map's offshore edge, and its height from the balance of the
// energy flux between neighbouring rays, capped by the breaking index.
//
// This work is based on:
// - Dean & Dalrymple (1991), "Water Wave Mechanics for Engineers and Scientists", chs. 3–4: the
//   dispersion relation ω² = g·k·tanh(k·d), the group velocity c_g = n·c with
//   n = ½(1 + 2kd/sinh 2kd), the shoaling coefficient K_s = √(c_g0/c_g) and the refraction
//   coefficient K_r = √(b0/b) from the conservation of E·c_g·b between rays, Snell's law
//   sin θ/c = sin θ0/c0 over straight parallel contours.
// - Mei, Stiassnie & Yue (2005), "Theory and Applications of Ocean Surface Waves", ch. 3
//   (refraction by slowly varying depth): the geometrical-optics (WKB) equations |∇S| = k(x) and
//   ∇·(A²·c_g·∇S/k) = 0.
// - Zhao (2005), "A fast sweeping method for eikonal equations", Math. Comp. 74: the Godunov
//   upwind update and the four alternating sweep orders; first-order accurate, exact for a
//   plane wave over uniform k.
// - LeVeque (2002), "Finite Volume Methods for Hyperbolic Problems", §20.1: the donor-cell
//   (upwind) flux of a steady conservation law, which keeps Σ fluxes exactly.
#include "ocean/shore_wave.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace ocean::waves {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Sweeps until no cell changes, at most this many rounds of four: each round carries the
// solution round one more turn of the rays against all four sweep orders.
constexpr int kMaxSweepRounds = 64;

}  // namespace

double shore_wavenumber(double omega, double depth_m, double g) {
  const double k_deep = omega * omega / g;
  if (!(depth_m > 0.0)) return kInf;
  if (std::isinf(depth_m)) return k_deep;
  // (W.32) x = k·d solves x·tanh x = y, y = ω²d/g. Newton on f(x) = x·tanh x − y, which is
  // increasing and convex for x > 0: from x0 = max(y, √y) ≥ the root the steps fall monotonically
  // onto it (x·tanh x ≤ min(x, x²)).
  const double y = k_deep * depth_m;
  if (y > 40.0) return k_deep;  // tanh(y) = 1 to 1e-34
  double x = std::max(y, std::sqrt(y));
  for (int i = 0; i < 100; ++i) {
    const double t = std::tanh(x);
    const double f = x * t - y;
    const double df = t + x * (1.0 - t * t);
    const double step = f / df;
    x -= step;
    if (std::abs(step) <= 1e-15 * x) break;
  }
  return x / depth_m;
}

double shore_group_velocity(double omega, double depth_m, double g) {
  if (!(depth_m > 0.0)) return 0.0;
  const double k = shore_wavenumber(omega, depth_m, g);
  const double kd2 = 2.0 * k * depth_m;
  const double n = kd2 > 700.0 ? 0.5 : 0.5 * (1.0 + kd2 / std::sinh(kd2));  // (W.33)
  return n * omega / k;
}

Status validate(const ShoreWaveParams& p) {
  // The bathymetry's placement and values as the damping takes them (W.28).
  if (Status s = validate(DampingParams{.bathymetry = p.bathymetry,
                                        .band_wavenumbers_radpm = {1.0},
                                        .gravity_mps2 = p.gravity_mps2});
      !s.ok())
    return s;
  if (Status s = require_in_range("period_s", p.period_s, 0.5, 60.0); !s.ok()) return s;
  if (Status s = require_in_range("deep_height_m", p.deep_height_m, 0.0, 100.0); !s.ok()) return s;
  if (Status s = require_finite("direction_deg", p.direction_deg); !s.ok()) return s;
  return require_in_range("breaking_index", p.breaking_index, 0.3, 1.5);
}

Result<ShoreWave> ShoreWave::make(ShoreWaveParams params) {
  if (Status s = validate(params); !s.ok()) return s;
  ShoreWave w;
  w.params_ = std::move(params);
  const ShoreWaveParams& p = w.params_;
  const double g = p.gravity_mps2;
  w.omega_ = 2.0 * std::numbers::pi / p.period_s;
  w.deep_wavenumber_ = w.omega_ * w.omega_ / g;
  const double k0 = w.deep_wavenumber_;
  const double a = p.direction_deg * std::numbers::pi / 180.0;
  const double ux = std::cos(a), uz = std::sin(a);  // d̂, the deep-water direction

  const HeightMap& m = *p.bathymetry.map;
  const int rows = m.rows, cols = m.cols;
  const double h = p.bathymetry.size_m / cols;
  const double x0 = p.bathymetry.origin_m[0], z0 = p.bathymetry.origin_m[1];
  const auto n = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
  const auto at = [cols](int r, int c) {
    return static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) +
           static_cast<std::size_t>(c);
  };
  std::vector<double> k(n);
  for (std::size_t i = 0; i < n; ++i) k[i] = shore_wavenumber(w.omega_, m.values[i], g);
  const auto water = [&](int r, int c) {
    return r >= 0 && r < rows && c >= 0 && c < cols && std::isfinite(k[at(r, c)]);
  };

  // (W.34) The offshore edge: the one whose outward normal n̂ points most against d̂. Its cells
  // hold the deep wave's phase S = k0·d̂·x, whose derivative along the edge, k0·(d̂·t̂), is what
  // Snell's law keeps; the eikonal gives the rest.
  const double against[4] = {ux, -ux, uz, -uz};  // −d̂·n̂ of the edges x−, x+, z−, z+
  const int edge = static_cast<int>(std::max_element(against, against + 4) - against);
  const double cos0 = against[edge];  // cos θ0, θ0 the incidence on the edge
  const bool along_x = edge >= 2;     // the edge runs along x (a row)
  std::vector<char> source(n, 0);
  std::vector<double>& S = w.phase_;
  S.assign(n, kInf);
  w.dir_x_.assign(n, 0.0);
  w.dir_z_.assign(n, 0.0);
  w.ray_density_.assign(n, 0.0);
  const int count = along_x ? cols : rows;
  for (int j = 0; j < count; ++j) {
    const int r = along_x ? (edge == 2 ? 0 : rows - 1) : j;
    const int c = along_x ? j : (edge == 0 ? 0 : cols - 1);
    if (!water(r, c)) continue;
    const std::size_t i = at(r, c);
    const double x = x0 + (c + 0.5) * h, z = z0 + (r + 0.5) * h;
    S[i] = k0 * (ux * x + uz * z);
    source[i] = 1;
    // Snell at the edge: the tangential wavenumber k0·(d̂·t̂) kept, the normal one inwards.
    const double sin_e = (along_x ? ux : uz) * k0 / k[i];
    const double cos_e = std::sqrt(std::max(0.0, 1.0 - sin_e * sin_e));
    const double inward = (edge == 0 || edge == 2) ? 1.0 : -1.0;
    w.dir_x_[i] = along_x ? sin_e : inward * cos_e;
    w.dir_z_[i] = along_x ? inward * cos_e : sin_e;
    // (W.35) The flux of a unit ray density through the edge: R·cos θ_e = cos θ0.
    w.ray_density_[i] = cos_e > 0.0 ? cos0 / cos_e : 0.0;
  }

  // The other edges through which the wave enters (d̂ pointing into the map) see no wave of
  // their own beyond them: their ghost neighbour continues the map's contours straight across
  // the edge, so that along it S keeps the deep wave's gradient k0·d̂ (Snell's invariant for
  // contours normal to the edge) and the ray density its own value.
  // ghost(r, c, true): the cell lies on a side edge at x = const (across the x axis).
  const auto ghost = [&](int r, int c, bool x_axis) {
    if (x_axis) return along_x && ((c == 0 && ux > 0.0) || (c == cols - 1 && ux < 0.0));
    return !along_x && ((r == 0 && uz > 0.0) || (r == rows - 1 && uz < 0.0));
  };
  const double gx_ghost = k0 * std::abs(ux), gz_ghost = k0 * std::abs(uz);

  // (W.34) |∇S| = k by fast sweeping (Zhao 2005): the Godunov upwind update from the smaller
  // neighbour along each axis, over the four diagonal orders until nothing changes.
  const auto update = [&](int r, int c) {
    const std::size_t i = at(r, c);
    if (source[i] || !std::isfinite(k[i])) return false;
    const double sx = std::min(water(r, c - 1) ? S[at(r, c - 1)] : kInf,
                               water(r, c + 1) ? S[at(r, c + 1)] : kInf);
    const double sz = std::min(water(r - 1, c) ? S[at(r - 1, c)] : kInf,
                               water(r + 1, c) ? S[at(r + 1, c)] : kInf);
    const double lo = std::min(sx, sz);
    if (!std::isfinite(lo)) return false;
    const double f = k[i] * h;
    double s = lo + f;
    if (std::isfinite(sx) && std::isfinite(sz) && std::abs(sx - sz) < f)
      s = 0.5 * (sx + sz + std::sqrt(2.0 * f * f - (sx - sz) * (sx - sz)));
    // On a side edge the ghost fixes ∂S across the edge to k0·|d̂'s component|; the other
    // component follows from |∇S| = k.
    if (ghost(r, c, true) && std::isfinite(sz))
      s = std::min(s, sz + h * std::sqrt(std::max(0.0, k[i] * k[i] - gx_ghost * gx_ghost)));
    if (ghost(r, c, false) && std::isfinite(sx))
      s = std::min(s, sx + h * std::sqrt(std::max(0.0, k[i] * k[i] - gz_ghost * gz_ghost)));
    if (s < S[i]) {
      S[i] = s;
      return true;
    }
    return false;
  };
  for (int round = 0; round < kMaxSweepRounds; ++round) {
    bool changed = false;
    for (int order = 0; order < 4; ++order) {
      const bool down = order & 1, right = order & 2;
      for (int rr = 0; rr < rows; ++rr) {
        const int r = down ? rr : rows - 1 - rr;
        for (int cc = 0; cc < cols; ++cc) changed |= update(r, right ? cc : cols - 1 - cc);
      }
    }
    if (!changed) break;
  }

  // The direction ∇S/|∇S| from the upwind differences the update used.
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const std::size_t i = at(r, c);
      if (source[i] || !std::isfinite(S[i])) continue;
      const double sw = water(r, c - 1) ? S[at(r, c - 1)] : kInf;
      const double se = water(r, c + 1) ? S[at(r, c + 1)] : kInf;
      const double sn = water(r - 1, c) ? S[at(r - 1, c)] : kInf;
      const double ss = water(r + 1, c) ? S[at(r + 1, c)] : kInf;
      double gx = std::min(sw, se) < S[i] ? (sw <= se ? S[i] - sw : se - S[i]) : 0.0;
      double gz = std::min(sn, ss) < S[i] ? (sn <= ss ? S[i] - sn : ss - S[i]) : 0.0;
      if (ghost(r, c, true)) gx = h * k0 * ux;
      if (ghost(r, c, false)) gz = h * k0 * uz;
      const double norm = std::hypot(gx, gz);
      if (norm > 0.0) {
        w.dir_x_[i] = gx / norm;
        w.dir_z_[i] = gz / norm;
      }
    }
  }

  // (W.35) ∇·(R·d̂) = 0 for the ray density R = b0/b, by the donor-cell flux (LeVeque 2002): in
  // the order of S, each cell's outflow R·(|d̂_x| + |d̂_z|)·h equals what its upwind neighbours
  // send it, R_N·|d̂_N·n̂|·h from each neighbour N whose direction points at it. What flows onto
  // land or off the map is gone.
  std::vector<std::size_t> order;
  order.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    if (std::isfinite(S[i]) && !source[i]) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::size_t l, std::size_t r) { return S[l] < S[r]; });
  std::vector<char> done(source);
  for (const std::size_t i : order) {
    const auto ucols = static_cast<std::size_t>(cols);
    const int r = static_cast<int>(i / ucols), c = static_cast<int>(i % ucols);
    double inflow = 0.0;
    const auto from = [&](int rn, int cn, double component) {
      if (!water(rn, cn) || !done[at(rn, cn)] || component <= 0.0) return;
      inflow += w.ray_density_[at(rn, cn)] * component;
    };
    from(r, c - 1, water(r, c - 1) ? w.dir_x_[at(r, c - 1)] : 0.0);
    from(r, c + 1, water(r, c + 1) ? -w.dir_x_[at(r, c + 1)] : 0.0);
    from(r - 1, c, water(r - 1, c) ? w.dir_z_[at(r - 1, c)] : 0.0);
    from(r + 1, c, water(r + 1, c) ? -w.dir_z_[at(r + 1, c)] : 0.0);
    // A side edge's ghost sends the cell its own density along the ghost's axis.
    const double out = (ghost(r, c, true) ? 0.0 : std::abs(w.dir_x_[i])) +
                       (ghost(r, c, false) ? 0.0 : std::abs(w.dir_z_[i]));
    w.ray_density_[i] = out > 0.0 ? inflow / out : 0.0;
    done[i] = 1;
  }
  return w;
}

ShoreWavePoint ShoreWave::at(double x, double z) const {
  const ShoreWaveParams& p = params_;
  const double g = p.gravity_mps2;
  const double a = p.direction_deg * std::numbers::pi / 180.0;
  const double ux = std::cos(a), uz = std::sin(a);
  ShoreWavePoint out;
  out.depth_m = sample(p.bathymetry, x, z, kInf);
  if (std::isinf(out.depth_m)) {  // off the map: the deep-water wave
    out.wavenumber_radpm = deep_wavenumber_;
    out.phase_rad = deep_wavenumber_ * (ux * x + uz * z);
    out.direction = {ux, uz};
    out.shoaling = out.refraction = 1.0;
    out.height_m = p.deep_height_m;
    return out;
  }
  if (!(out.depth_m > 0.0)) return out;  // land
  // Bilinear between the cell centres over the reached cells (the phase is +inf elsewhere).
  const HeightMap& m = *p.bathymetry.map;
  const double h = p.bathymetry.size_m / m.cols;
  const double cu = std::clamp((x - p.bathymetry.origin_m[0]) / h - 0.5, 0.0, m.cols - 1.0);
  const double cv = std::clamp((z - p.bathymetry.origin_m[1]) / h - 0.5, 0.0, m.rows - 1.0);
  const int c0 = std::min(static_cast<int>(cu), m.cols - 1), c1 = std::min(c0 + 1, m.cols - 1);
  const int r0 = std::min(static_cast<int>(cv), m.rows - 1), r1 = std::min(r0 + 1, m.rows - 1);
  const double fu = cu - c0, fv = cv - r0;
  const auto cell = [&](int r, int c) {
    return static_cast<std::size_t>(r) * static_cast<std::size_t>(m.cols) +
           static_cast<std::size_t>(c);
  };
  const std::size_t idx[4] = {cell(r0, c0), cell(r0, c1), cell(r1, c0), cell(r1, c1)};
  const double wt[4] = {(1 - fu) * (1 - fv), fu * (1 - fv), (1 - fu) * fv, fu * fv};
  double sum = 0.0, s = 0.0, dx = 0.0, dz = 0.0, density = 0.0;
  for (int j = 0; j < 4; ++j) {
    if (!std::isfinite(phase_[idx[j]]) || wt[j] == 0.0) continue;
    sum += wt[j];
    s += wt[j] * phase_[idx[j]];
    dx += wt[j] * dir_x_[idx[j]];
    dz += wt[j] * dir_z_[idx[j]];
    density += wt[j] * ray_density_[idx[j]];
  }
  const double len = std::hypot(dx, dz);
  if (!(sum > 0.0) || !(len > 0.0)) return out;  // the wave does not reach here
  out.wavenumber_radpm = shore_wavenumber(omega_, out.depth_m, g);
  out.phase_rad = s / sum;
  out.direction = {dx / len, dz / len};
  out.shoaling = std::sqrt(shore_group_velocity(omega_, kInf, g) /
                           shore_group_velocity(omega_, out.depth_m, g));  // (W.35)
  out.refraction = std::sqrt(density / sum);
  const double unbroken = p.deep_height_m * out.shoaling * out.refraction;
  const double highest = p.breaking_index * out.depth_m;  // (W.36)
  out.breaking = unbroken >= highest;
  out.height_m = std::min(unbroken, highest);
  return out;
}

std::array<double, 3> ShoreWave::displacement_at(double x, double z, double time_s,
                                                 double choppiness) const {
  const ShoreWavePoint q = at(x, z);
  if (!(q.height_m > 0.0)) return {0.0, 0.0, 0.0};
  const double theta = q.phase_rad - omega_ * time_s;  // (W.37)
  const double amplitude = 0.5 * q.height_m;
  const double kd = q.wavenumber_radpm * q.depth_m;
  const double horizontal = -choppiness * amplitude * std::sin(theta) / std::tanh(kd);
  return {horizontal * q.direction[0], amplitude * std::cos(theta), horizontal * q.direction[1]};
}

}  // namespace ocean::waves
