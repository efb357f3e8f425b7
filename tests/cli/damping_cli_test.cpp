// The damping flags of `ocean query`: a mask of 1 and deep water change nothing, a mask of 0 and
// dry land do; bad maps, placements and values are one line and a non-zero exit; `ocean bake`
// refuses the flags.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "cli/cli_run.hpp"
#include "ocean/io.hpp"

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
  ocean_test::expect_usage_error(sea + " --shallows beach", "--shallows = 'beach': must be");
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
