// `ocean stats`: the JSON keys and table, nulls and defaults, and the bad-input contract. The
// statistics themselves are tested in tests/statistics/surface_stats_test.cpp.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "cli/cli_run.hpp"

namespace {

constexpr double kG = 9.81;

// --- The command line --------------------------------------------------------------------------

using ocean_test::CliRun;
const auto run_stats = ocean_test::run_cli;

TEST(CliStats, JsonHasEveryKey) {
  const CliRun r = run_stats(
      "stats --json --model pierson-moskowitz --wind-speed 8 --patch-size 800 --resolution 64 "
      "--seeds 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"hs_measured_m",
                          "hs_spectrum_m",
                          "hs_closed_form_m",
                          "mean_height_m",
                          "height_skewness",
                          "height_kurtosis",
                          "mean_square_slope",
                          "cox_munk_mss",
                          "resolved_mss_upwind",
                          "resolved_mss_crosswind",
                          "unresolved_mss_upwind",
                          "unresolved_mss_crosswind",
                          "total_mss",
                          "cox_munk_mss_upwind",
                          "cox_munk_mss_crosswind",
                          "folded_fraction",
                          "min_jacobian",
                          "foam_coverage",
                          "mean_foam",
                          "max_imaginary_rel_hs",
                          "loop_error_rel_hs",
                          "resolution",
                          "patch_size_m",
                          "seeds",
                          "time_s",
                          "choppiness",
                          "model"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["resolution"].get<int>(), 64);
  EXPECT_EQ(j["patch_size_m"].get<double>(), 800.0);
  EXPECT_EQ(j["seeds"].get<int>(), 2);
  EXPECT_EQ(j["time_s"].get<double>(), 0.0);
  EXPECT_EQ(j["model"].get<std::string>(), "pierson-moskowitz");
  EXPECT_NEAR(j["hs_closed_form_m"].get<double>(), 0.2093 * 64.0 / kG, 1e-3);
  EXPECT_NEAR(j["cox_munk_mss"].get<double>(), 0.003 + 5.12e-3 * 8.0, 1e-12);
  EXPECT_GT(j["hs_measured_m"].get<double>(), 0.0);
}

TEST(CliStats, NullsAndDefaults) {
  // Hs/Tp sea: no wind speed, no Cox–Munk; no loop: no loop error. Default patch 1000 m.
  const CliRun r = run_stats(
      "stats --json --model jonswap --hs 2 --tp 8 --resolution 32 --seeds 1 --loop-period 0 "
      "--time 2.5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["cox_munk_mss"].is_null());
  EXPECT_TRUE(j["total_mss"].is_null());
  EXPECT_TRUE(j["unresolved_mss_upwind"].is_null());
  EXPECT_TRUE(j["loop_error_rel_hs"].is_null());
  EXPECT_EQ(j["patch_size_m"].get<double>(), 1000.0);
  EXPECT_EQ(j["time_s"].get<double>(), 2.5);
  // --cascades are used when --patch-size is not given; stats describe cascade 0.
  const CliRun cascades = run_stats("stats --json --cascades 300,70 --resolution 32 --seeds 1");
  ASSERT_EQ(cascades.exit_code, 0) << cascades.err;
  EXPECT_EQ(nlohmann::json::parse(cascades.out)["patch_size_m"].get<double>(), 300.0);
  // Without --json: a table with a header and one row per key.
  const CliRun table = run_stats("stats --resolution 32 --seeds 1");
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_NE(table.out.find("hs_measured_m"), std::string::npos);
  EXPECT_NE(table.out.find("unit"), std::string::npos);
}

TEST(CliStats, BadInputExitsTwoWithOneLineAndNoStdout) {
  struct StatsCase {
    const char* args;
    const char* mentions;
  };
  const StatsCase cases[] = {
      {"stats --seeds 0", "--seeds = 0"},
      {"stats --seeds=-3", "--seeds = -3"},
      {"stats --seeds 2.5", "--seeds = 2.5"},
      {"stats --seeds x", "--seeds = 'x'"},
      {"stats --patch-size 0", "--patch-size = 0"},
      {"stats --patch-size=-10", "--patch-size = -10"},
      {"stats --patch-size nan", "--patch-size = nan"},
      {"stats --time nan", "--time = nan"},
      {"stats --time inf", "--time = inf"},
      {"stats --resolution 100", "resolution = 100"},
      {"stats --model pierson-moskowitz --wind-speed=-3", "--wind-speed = -3"},
      {"stats --no-such-flag", "no-such-flag"},
  };
  for (const StatsCase& c : cases) ocean_test::expect_usage_error(c.args, c.mentions);
}

}  // namespace
