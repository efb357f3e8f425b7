// The foam drawn out along the wind (docs/waves.md W.29–W.31, docs/rendering.md R.11), seen from
// straight above in the normals debug view (the foam in the HDR image's alpha).
//
// One blob of foam on an otherwise clean map, drawn with and without the wind drift: W.31's
// footprint is a weighted sum of the map's translates by −u_d·a_j with weights summing to one, so
// against the blob without drift the drawn foam must keep its integral, move its centroid by
// u_d·ā downwind (ā = Σw_j·a_j, the taps' mean age) and not across, and grow its variance along
// the wind by |u_d|²·Var(a) and not across — identities of the footprint, not of our output.
// On a storm sea (the storm preset's wind, 22 m/s) the drawn flecks must be smooth along the wind
// and rough across it, where without the drift they are alike both ways. Skips where no Vulkan
// device exists (fails with OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "ocean/lod.hpp"
#include "ocean/plan.hpp"
#include "ocean/preset.hpp"
#include "render/render_helpers.hpp"
#include "sim/packing.hpp"
#include "support/require_devices.hpp"

namespace foam_streaks_render {  // named: the test target is a unity build

using ocean::render::View;
constexpr int kSide = 160;
constexpr double kHeight = 30.0;  // 28 m across, 0.175 m a pixel
constexpr double kLag = 0.5;      // m: about the storm's flecks (their half-correlation length)

// W.31's taps, restated: ages a_j/τ = (j + ½)·S/K, weights e^{−a_j/τ} normalised (K = 16, S = 4).
struct TapMoments {
  double mean = 0.0;      // ā/τ
  double variance = 0.0;  // Var(a)/τ²
};
TapMoments tap_moments() {
  double w_sum = 0.0, m1 = 0.0, m2 = 0.0;
  for (int j = 0; j < 16; ++j) {
    const double s = (j + 0.5) * 4.0 / 16.0, w = std::exp(-s);
    w_sum += w, m1 += w * s, m2 += w * s * s;
  }
  return {m1 / w_sum, m2 / w_sum - (m1 / w_sum) * (m1 / w_sum)};
}

// The cascades' foam as the streaks draw it: without the whitecaps' patches (R.11b), whose
// threshold would replace the drawn probability with its white share.
View top_down() {
  View view = ocean::render::testing::top_down_debug_view(kHeight);
  view.shading.whitecap_patches = false;
  return view;
}

// The drawn foam at world (x, 0, z), bilinear between pixel centres of the HDR alpha.
double foam_at(const std::vector<float>& hdr, const View& view, double x, double z) {
  const auto& m = ocean::lod::view_projection(view.camera).m;  // column-major
  const double cx = m[0] * x + m[8] * z + m[12], cy = m[1] * x + m[9] * z + m[13];
  const double cw = m[3] * x + m[11] * z + m[15];
  const double u = (cx / cw + 1.0) * 0.5 * kSide - 0.5, v = (1.0 - cy / cw) * 0.5 * kSide - 0.5;
  const int c = static_cast<int>(std::floor(u)), r = static_cast<int>(std::floor(v));
  if (c < 0 || r < 0 || c + 1 >= kSide || r + 1 >= kSide) return 0.0;
  const double fu = u - c, fv = v - r;
  const auto px = [&](int cc, int rr) {
    return static_cast<double>(hdr[(static_cast<std::size_t>(rr) * kSide + cc) * 4 + 3]);
  };
  return (1 - fv) * ((1 - fu) * px(c, r) + fu * px(c + 1, r)) +
         fv * ((1 - fu) * px(c, r + 1) + fu * px(c + 1, r + 1));
}

// Integral, centroid and second central moments of the drawn foam over |x|, |z| ≤ 12 m.
struct Moments {
  double mass = 0.0, x = 0.0, z = 0.0, xx = 0.0, zz = 0.0, xz = 0.0;
};
Moments moments(const std::vector<float>& hdr, const View& view) {
  constexpr double kStep = 0.05;
  double m0 = 0.0, mx = 0.0, mz = 0.0, mxx = 0.0, mzz = 0.0, mxz = 0.0;
  for (double x = -12.0; x <= 12.0; x += kStep)
    for (double z = -12.0; z <= 12.0; z += kStep) {
      const double f = foam_at(hdr, view, x, z);
      m0 += f, mx += f * x, mz += f * z, mxx += f * x * x, mzz += f * z * z, mxz += f * x * z;
    }
  Moments r;
  r.mass = m0 * kStep * kStep;
  r.x = mx / m0, r.z = mz / m0;
  r.xx = mxx / m0 - r.x * r.x, r.zz = mzz / m0 - r.z * r.z, r.xz = mxz / m0 - r.x * r.z;
  return r;
}

TEST(FoamStreaksRender, ABlobMovesAndStretchesDownwindByTheFootprintsMoments) {
  auto ctx = ocean::render::testing::graphics_context();
  if (ctx == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  // One cascade of 128 m at N = 128 (1 m texels; a pixel of 0.175 m magnifies, mip 0).
  ocean::SimulationConfig config;
  config.resolution = 128;
  config.cascade_patch_sizes_m = {128.0};
  config.sea.wind_sea.spectrum.wind_speed_mps = 5.0;
  auto plan = ocean::SimulationPlan::make(config);
  ASSERT_TRUE(plan.ok()) << plan.status().message();
  // A flat map holding a 3 × 3-texel blob of foam 1 round texel (0, 0), i.e. world (0, 0).
  ocean::Frame frame;
  ocean::allocate_frame(config, frame);
  const int n = config.resolution;
  std::vector<float> level(static_cast<std::size_t>(n) * n, 0.0f);
  for (int dr = -1; dr <= 1; ++dr)
    for (int dc = -1; dc <= 1; ++dc)
      level[static_cast<std::size_t>(((dr + n) % n) * n + (dc + n) % n)] = 1.0f;
  ocean::CascadeFrame& cf = frame.cascades[0];
  for (int l = 0, size = n; size >= 1; ++l, size /= 2) {
    const std::size_t base = ocean::mip_offset(n, l);
    for (int i = 0; i < size * size; ++i)
      cf.packed_mips[base + static_cast<std::size_t>(i)] =
          ocean::packing::pack_rgba8(0.0f, 0.0f, level[static_cast<std::size_t>(i)], 1.0f);
    std::vector<float> next(
        static_cast<std::size_t>(std::max(size / 2, 1) * std::max(size / 2, 1)));
    for (int r = 0; r < size / 2; ++r)
      for (int c = 0; c < size / 2; ++c) {
        const auto at = [&](int rr, int cc) {
          return level[static_cast<std::size_t>(rr * size + cc)];
        };
        next[static_cast<std::size_t>(r * (size / 2) + c)] =
            0.25f * (at(2 * r, 2 * c) + at(2 * r, 2 * c + 1) + at(2 * r + 1, 2 * c) +
                     at(2 * r + 1, 2 * c + 1));
      }
    level = std::move(next);
  }
  const std::array<double, 2> drift = {0.4, 0.3};  // m/s, 0.5 m/s towards 36.9°
  const double tau = 3.85;
  std::vector<float> still, drifted;
  for (int pass = 0; pass < 2; ++pass) {
    auto r = ocean::render::Renderer::make(ctx, {.width = kSide, .height = kSide});
    ASSERT_TRUE(r.ok()) << r.status().message();
    ocean::SurfaceDescription surface = plan.value().surface();
    surface.foam_drift_mps = pass == 0 ? std::array<double, 2>{0.0, 0.0} : drift;
    surface.foam_decay_time_s = tau;
    ASSERT_TRUE(r.value()->configure(surface).ok());
    ASSERT_TRUE(r.value()->upload(frame).ok());
    ASSERT_TRUE(r.value()->draw(top_down()).ok());
    ASSERT_TRUE(r.value()->read_hdr(pass == 0 ? still : drifted).ok());
  }
  const Moments a = moments(still, top_down()), b = moments(drifted, top_down());
  const TapMoments taps = tap_moments();
  const double ux = drift[0] * tau, uz = drift[1] * tau, len = std::hypot(ux, uz);
  // Along (ŵ) and across (n̂) the wind.
  const double wx = ux / len, wz = uz / len;
  const auto along_var = [&](const Moments& m) {
    return wx * wx * m.xx + 2 * wx * wz * m.xz + wz * wz * m.zz;
  };
  const auto across_var = [&](const Moments& m) {
    return wz * wz * m.xx - 2 * wx * wz * m.xz + wx * wx * m.zz;
  };
  const double shift_along = (b.x - a.x) * wx + (b.z - a.z) * wz;
  const double shift_across = -(b.x - a.x) * wz + (b.z - a.z) * wx;
  std::printf(
      "blob: mass %.4f -> %.4f m²; centroid moved %.4f m along (footprint: %.4f m), %.4f m "
      "across; variance along %.4f -> %.4f m² (+%.4f expected), across %.4f -> %.4f m²\n",
      a.mass, b.mass, shift_along, len * taps.mean, shift_across, along_var(a), along_var(b),
      len * len * taps.variance, across_var(a), across_var(b));
  // The blob's integral (9 m² of texel values, bilinear): the weights sum to one. Half-float
  // alpha rounds each pixel by ≤ 2⁻¹¹ relative.
  EXPECT_NEAR(b.mass / a.mass, 1.0, 0.01);
  // The centroid: u_d·ā along, 0 across; allowed: a quarter of a pixel (0.044 m).
  EXPECT_NEAR(shift_along, len * taps.mean, 0.044);
  EXPECT_NEAR(shift_across, 0.0, 0.044);
  // The spread: Var(a)·|u_d|² more along the wind (bound 5 %).
  EXPECT_NEAR(along_var(b) - along_var(a), len * len * taps.variance,
              0.05 * len * len * taps.variance);
  // Across: unchanged but for the pixels' bilinear reconstruction, a tent of variance px²/6
  // that aliases with the blob's place among the pixels.
  EXPECT_NEAR(across_var(b), across_var(a), 0.175 * 0.175 / 6.0);
}

// The distance, m, at which the autocorrelation of the drawn foam (its mean removed) along
// (dx, dz) first falls to one half, over the picture's central 20 × 20 m sampled every 0.05 m.
double half_correlation_length(const std::vector<float>& hdr, const View& view, double dx,
                               double dz) {
  constexpr double kStep = 0.05, kHalf = 10.0;
  const int n = static_cast<int>(2 * kHalf / kStep);
  std::vector<double> f(static_cast<std::size_t>(n) * n);
  double mean = 0.0;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) {
      const double v = foam_at(hdr, view, -kHalf + i * kStep, -kHalf + k * kStep);
      f[static_cast<std::size_t>(i) * n + k] = v;
      mean += v;
    }
  mean /= static_cast<double>(f.size());
  for (double& v : f) v -= mean;
  const auto correlation = [&](int lag) {
    const int li = static_cast<int>(std::lround(lag * dx)),
              lk = static_cast<int>(std::lround(lag * dz));
    double sum = 0.0;
    for (int i = 0; i + li < n; ++i)
      for (int k = 0; k + lk < n; ++k)
        sum += f[static_cast<std::size_t>(i) * n + k] *
               f[static_cast<std::size_t>(i + li) * n + k + lk];
    return sum / (static_cast<double>(n - li) * (n - lk));
  };
  const double c0 = correlation(0);
  double previous = 1.0;
  for (int lag = 1; lag < n / 2; ++lag) {
    const double c = correlation(lag) / c0;
    if (c <= 0.5) return kStep * (lag - 1 + (previous - 0.5) / (previous - c));
    previous = c;
  }
  return kStep * n / 2;
}

// The drawn foam's structure function ⟨(f(p + h·d̂) − f(p))²⟩ at lag h, m, along the unit
// (dx, dz), over the picture's central 20 × 20 m: the flecks' contrast at that lag, blind to the
// long cascades' slow swell of the cover that dominates the correlation at larger lags.
double structure_function(const std::vector<float>& hdr, const View& view, double h, double dx,
                          double dz) {
  constexpr double kStep = 0.05, kHalf = 10.0;
  double sum = 0.0;
  int count = 0;
  for (double x = -kHalf; x <= kHalf; x += kStep)
    for (double z = -kHalf; z <= kHalf; z += kStep) {
      const double d = foam_at(hdr, view, x + h * dx, z + h * dz) - foam_at(hdr, view, x, z);
      sum += d * d;
      ++count;
    }
  return sum / count;
}

TEST(FoamStreaksRender, StormFoamIsLongerAlongTheWindThanAcross) {
  auto ctx = ocean::render::testing::graphics_context();
  if (ctx == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  auto config = ocean::preset::builtin("storm");  // 22 m/s towards +x
  ASSERT_TRUE(config.ok()) << config.status().message();
  auto backend = ocean::make_backend("cpu");
  ASSERT_TRUE(backend.ok());
  auto sim = ocean::Simulator::make(config.value(), std::move(backend).value());
  ASSERT_TRUE(sim.ok()) << sim.status().message();
  for (int frame = 0; frame <= 20; ++frame) sim.value()->step(2.0 + 0.1 * frame);
  const ocean::SurfaceDescription surface = sim.value()->plan().surface();
  ASSERT_NEAR(surface.foam_drift_mps[0], ocean::kWindDriftFraction * 22.0, 1e-12);
  ASSERT_NEAR(surface.foam_drift_mps[1], 0.0, 1e-12);
  double contrast[2] = {0.0, 0.0}, mean[2] = {0.0, 0.0};
  for (int pass = 0; pass < 2; ++pass) {
    auto r = ocean::render::Renderer::make(ctx, {.width = kSide, .height = kSide});
    ASSERT_TRUE(r.ok()) << r.status().message();
    ocean::SurfaceDescription s = surface;
    if (pass == 0) s.foam_drift_mps = {0.0, 0.0};
    ASSERT_TRUE(r.value()->configure(s).ok());
    ASSERT_TRUE(r.value()->upload(sim.value()->frame()).ok());
    ASSERT_TRUE(r.value()->draw(top_down()).ok());
    std::vector<float> hdr;
    ASSERT_TRUE(r.value()->read_hdr(hdr).ok());
    const double along = half_correlation_length(hdr, top_down(), 1.0, 0.0);
    const double across = half_correlation_length(hdr, top_down(), 0.0, 1.0);
    const double d_along = structure_function(hdr, top_down(), kLag, 1.0, 0.0);
    const double d_across = structure_function(hdr, top_down(), kLag, 0.0, 1.0);
    contrast[pass] = d_across / d_along;
    for (std::size_t i = 3; i < hdr.size(); i += 4) mean[pass] += hdr[i];
    mean[pass] /= static_cast<double>(hdr.size() / 4);
    std::printf(
        "%s: foam %.4f; half-correlation %.3f m along the wind, %.3f m across; structure "
        "function at %.2f m: %.3g along, %.3g across (ratio %.2f)\n",
        pass == 0 ? "no drift" : "drift   ", mean[pass], along, across, kLag, d_along, d_across,
        contrast[pass]);
  }
  // Without drift the flecks are as rough along the wind as across (the storm's spreading is
  // broad): the ratio is 1 within a quarter. The footprint (W.31) smooths them along the wind
  // over |u_d|·τ = 2.5 m, five times the lag, and not across: at least twice as rough across.
  EXPECT_NEAR(contrast[0], 1.0, 0.25);
  EXPECT_GT(contrast[1], 2.0);
  // The footprint's weights sum to one: the drawn cover stays the map's (2 % sampling of the
  // picture's 28 m by its flecks aside).
  EXPECT_NEAR(mean[1] / mean[0], 1.0, 0.02);
}

}  // namespace foam_streaks_render
