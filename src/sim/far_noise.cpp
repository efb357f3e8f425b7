// The far field's noise (ocean/far_noise.hpp, docs/rendering.md R.13, R.13a): the statistics of
// the band it replaces, the fit of the noise octaves, their drift, the CPU reference of the noise
// the renderer's shaders evaluate, and the per-frame map the backends compute (the noise itself
// is far_noise.h, shared with the GLSL).
//
// This work is based on:
//   - VR-GIS FFT+Perlin ("CUDA concurrent kernels: FFT + Perlin noise ocean for a VR-GIS
//     platform"), §III: octaves of one noise at several step lengths; the noise height and normal
//     maps computed each frame beside the FFT (its concurrent kernels).
//   - Perlin, K. (2002) "Improving noise": gradient noise with the quintic fade.
//   - Olano, M. & Baker, D. (2010) "LEAN mapping": slope variances add, which is what the fit and
//     the renderer's roughness use.
//   - Taylor, G. I. (1938) "The spectrum of turbulence": the frozen-field hypothesis, a pattern
//     carried unchanged at the mean velocity — here each octave at the energy-weighted mean phase
//     velocity of its sub-band (R.13a), which keeps every moment of the noise at every time.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "sim/far_noise_map.hpp"

namespace ocean {

namespace {

double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
double fade_derivative(double t) { return 30.0 * t * t * (t * (t - 2.0) + 1.0); }

// What the simulation's normals make of the slope (i·kx, i·kz)·h̃ of one wave vector: the exact
// wavenumber for analytic normals, the central difference's sin(kΔ)/Δ (Aebi, VR Ocean, eq. 45),
// Sobel's smoothed difference (weights 1, 2, 1 across: a factor (1 + cos kΔ)/2). Δ the texel.
std::array<double, 2> slope_transfer(NormalMethod method, double kx, double kz, double spacing) {
  switch (method) {
    case NormalMethod::analytic: return {kx, kz};
    case NormalMethod::central_difference:
      return {std::sin(kx * spacing) / spacing, std::sin(kz * spacing) / spacing};
    case NormalMethod::sobel:
      return {std::sin(kx * spacing) / spacing * 0.5 * (1.0 + std::cos(kz * spacing)),
              std::sin(kz * spacing) / spacing * 0.5 * (1.0 + std::cos(kx * spacing))};
  }
  return {kx, kz};
}

constexpr std::array<std::uint32_t, 3> kSeeds = {OCEAN_FAR_SEED0, OCEAN_FAR_SEED1, OCEAN_FAR_SEED2};

// A lattice coordinate q split into whole cells, wrapped modulo 2³² as the lattice's indices
// are, and the rest in [0, 1) (float rounding may give exactly 1: the next cell's 0).
struct Split {
  std::uint32_t cells;
  float rest;
};
Split split(double q) {
  const double whole = std::floor(q);
  return {static_cast<std::uint32_t>(static_cast<std::int64_t>(whole)),
          static_cast<float>(q - whole)};
}

}  // namespace

UnitNoiseMoments unit_noise_moments() {
  // value = Σ_c W_c·(g_c·d_c), W_c the fade products, d_c the offset from corner c. With unit
  // gradients uniform in angle, E[g gᵀ] = I/2 and corners are independent, so E[value²] =
  // Σ W_c²|d_c|²/2 and E[(∂value/∂x)²] = Σ (∂W_c)²|d_c|²/2 + ∂W_c·W_c·d_c,x + W_c²/2; both
  // integrated over the cell by the midpoint rule (smooth integrands: error ~1e-5).
  constexpr int kPoints = 256;
  UnitNoiseMoments m;
  for (int a = 0; a < kPoints; ++a) {
    const double u = (a + 0.5) / kPoints;
    for (int b = 0; b < kPoints; ++b) {
      const double v = (b + 0.5) / kPoints;
      for (int corner = 0; corner < 4; ++corner) {
        const int cx = corner & 1, cz = corner >> 1;
        const double wu = cx ? fade(u) : 1.0 - fade(u);
        const double wv = cz ? fade(v) : 1.0 - fade(v);
        const double dwu = cx ? fade_derivative(u) : -fade_derivative(u);
        const double dx = u - cx, dz = v - cz;
        const double w = wu * wv, dw = dwu * wv, d2 = dx * dx + dz * dz;
        m.height_variance += w * w * d2 / 2.0;
        m.slope_variance += dw * dw * d2 / 2.0 + dw * w * dx + w * w / 2.0;
      }
    }
  }
  const double cells = static_cast<double>(kPoints) * kPoints;
  m.height_variance /= cells;
  m.slope_variance /= cells;
  return m;
}

namespace {

// Cascade 0's wave vectors (as make_initial_spectrum fills them and src/statistics sums them)
// whose |k| lies in [k_from, k_to) ∩ its band: the sums of BandStatistics.
BandStatistics band_statistics(const SeaState& sea, const SimulationConfig& config, double k_from,
                               double k_to) {
  const Dispersion& dispersion = sea.dispersion();
  const std::array<double, 2> band = cascade_bands(config).front();
  const int n = config.resolution, half = n / 2;
  const double dk = 2.0 * std::numbers::pi / config.cascade_patch_sizes_m.front();
  const double spacing = config.cascade_patch_sizes_m.front() / n;
  BandStatistics s;
  double h2 = 0.0, s2 = 0.0;
  std::array<double, 2> momentum{};  // Σ c(|k|)·k̂·F(k)Δk²
  for (int row = 1; row < n; ++row) {
    for (int col = 1; col < n; ++col) {
      const double kx = dk * (col - half), kz = dk * (row - half);
      const double k = std::hypot(kx, kz);
      if (k <= 0.0 || k < band[0] || k >= band[1] || k < k_from || k >= k_to) continue;
      const double power = sea.wave_vector_spectrum(kx, kz) * dk * dk;
      const std::array<double, 2> t = slope_transfer(config.normals, kx, kz, spacing);
      const double slope_power = (t[0] * t[0] + t[1] * t[1]) * power;
      s.height_variance_m2 += power;
      s.slope_variance += slope_power;
      h2 += power * power;
      s2 += slope_power * slope_power;
      const double c = dispersion.phase_velocity(k);
      momentum[0] += c * kx / k * power;
      momentum[1] += c * kz / k * power;
    }
  }
  // A pair (k, −k) is one complex Gaussian whose |A|² (mean 2p) spreads by its mean: the
  // variance of a realisation's sum is Σ_pairs (2p)² = 2·Σ_k p².
  if (s.height_variance_m2 > 0.0) {
    s.height_sampling_rel_std = std::sqrt(2.0 * h2) / s.height_variance_m2;
    s.phase_velocity_mps = {momentum[0] / s.height_variance_m2, momentum[1] / s.height_variance_m2};
  }
  if (s.slope_variance > 0.0) s.slope_sampling_rel_std = std::sqrt(2.0 * s2) / s.slope_variance;
  return s;
}

}  // namespace

Result<BandStatistics> cascade0_statistics(const SimulationConfig& config) {
  Result<SeaState> sea = SeaState::make(config.sea);
  if (!sea.ok()) return sea.status();
  return band_statistics(sea.value(), config, 0.0, std::numeric_limits<double>::infinity());
}

Result<FarFieldNoise> fit_far_field_noise(const SimulationConfig& config) {
  Result<SeaState> sea = SeaState::make(config.sea);
  if (!sea.ok()) return sea.status();
  return fit_far_field_noise(sea.value(), config);
}

FarFieldNoise fit_far_field_noise(const SeaState& sea, const SimulationConfig& config) {
  FarFieldNoise noise;
  noise.target = band_statistics(sea, config, 0.0, std::numeric_limits<double>::infinity());
  const UnitNoiseMoments unit = unit_noise_moments();
  // The band's wavenumbers on the grid, from the lowest (one period) to its upper edge or the
  // grid's corner, in three equal ratios: octave o stands for the waves of sub-band o.
  const int n = config.resolution;
  const double dk = 2.0 * std::numbers::pi / config.cascade_patch_sizes_m.front();
  const std::array<double, 2> band = cascade_bands(config).front();
  const double k_lo = std::max(band[0], dk);
  const double k_hi = std::min(band[1], dk * (n / 2) * std::numbers::sqrt2);
  const double step = std::cbrt(std::max(k_hi / k_lo, 1.0));
  double k_from = 0.0;
  for (std::size_t o = 0; o < 3; ++o) {
    const double k_to = o == 2 ? std::numeric_limits<double>::infinity()
                               : k_lo * std::pow(step, static_cast<double>(o + 1));
    const BandStatistics sub = band_statistics(sea, config, k_from, k_to);
    const double var_h = sub.height_variance_m2, var_s = sub.slope_variance;
    // One octave of spacing ℓ and amplitude a has a²G = var_h and 2a²Gs/ℓ² = var_s.
    if (var_h > 0.0 && var_s > 0.0) {
      noise.cell_m[o] =
          std::sqrt(2.0 * unit.slope_variance * var_h / (unit.height_variance * var_s));
      noise.amplitude_m[o] = std::sqrt(var_h / unit.height_variance);
      noise.slope_variance[o] = var_s;
      noise.velocity_mps[o] = sub.phase_velocity_mps;
    } else {  // an empty sub-band: an octave of zero amplitude at the sub-band's scale
      noise.cell_m[o] = std::numbers::pi / (k_lo * std::pow(step, static_cast<double>(o) + 0.5));
    }
    k_from = k_to;
  }
  return noise;
}

FarFieldSample far_field_noise(const FarFieldNoise& noise, double x_m, double z_m) {
  float h = 0.0f, sx = 0.0f, sz = 0.0f;
  for (std::size_t o = 0; o < 3; ++o)
    noise::far_octave(static_cast<float>(x_m), static_cast<float>(z_m),
                      static_cast<float>(noise.cell_m[o]), static_cast<float>(noise.amplitude_m[o]),
                      1.0f, kSeeds[o], h, sx, sz);
  return {.height_m = h, .slope_x = sx, .slope_z = sz};
}

FarFieldSample far_field_noise(const FarFieldNoise& noise, double x_m, double z_m, double time_s) {
  float h = 0.0f, sx = 0.0f, sz = 0.0f;
  for (std::size_t o = 0; o < 3; ++o) {
    const double s = noise.cell_m[o];
    const Split u = split((x_m - noise.velocity_mps[o][0] * time_s) / s);
    const Split v = split((z_m - noise.velocity_mps[o][1] * time_s) / s);
    float gx = 0.0f, gz = 0.0f;
    const float g =
        noise::far_gradient_noise_shifted(u.rest, v.rest, u.cells, v.cells, kSeeds[o], gx, gz);
    const auto a = static_cast<float>(noise.amplitude_m[o]);
    const auto inv_cell = static_cast<float>(1.0 / s);
    h += a * g;
    sx += a * inv_cell * gx;
    sz += a * inv_cell * gz;
  }
  return {.height_m = h, .slope_x = sx, .slope_z = sz};
}

FarNoiseLattice far_noise_lattice(const FarFieldNoise& noise, int octave, double x_m, double z_m,
                                  double time_s) {
  const auto o = static_cast<std::size_t>(octave);
  const double s = noise.cell_m[o];
  const Split u = split((x_m - noise.velocity_mps[o][0] * time_s) / s);
  const Split v = split((z_m - noise.velocity_mps[o][1] * time_s) / s);
  return {.cells_u = u.cells, .cells_v = v.cells, .rest_u = u.rest, .rest_v = v.rest};
}

namespace far_noise_map {

noise::FarNoiseMapParams params(const FarFieldNoise& noise, const FarNoiseConfig& map,
                                double time_s) {
  noise::FarNoiseMapParams p{};
  p.resolution = static_cast<std::uint32_t>(map.resolution);
  const double spacing = map.size_m / map.resolution;
  for (std::size_t o = 0; o < 3; ++o) {
    const double s = noise.cell_m[o];
    const Split u = split((map.origin_m[0] - noise.velocity_mps[o][0] * time_s) / s);
    const Split v = split((map.origin_m[1] - noise.velocity_mps[o][1] * time_s) / s);
    p.octave[o] = {.origin_u = u.rest,
                   .origin_v = v.rest,
                   .shift_u = u.cells,
                   .shift_v = v.cells,
                   .step = static_cast<float>(spacing / s),
                   .amplitude_m = static_cast<float>(noise.amplitude_m[o]),
                   .inv_cell = static_cast<float>(1.0 / s),
                   .seed = kSeeds[o]};
  }
  return p;
}

void fill_rows(const noise::FarNoiseMapParams& p, std::size_t begin, std::size_t end, float* out) {
  // far_noise_texel for every texel of the rows, with each octave's corner gradients carried
  // along the row: a row stays in one row of cells, and a texel reuses its left neighbour's
  // cell, or that cell's right edge, so most texels hash no gradient at all (on the default
  // window 2.5× faster than calling far_noise_texel per texel, with the same arithmetic on the
  // same gradients: the same bits).
  const std::size_t n = p.resolution;
  struct Row {
    float v = 0.0f;       // the rest of the lattice coordinate across the row
    std::uint32_t j = 0;  // the row of cells
    std::uint32_t i = 0;  // the cell of `cell`
    bool valid = false;   // `cell` holds cell (i, j)
    noise::FarCell cell{};
  };
  for (std::size_t row = begin; row < end; ++row) {
    Row rows[OCEAN_FAR_OCTAVES];
    for (std::size_t o = 0; o < OCEAN_FAR_OCTAVES; ++o) {
      const noise::FarNoiseOctave& q = p.octave[o];
      const float v = q.origin_v + static_cast<float>(row) * q.step;
      const float fz = std::floor(v);
      rows[o].v = v - fz;
      rows[o].j = static_cast<std::uint32_t>(static_cast<int>(fz)) + q.shift_v;
    }
    float* line = out + 3 * row * n;
    for (std::size_t col = 0; col < n; ++col) {
      float h = 0.0f, sx = 0.0f, sz = 0.0f;
      for (std::size_t o = 0; o < OCEAN_FAR_OCTAVES; ++o) {
        const noise::FarNoiseOctave& q = p.octave[o];
        Row& r = rows[o];
        const float u = q.origin_u + static_cast<float>(col) * q.step;
        const float fx = std::floor(u);
        const std::uint32_t i = static_cast<std::uint32_t>(static_cast<int>(fx)) + q.shift_u;
        if (!r.valid || i != r.i) {
          if (r.valid && i == r.i + 1u) {  // the next cell: its left edge is this one's right
            r.cell.ax = r.cell.bx, r.cell.az = r.cell.bz;
            r.cell.cx = r.cell.ex, r.cell.cz = r.cell.ez;
            noise::far_lattice_gradient(i + 1u, r.j, q.seed, r.cell.bx, r.cell.bz);
            noise::far_lattice_gradient(i + 1u, r.j + 1u, q.seed, r.cell.ex, r.cell.ez);
          } else {
            r.cell = noise::far_cell(i, r.j, q.seed);
          }
          r.i = i;
          r.valid = true;
        }
        float gx = 0.0f, gz = 0.0f;
        const float g = noise::far_cell_noise(u - fx, r.v, r.cell, gx, gz);
        const float a = q.amplitude_m;
        h += a * g;
        sx += a * q.inv_cell * gx;
        sz += a * q.inv_cell * gz;
      }
      line[3 * col] = h;
      line[3 * col + 1] = sx;
      line[3 * col + 2] = sz;
    }
  }
}

}  // namespace far_noise_map

}  // namespace ocean
