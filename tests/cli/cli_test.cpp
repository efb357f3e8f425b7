// The ocean command line: JSON output against published values, and the bad-input contract
// (exit 2, nothing on stdout, one line on stderr naming the flag).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/cli_run.hpp"
#include "ocean/conformance.hpp"

namespace {

using ocean_test::CliRun;
const auto run = ocean_test::run_cli;

// xdyn BretschneiderSpectrumTest.cpp: Hs = 1, Tp = 5, ω = 1 → 0.034510725921325.
TEST(Cli, SpectrumJsonMatchesPublishedValue) {
  const CliRun r = run("spectrum --model pierson-moskowitz --hs 1 --tp 5 --omega 1,0 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["S"][0].get<double>(), 0.034510725921325, 1e-14);
  EXPECT_EQ(j["S"][1].get<double>(), 0.0);
  EXPECT_EQ(j["omega"].size(), 2u);
}

TEST(Cli, SpectrumAcceptsEveryModelAndFlag) {
  const char* ok[] = {
      "spectrum --model jonswap --wind-speed 12 --fetch 50000 --omega 0.5,1 --json",
      "spectrum --model jonswap --hs 3 --tp 9 --gamma auto --omega 0.7 --json",
      "spectrum --model jonswap --hs 3 --tp 9 --gamma 2 --normalization exact --omega 0.7 --json",
      "spectrum --model tma --wind-speed 12 --fetch 50000 --depth 10 --depth-factor "
      "thompson-vincent --omega 1 --json",
      "spectrum --model tma --hs 2 --tp 8 --depth 10 --gravity 9.80665 --omega 1 --json",
      "spectrum --model phillips --wind-speed 8 --cutoff-length 0.2 --omega 1 --json",
      "spectrum --model jonswap --wind-speed 12 --fetch 50000 --fetch-law cube-root --omega 1 "
      "--json",
  };
  for (const char* args : ok) {
    const CliRun r = run(args);
    EXPECT_EQ(r.exit_code, 0) << args << ": " << r.err;
    EXPECT_GT(nlohmann::json::parse(r.out)["S"][0].get<double>(), 0.0) << args;
  }
}

// WAFO w2k at h = 20: ω = 1, 2 → k = 0.10503601, 0.40774726.
TEST(Cli, DispersionJson) {
  const CliRun r = run("dispersion --depth 20 --omega 1,2 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["k"][0].get<double>(), 0.10503601, 1e-8);
  EXPECT_NEAR(j["k"][1].get<double>(), 0.40774726, 1e-8);
  EXPECT_EQ(j["group_velocity"].size(), 2u);
  const CliRun back = run("dispersion --depth 20 --k 0.01 --json");
  EXPECT_NEAR(nlohmann::json::parse(back.out)["omega"][0].get<double>(), 0.13914927, 1e-8);
}

// WAFO cos-2s, s = 15: D(0) = 1.10168934.
TEST(Cli, SpreadingJson) {
  const CliRun r = run("spreading --model cos2s --s 15 --theta 0,3.14159 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["D"][0].get<double>(), 1.10168934, 1e-8);
  for (const char* args :
       {"spreading --model mitsuyasu --wind-speed 10 --fetch 1e5 --theta 0 --json",
        "spreading --model hasselmann --wind-speed 10 --fetch 1e5 --omega-ratio 2 --theta 0 --json",
        "spreading --model donelan-banner --omega-ratio 1.6 --theta 0 --json",
        "spreading --model power-cosine --alpha 0.3 --theta 0 --json",
        "spreading --model power-cosine --s 2 --symmetric --theta 0 --json"}) {
    const CliRun ok = run(args);
    EXPECT_EQ(ok.exit_code, 0) << args << ": " << ok.err;
  }
}

TEST(Cli, BadInputExitsTwoWithOneLineAndNoStdout) {
  struct Case {
    const char* args;
    const char* mentions;
  };
  const Case cases[] = {
      {"spectrum --model jonswap --wind-speed -3 --fetch 1e4 --omega 1", "--wind-speed = -3"},
      {"spectrum --model pierson-moskowitz --wind-speed nan --omega 1", "--wind-speed = nan"},
      {"spectrum --model jonswap --wind-speed 10 --fetch 0 --omega 1", "--fetch = 0"},
      {"spectrum --model jonswap --wind-speed 10 --omega 1", "--fetch"},
      {"spectrum --model tma --wind-speed 10 --fetch 1e4 --depth 0 --omega 1", "--depth = 0"},
      {"spectrum --model tma --wind-speed 10 --fetch 1e4 --omega 1", "--depth"},
      {"spectrum --model foo --omega 1", "foo"},
      {"spectrum --model jonswap --hs 2 --tp 8 --omega ''", "--omega"},
      {"spectrum --model jonswap --hs 2 --tp 8 --omega 1,,2", "--omega"},
      {"spectrum --model jonswap --hs 2 --tp 8 --omega 1,x", "'x' is not a number"},
      {"spectrum --model jonswap --hs 2 --tp 8 --omega -1", "--omega = -1"},
      {"spectrum --model jonswap --hs 2 --tp 8 --gamma 0.5 --omega 1", "--gamma = 0.5"},
      {"spectrum --model jonswap --hs 2 --tp 8", "--omega"},
      {"spectrum --no-such-flag", "no-such-flag"},
      {"dispersion --depth -1 --k 1", "--depth = -1"},
      {"dispersion --k 1 --omega 1", "exactly one"},
      {"dispersion --gravity 0 --k 1", "--gravity = 0"},
      {"spreading --model cos2s --theta 0", "needs s"},
      {"spreading --model power-cosine --alpha 2 --theta 0", "--alpha = 2"},
      {"spreading --model mitsuyasu --theta 0", "--wind-speed"},
      {"spreading --model donelan-banner", "--theta"},
      {"spreading --model nope --theta 0", "nope"},
      {"", "subcommand"},
  };
  for (const Case& c : cases) ocean_test::expect_usage_error(c.args, c.mentions);
}

TEST(Cli, PlotWritesPngAtomically) {
  // A directory of its own (mkdtemp), so that runs side by side do not share it.
  std::string name = (std::filesystem::temp_directory_path() / "ocean_cli_plot_XXXXXX").string();
  ASSERT_NE(::mkdtemp(name.data()), nullptr);
  const std::filesystem::path dir = name;
  const std::filesystem::path png = dir / "sea.png";
  const CliRun r = run("spectrum --plot " + png.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(png, std::ios::binary);
  char signature[8] = {};
  in.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG");
  // Only the target file is left: no temporaries.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
  // An unwritable destination is a runtime error (exit 1) that leaves nothing behind.
  const CliRun bad = run("spectrum --plot " + (dir / "missing" / "sea.png").string());
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("missing"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
  std::filesystem::remove_all(dir);
}

// `ocean validate --backend cpu` compares the CPU backend's fused SIMD pipeline with its scalar
// reference pipeline (not the backend with itself) and holds it to the CPU bounds.
TEST(Cli, ValidateCpuComparesTheTwoCpuPipelines) {
  const CliRun r = run("validate --backend cpu --json");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["pass"].get<bool>());
  const ocean::conformance::Bounds& bounds = ocean::conformance::kCpuBounds;
  EXPECT_EQ(j["bounds"]["height_rel_hs"].get<double>(), bounds.height_rel_hs);
  EXPECT_EQ(j["bounds"]["displacement_rel_hs"].get<double>(), bounds.displacement_rel_hs);
  EXPECT_EQ(j["bounds"]["foam"].get<double>(), bounds.foam);
  EXPECT_EQ(j["cases"].size(), ocean::conformance::cases().size());
  // Two computations that round differently: errors above zero, within the bounds.
  const double max_error = j["max_error_rel_hs"].get<double>();
  EXPECT_GT(max_error, 0.0);
  EXPECT_LE(max_error, bounds.displacement_rel_hs);
  EXPECT_GT(j["errors"]["normal"].get<double>(), 0.0);
  EXPECT_LE(j["errors"]["normal"].get<double>(), bounds.normal);
}

TEST(Cli, HelpExitsZero) {
  const CliRun r = run("spectrum --help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("--wind-speed"), std::string::npos);
}

}  // namespace
