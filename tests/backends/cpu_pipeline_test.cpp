// The CPU scalar reference pipeline stage by stage on hand-made spectra: one wave vector gives the
// analytic cosine and trochoid, a flat sea gives J = 1, foam accumulates and decays as
// published, packing and smoothness follow Aebi, VR Ocean, eqs. 49–55.
#include <gtest/gtest.h>

#include <cmath>

#include "cpu/cpu_backend.hpp"

namespace {

using ocean::cpu::CascadeState;

constexpr double kPi = ocean::kPi;

struct Pipeline {
  ocean::SimulationConfig config;
  CascadeState state;
  ocean::CascadeFrame frame;
  ocean::fft::Plan2D plan;
  std::unique_ptr<ocean::TaskRunner> runner = ocean::make_serial_runner();

  Pipeline(int n, double patch, ocean::NormalMethod method, double choppiness) {
    config.resolution = n;
    config.cascade_patch_sizes_m = {patch};
    config.normals = method;
    config.choppiness = choppiness;
    config.loop_period_s = 0.0;
    const auto texels = static_cast<std::size_t>(n * n);
    state.resolution = n;
    state.patch_size_m = patch;
    state.spectrum.resolution = n;
    state.spectrum.patch_size_m = patch;
    state.spectrum.packed.assign(texels, {0, 0, 0, 0});
    state.spectrum.omega.assign(texels, 0.0f);
    state.spectrum.h0.assign(texels, 0.0);
    ocean::cpu::build_plane_factors(state, method, choppiness);
    const auto planes = static_cast<std::size_t>(ocean::cpu::plane_count(method));
    state.plane_re.assign(planes, std::vector<float>(texels));
    state.plane_im.assign(planes, std::vector<float>(texels));
    state.foam.assign(texels, 0.0f);
    state.mip_work.assign(4 * ocean::mip_chain_texels(n), 0.0f);
    frame.resolution = n;
    frame.patch_size_m = patch;
    frame.displacement.assign(3 * texels, 0.0f);
    frame.displacement_half.assign(4 * texels, 0);
    frame.normal.assign(3 * texels, 0.0f);
    frame.jacobian.assign(texels, 0.0f);
    frame.foam.assign(texels, 0.0f);
    frame.packed_mips.assign(ocean::mip_chain_texels(n), 0u);
    plan = ocean::fft::Plan2D::make(n).value();
  }

  // One travelling wave A·cos(k·x − ωt) at grid wave vector (m, row): h0(k) = A/2 and its
  // partner's packed conjugate (M.6.5).
  void inject(int m, int row, double amplitude, float omega) {
    const int n = state.resolution;
    const std::size_t i = static_cast<std::size_t>(row * n + m);
    const std::size_t j = static_cast<std::size_t>(((n - row) % n) * n + (n - m) % n);
    const float a = static_cast<float>(amplitude / 2);
    state.spectrum.packed[i] = {a, 0.0f, 0.0f, -a};  // (a+c, b+d, b−d, c−a) with (a,0), (0,0)
    state.spectrum.packed[j] = {a, 0.0f, 0.0f, a};   // (0,0) and conj(h0(k)) = (a, 0)
    state.spectrum.omega[i] = state.spectrum.omega[j] = omega;
  }

  void run(double t, double dt = 0.0, bool reset = true) {
    ocean::cpu::evolve(state, t, 0.0, *runner);
    ocean::fft::SplitComplex planes[ocean::fft::kMaxPlanes];
    for (std::size_t p = 0; p < state.plane_re.size(); ++p) {
      planes[p] = {state.plane_re[p].data(), state.plane_im[p].data()};
    }
    plan.inverse({planes, state.plane_re.size()}, *runner, true);
    ocean::cpu::assemble_displacement_reference(state, state.plane_re[1].data(), frame, *runner);
    ocean::cpu::finalize(state, config, dt, reset, frame, *runner);
    ocean::cpu::build_mips(state, frame, *runner);
  }
};

TEST(CpuPipeline, SingleWaveIsAnalyticTrochoid) {
  for (auto method : {ocean::NormalMethod::analytic, ocean::NormalMethod::central_difference,
                      ocean::NormalMethod::sobel}) {
    const int n = 64;
    const double patch = 100.0, amplitude = 1.5, lambda = 0.8;
    const float omega = 0.9f;
    const double t = 3.7;
    Pipeline p(n, patch, method, lambda);
    const int m = n / 2 + 3, row = n / 2 - 2;  // k = 2π/L·(3, −2)
    p.inject(m, row, amplitude, omega);
    p.run(t);
    const double kx = 2 * kPi / patch * 3, kz = 2 * kPi / patch * -2;
    const double k = std::hypot(kx, kz);
    // Central differences see sin(kΔ)/Δ instead of k; Sobel additionally the cross weight.
    const double spacing = patch / n;
    const auto derivative_gain = [&](double kk, double kother) {
      if (method == ocean::NormalMethod::analytic) return kk;
      const double central = std::sin(kk * spacing) / spacing;
      if (method == ocean::NormalMethod::central_difference) return central;
      return central * (2.0 + 2.0 * std::cos(kother * spacing)) / 4.0;
    };
    const double gx = derivative_gain(kx, kz), gz = derivative_gain(kz, kx);
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) {
        const std::size_t i = static_cast<std::size_t>(r * n + c);
        const double x = c * spacing, z = r * spacing;
        const double theta = kx * x + kz * z - omega * t;
        ASSERT_NEAR(p.frame.displacement[3 * i + 1], amplitude * std::cos(theta), 2e-5);
        ASSERT_NEAR(p.frame.displacement[3 * i + 0], -lambda * amplitude * kx / k * std::sin(theta),
                    2e-5);
        ASSERT_NEAR(p.frame.displacement[3 * i + 2], -lambda * amplitude * kz / k * std::sin(theta),
                    2e-5);
        // Analytic derivatives of the trochoid p(x) = (x − λA·k̂x·sinθ, A·cosθ, z − λA·k̂z·sinθ).
        const double s = std::sin(theta), co = std::cos(theta);
        const double dx_dx = -lambda * amplitude * kx / k * gx * co,
                     dx_dz = -lambda * amplitude * kx / k * gz * co;
        const double dz_dx = -lambda * amplitude * kz / k * gx * co,
                     dz_dz = -lambda * amplitude * kz / k * gz * co;
        const double h_dx = -amplitude * gx * s, h_dz = -amplitude * gz * s;
        const double jac = (1 + dx_dx) * (1 + dz_dz) - dx_dz * dz_dx;
        ASSERT_NEAR(p.frame.jacobian[i], jac, 2e-5) << ocean::to_string(method);
        double nx = h_dz * dz_dx - (1 + dz_dz) * h_dx, ny = jac,
               nz = dx_dz * h_dx - h_dz * (1 + dx_dx);
        const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
        ASSERT_NEAR(p.frame.normal[3 * i + 0], nx / len, 2e-5);
        ASSERT_NEAR(p.frame.normal[3 * i + 1], ny / len, 2e-5);
        ASSERT_NEAR(p.frame.normal[3 * i + 2], nz / len, 2e-5);
      }
    }
    if (method == ocean::NormalMethod::analytic) {
      // Exact derivatives: J = 1 − λ·A·k·cosθ for a single wave.
      ASSERT_NEAR(p.frame.jacobian[0], 1 - lambda * amplitude * k * std::cos(-omega * t), 2e-5);
    }
  }
}

TEST(CpuPipeline, FlatSeaHasUnitJacobianAndUpNormals) {
  Pipeline p(32, 50.0, ocean::NormalMethod::central_difference, 1.0);
  p.config.roughness = 0.0;
  p.run(1.0);
  for (std::size_t i = 0; i < 32 * 32; ++i) {
    EXPECT_EQ(p.frame.jacobian[i], 1.0f);
    EXPECT_EQ(p.frame.normal[3 * i + 1], 1.0f);
    EXPECT_EQ(p.frame.displacement[3 * i + 1], 0.0f);
    EXPECT_EQ(p.frame.foam[i], 0.0f);
  }
  // Flat and perfectly smooth: every mip texel is (128, 128, 0, 255).
  const std::uint32_t expected = 128u | (128u << 8) | (0u << 16) | (255u << 24);
  for (std::uint32_t v : p.frame.packed_mips) ASSERT_EQ(v, expected);
}

// Vincevičius 2024, listing 2.4: foam_t = max(foam_{t−1} − decay·dt/max(now, 0.5), now).
TEST(CpuPipeline, FoamAccumulatesAndDecays) {
  const int n = 32;
  Pipeline p(n, 20.0, ocean::NormalMethod::central_difference, 1.0);
  p.config.foam = {.source = ocean::FoamSource::ramp,
                   .jacobian_start = 0.3,
                   .jacobian_full = -0.2,
                   .decay_per_s = 0.5};
  // A steep, very choppy wave folds (J < 0) at its crests.
  p.inject(n / 2 + 2, n / 2, 2.0, 1.0f);
  p.run(0.0);
  float max_foam = 0.0f;
  std::size_t crest = 0;
  for (std::size_t i = 0; i < p.frame.foam.size(); ++i) {
    if (p.frame.foam[i] > max_foam) max_foam = p.frame.foam[i], crest = i;
  }
  ASSERT_EQ(max_foam, 1.0f);
  ASSERT_LT(p.frame.jacobian[crest], -0.2f);
  // Calm the sea: J = 1 everywhere, so "now" is 0 and the foam decays by decay·dt/0.5.
  p.state.spectrum.packed.assign(p.state.spectrum.packed.size(), {0, 0, 0, 0});
  p.run(0.4, 0.4, false);
  EXPECT_NEAR(p.frame.foam[crest], 1.0f - 0.5f * 0.4f / 0.5f, 1e-6);
  p.run(0.8, 0.4, false);
  EXPECT_NEAR(p.frame.foam[crest], 1.0f - 2 * 0.5f * 0.4f / 0.5f, 1e-6);
  p.run(5.0, 4.2, false);
  EXPECT_EQ(p.frame.foam[crest], 0.0f);
}

// Aebi, VR Ocean, eqs. 49, 53, 50–51.
TEST(CpuPipeline, RoughnessSmoothnessAndPacking) {
  EXPECT_FLOAT_EQ(ocean::cpu::normal_length_from_roughness(0.0f), 1.0f);
  EXPECT_NEAR(ocean::cpu::normal_length_from_roughness(1.0f), 0.5f, 1e-6f);
  EXPECT_FLOAT_EQ(ocean::cpu::smoothness_from_normal_length(1.0f), 1.0f);
  // float(2/3) lies 2e-8 above 2/3: 3·|n| − 2 is 0 when the product is rounded and 6e-8 when it
  // is fused into the subtraction (GCC contracts on AArch64), so the edge of the ramp is tested
  // to within 1e-6 rather than for an exact 0.
  EXPECT_NEAR(ocean::cpu::smoothness_from_normal_length(2.0f / 3.0f), 0.0f, 1e-6f);
  EXPECT_FLOAT_EQ(ocean::cpu::smoothness_from_normal_length(0.1f), 0.0f);
  // t = 0.5: r = 1 − 0.5·(0.85 + 0.075) = 0.5375, smoothness = 1 − √r.
  EXPECT_NEAR(ocean::cpu::smoothness_from_normal_length(5.0f / 6.0f), 1.0f - std::sqrt(0.5375f),
              1e-6f);
  EXPECT_EQ(ocean::cpu::pack_rgba8(1.0f, -1.0f, 0.5f, 1.0f),
            255u | (0u << 8) | (128u << 16) | (255u << 24));
  EXPECT_EQ(ocean::cpu::pack_rgba8(0.0f, 0.0f, 2.0f, -1.0f), 128u | (128u << 8) | (255u << 16));
}

// Mip offsets (Aebi, VR Ocean, eq. 55) and averaging of unnormalised normals (eq. 52): a
// checkerboard of two tilted normals averages to a shorter vector, i.e. a rougher (less smooth)
// level 1.
TEST(CpuPipeline, MipChainLayoutAndToksvigSmoothness) {
  EXPECT_EQ(ocean::mip_chain_texels(256), (4u * 256u * 256u - 1u) / 3u);
  EXPECT_EQ(ocean::mip_offset(256, 0), 0u);
  EXPECT_EQ(ocean::mip_offset(256, 1), 65536u);
  EXPECT_EQ(ocean::mip_offset(256, 2), 65536u + 16384u);
  EXPECT_EQ(ocean::mip_offset(256, 8), ocean::mip_chain_texels(256) - 1);
  const int n = 32;
  Pipeline p(n, 32.0, ocean::NormalMethod::central_difference, 0.0);
  p.config.roughness = 0.0;
  p.inject(n / 2 + n / 4, n / 2, 0.4, 0.0f);  // wavelength 4 texels: steep slopes alternate
  p.run(0.0);
  const auto smooth = [&](std::size_t texel) { return (p.frame.packed_mips[texel] >> 24) & 255u; };
  EXPECT_EQ(smooth(0), 255u);  // level 0 is as smooth as its roughness says
  const std::size_t level2 = ocean::mip_offset(n, 2);
  EXPECT_LT(smooth(level2), 200u);  // averaged over a whole wavelength: normals diverge
}

}  // namespace
