// The damping flags of `ocean query`: a mask of 1 and deep water change nothing, a mask of 0 and
// dry land do; bad maps, placements and values are one line and a non-zero exit; `ocean bake`
// refuses the flags. Over `--shallows beach` the queried heights carry the peak wave shoaled and
// refracted as linear theory's closed forms say (docs/waves.md W.32–W.38).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numbers>

#include "cli/cli_run.hpp"
#include "ocean/io.hpp"
#include "ocean/sim.hpp"
#include "support/depth_law.hpp"

namespace {

namespace fs = std::filesystem;

// A 4×4 .npy of one value.
fs::path constant_npy(const fs::path& dir, const std::string& name, float value) {
  const std::vector<float> v(16, value);
  const std::size_t shape[] = {4, 4};
  EXPECT_TRUE(ocean::io::write_npy(dir / name, v.data(), shape).ok());
  return dir / name;
}

constexpr const char* kDampedSea =
    "query --resolution 32 --cascades 200,47 --seed 4 --time 2 --json --at '1,2;10,-20;-30,40'";

std::vector<double> damped_heights(const std::string& extra) {
  const auto r = ocean_test::run_cli(std::string(kDampedSea) + extra);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  if (r.exit_code != 0) return {};
  return nlohmann::json::parse(r.out)["height_m"].get<std::vector<double>>();
}

TEST(DampingCli, MaskAndBathymetryActWhereTheySay) {
  ocean_test::ScratchDir dir("damping_cli_");
  const auto at = [](const fs::path& file) { return " " + file.string() + ",-50,-50,100"; };
  const std::vector<double> bare = damped_heights("");
  ASSERT_EQ(bare.size(), 3u);
  EXPECT_EQ(damped_heights(" --damping-mask" + at(constant_npy(dir.path, "one.npy", 1.0f))), bare);
  EXPECT_EQ(damped_heights(" --bathymetry" + at(constant_npy(dir.path, "deep.npy", 1e5f))), bare);
  const std::vector<double> low =
      damped_heights(" --damping-mask" + at(constant_npy(dir.path, "zero.npy", 0.0f)));
  ASSERT_EQ(low.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NE(low[i], bare[i]) << i;
  // Depth 0: every band has weight 0 (Φ = 0), the surface is flat.
  EXPECT_EQ(damped_heights(" --bathymetry" + at(constant_npy(dir.path, "dry.npy", 0.0f))),
            (std::vector<double>{0.0, 0.0, 0.0}));
  // Outside the maps nothing changes.
  EXPECT_EQ(damped_heights(" --damping-mask " + (dir.path / "zero.npy").string() + ",500,500,10"),
            bare);
}

TEST(DampingCli, BreakingHoldsTheHeightsOverShallowWaterAndTheLagoonHasAnIsland) {
  ocean_test::ScratchDir dir("damping_cli_surf_");
  const std::string shallow =
      " --bathymetry " + constant_npy(dir.path, "shallow.npy", 0.1f).string() + ",-50,-50,100";
  // Over 0.1 m of water the damped sea's H_rms exceeds γ·d: breaking scales every band by the one
  // factor γ·d/H_rms (W.27), so without choppiness (a query then reads the point itself) each
  // height is the unbroken one times that factor, below 1.
  const std::string flat = " --choppiness 0" + shallow;
  const std::vector<double> unbroken = damped_heights(flat + " --breaking-index 0");
  const std::vector<double> broken = damped_heights(flat);
  ASSERT_EQ(unbroken.size(), 3u);
  ASSERT_EQ(broken.size(), 3u);
  const double factor = broken[0] / unbroken[0];
  EXPECT_LT(factor, 0.99);
  EXPECT_GT(factor, 0.0);
  for (std::size_t i = 1; i < 3; ++i) EXPECT_NEAR(broken[i], factor * unbroken[i], 1e-6) << i;
  // A higher index lets the waves be higher.
  const std::vector<double> higher = damped_heights(flat + " --breaking-index 1.2");
  ASSERT_EQ(higher.size(), 3u);
  EXPECT_GT(std::abs(higher[0]), std::abs(broken[0]));
  // The lagoon's island, land within 40 m of its centre (its shore at 50 m): no waves.
  const auto island = ocean_test::run_cli(
      "query --resolution 32 --cascades 200,47 --seed 4 --time 2 --json --choppiness 0 "
      "--shallows lagoon --at '1,2;10,-20;-20,30'");
  ASSERT_EQ(island.exit_code, 0) << island.err;
  EXPECT_EQ(nlohmann::json::parse(island.out)["height_m"].get<std::vector<double>>(),
            (std::vector<double>{0.0, 0.0, 0.0}));
}

// The root k of ω² = g·k·tanh(k·d) by bisection (Dean & Dalrymple 1991, ch. 3).
double beach_dispersion_root(double omega, double d) {
  constexpr double g = 9.81;
  double lo = 0.0, hi = 10.0 * omega * omega / g + omega / std::sqrt(g * d);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (g * mid * std::tanh(mid * d) < omega * omega ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The beach (apps/ocean/shallows.hpp): contours whose normal points 35° from +x towards +z, the
// shore 100 m out along it, the bottom at 1:20 from 10 m deep. A wind sea of Tp = 8 s travelling
// along +x meets them at θ0 = 35°. The shore wave's part of a queried height is what the query
// gives less what it gives with the shore wave's layer moved away; its amplitude is read from two
// instants a quarter period apart. Between 3 m and 1 m of water it grows by the ratio of
// β·K_s·K_r (W.35, W.38): K_s = √(c_g0/c_g), K_r = √(cos θ0/cos θ) with Snell's
// sin θ = (k0/k)·sin θ0, β = √(1 − Φ(√(g·k_low), d)), k_low the low band's wavenumber (W.14).
TEST(DampingCli, TheBeachCarriesThePeakWaveShoaledAndRefracted) {
  constexpr double pi = std::numbers::pi, gravity = 9.81, tp = 8.0, theta0 = 35.0 * pi / 180.0;
  const double nx = std::cos(theta0), nz = std::sin(theta0);
  const double u_deep = 40.0, u_shallow = 80.0;  // d = 3 m and 1 m
  const std::string at = std::to_string(u_deep * nx) + "," + std::to_string(u_deep * nz) + ";" +
                         std::to_string(u_shallow * nx) + "," + std::to_string(u_shallow * nz) +
                         ";140,60;-400,0";  // land; off the map
  const auto heights = [&](double t, const std::string& extra) {
    const auto r = ocean_test::run_cli(
        "query --resolution 32 --cascades 200,47 --seed 4 --hs 0.4 --tp 8 --json --choppiness 0 "
        "--shallows beach --time " +
        std::to_string(t) + " --at '" + at + "'" + extra);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.exit_code == 0 ? nlohmann::json::parse(r.out)["height_m"].get<std::vector<double>>()
                            : std::vector<double>(4, std::nan(""));
  };
  const std::string away = " --local-area 3000,3000,50 --local-resolution 64";
  std::vector<double> amplitude(4, 0.0);
  for (double t : {3.0, 3.0 + tp / 4.0}) {
    const std::vector<double> with = heights(t, ""), without = heights(t, away);
    ASSERT_EQ(with.size(), 4u);
    ASSERT_EQ(without.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i)
      amplitude[i] += (with[i] - without[i]) * (with[i] - without[i]);
  }
  for (double& a : amplitude) a = std::sqrt(a);
  EXPECT_EQ(amplitude[2], 0.0);  // land carries no wave
  EXPECT_EQ(amplitude[3], 0.0);  // nor does the sea beyond the map
  ocean::SimulationConfig bands;
  bands.resolution = 32;
  bands.cascade_patch_sizes_m = {200.0, 47.0};
  const double k_low = ocean::band_wavenumbers(bands).front();
  const double omega = 2.0 * pi / tp, k0 = omega * omega / gravity;
  const auto theory = [&](double d) {
    const double k = beach_dispersion_root(omega, d);
    const double cg = 0.5 * (1.0 + 2.0 * k * d / std::sinh(2.0 * k * d)) * omega / k;
    const double sin_theta = k0 / k * std::sin(theta0);
    const double ks = std::sqrt(gravity / (2.0 * omega) / cg);
    const double kr = std::sqrt(std::cos(theta0) / std::sqrt(1.0 - sin_theta * sin_theta));
    const double beta =
        std::sqrt(1.0 - ocean_test::kitaigorodskii_phi(std::sqrt(gravity * k_low), d));
    return beta * ks * kr;
  };
  const double want = theory(1.0) / theory(3.0);
  ASSERT_GT(amplitude[0], 0.0);
  const double got = amplitude[1] / amplitude[0];
  std::printf(
      "shore wave amplitude over 3 m and 1 m: %.4f and %.4f m, ratio %.4f, closed form "
      "%.4f\n",
      amplitude[0], amplitude[1], got, want);
  // The layer's frames and cells: a blend of two frames keeps ≥ cos(π/32) of the amplitude, a
  // bilinear sample between cells ≥ cos(π/n) at n cells per wavelength (21 over 1 m of water);
  // the ray sweeps on contours at 35° to the grid ≈ 0.2 % (tests/waves/shore_wave_test.cpp).
  EXPECT_NEAR(got, want, 0.03 * want);
}

TEST(DampingCli, BadInputIsOneLine) {
  ocean_test::ScratchDir dir("damping_cli_bad_");
  const std::string sea = kDampedSea;
  const auto missing = ocean_test::run_cli(sea + " --bathymetry /nonexistent/d.npy,0,0,10");
  EXPECT_EQ(missing.exit_code, 1);  // an unreadable file is a runtime failure
  EXPECT_TRUE(missing.out.empty());
  EXPECT_NE(missing.err.find("--bathymetry: cannot read '/nonexistent/d.npy'"), std::string::npos)
      << missing.err;
  EXPECT_EQ(ocean_test::line_count(missing.err), 1);
  const std::string high = constant_npy(dir.path, "high.npy", -2e4f).string();  // land 20 km up
  ocean_test::expect_usage_error(sea + " --bathymetry " + high + ",0,0,10",
                                 "bathymetry value 0 = -20000 is not a depth");
  const std::string nan = constant_npy(dir.path, "nan.npy", std::nanf("")).string();
  ocean_test::expect_usage_error(sea + " --bathymetry " + nan + ",0,0,10", "not a finite");
  const std::string ok = constant_npy(dir.path, "ok.npy", 1.0f).string();
  ocean_test::expect_usage_error(sea + " --bathymetry " + ok + ",0,0,0", "size_m = 0");
  ocean_test::expect_usage_error(sea + " --damping-mask " + ok + ",0,0", "FILE,X0,Z0,SIZE_M");
  ocean_test::expect_usage_error(sea + " --damping-mask " + ok + ",nan,0,5", "--damping-mask");
  const std::string two = constant_npy(dir.path, "two.npy", 2.0f).string();
  ocean_test::expect_usage_error(sea + " --damping-mask " + two + ",0,0,10",
                                 "damping mask value 0 = 2 is not in [0, 1]");
  ocean_test::expect_usage_error(sea + " --bathymetry x.png,0,0,10", "need a .npy file");
  ocean_test::expect_usage_error(sea + " --shallows reef", "--shallows = 'reef': must be");
  ocean_test::expect_usage_error(sea + " --shallows lagoon --bathymetry " + ok + ",0,0,10",
                                 "not with --damping-mask or --bathymetry");
  ocean_test::expect_usage_error(sea + " --bathymetry " + ok + ",0,0,10 --breaking-index 2",
                                 "--breaking-index '2': breaking_index = 2");
  ocean_test::expect_usage_error(sea + " --shallows lagoon --breaking-index 0.1",
                                 "--breaking-index '0.1'");
  ocean_test::expect_usage_error(sea + " --bathymetry " + ok + ",0,0,10 --breaking-index x",
                                 "--breaking-index");
  ocean_test::expect_usage_error(
      "query --calm --local-area 0,0,10 --at 1,1 --bathymetry " + ok + ",0,0,10", "--calm");
  ocean_test::expect_usage_error("bake --resolution 32 --frames 1 --out " +
                                     (dir.path / "never").string() + " --damping-mask " + ok +
                                     ",0,0,10",
                                 "not applied by bake");
  EXPECT_FALSE(fs::exists(dir.path / "never"));
}

}  // namespace
