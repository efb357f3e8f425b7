// `ocean xr` against the project's test OpenXR runtime (tests/xr/runtime): the runtime checks
// every frame it receives (two views at the predicted display time, posed as located, each a
// swapchain image released during the frame and not black) and writes what it found to a JSON
// report; the tool prints the display times it was given and the simulation times it used.
// Without a runtime the tool says so in one line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/cli_run.hpp"
#include "ocean/vk.hpp"
#include "support/require_devices.hpp"

namespace {

using ocean_test::run_cli_argv;
using ocean_test::ScratchDir;

constexpr std::int64_t kPeriod_ns = 11'111'111;  // the test runtime's 90 Hz

void run_frames(bool validation) {
  if (!ocean::vk::list_devices().ok()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  ScratchDir dir("ocean_xr_test");
  const std::string report = (dir.path / "report.json").string();
  const std::filesystem::path messages = dir.path / "validation.txt";
  std::vector<std::string> args = {"xr", "--frames", "5", "--quality", "low", "--json"};
  if (validation) args.push_back("--validation");
  const ocean_test::CliRun r =
      run_cli_argv(args, {},
                   {std::string("XR_RUNTIME_JSON=") + OCEAN_TEST_XR_RUNTIME_JSON,
                    "OCEAN_TEST_XR_REPORT=" + report,
                    "XR_CORE_VALIDATION_FILE_NAME=" + messages.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // No loader or tool message; the OpenXR validation layer announces itself once (so it ran)
  // and writes its findings to the file, which it creates at the first one.
  EXPECT_EQ(r.err, validation ? "Core Validation output type: text, first time = true\n" : "");
  EXPECT_FALSE(std::filesystem::exists(messages)) << "the OpenXR validation layer reported";

  std::ifstream in(report);
  ASSERT_TRUE(in.good()) << "the runtime wrote no report";
  const nlohmann::json seen = nlohmann::json::parse(in);
  EXPECT_EQ(seen["problems"], nlohmann::json::array()) << seen.dump();
  EXPECT_EQ(seen["frames"], 5);
  EXPECT_EQ(seen["views"], 10);  // two per frame
  EXPECT_EQ(seen["images_checked"], 10);
  EXPECT_EQ(seen["images_lit"], 10);  // more than half of each eye's pixels not black

  const nlohmann::json out = nlohmann::json::parse(r.out);
  EXPECT_EQ(out["runtime"], "ocean test runtime");
  EXPECT_EQ(out["frames"], 5);
  const auto display = out["display_times_ns"].get<std::vector<std::int64_t>>();
  const auto simulated = out["simulation_times_s"].get<std::vector<double>>();
  ASSERT_EQ(display.size(), 5u);
  ASSERT_EQ(simulated.size(), 5u);
  for (std::size_t i = 0; i < display.size(); ++i) {
    // Display times are whole periods apart (frames may be skipped, never half-displayed), and
    // the simulation time is the display time since the first frame.
    if (i > 0) {
      EXPECT_GT(display[i], display[i - 1]);
      EXPECT_EQ((display[i] - display[i - 1]) % kPeriod_ns, 0);
    }
    EXPECT_DOUBLE_EQ(simulated[i], double(display[i] - display[0]) * 1e-9);
  }
}

TEST(XrCli, RunsFramesAgainstTheTestRuntime) { run_frames(false); }

TEST(XrCli, RunsFramesUnderTheValidationLayers) { run_frames(true); }

TEST(XrCli, NoRuntimeIsOneLineAndAFailure) {
  ScratchDir dir("ocean_xr_none");
  const ocean_test::CliRun r = run_cli_argv(
      {"xr", "--frames", "1"}, {}, {"XR_RUNTIME_JSON=" + (dir.path / "absent.json").string()});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(ocean_test::line_count(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("ocean: error: no OpenXR runtime", 0), 0u) << r.err;
}

TEST(XrCli, BadFlagsAreOneLine) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"xr", "--frames", "-1"},
        std::vector<std::string>{"xr", "--eye-height", "nan"},
        std::vector<std::string>{"xr", "--frames", "2.5"}}) {
    const ocean_test::CliRun r = run_cli_argv(args);
    EXPECT_EQ(r.exit_code, 2) << args[2];
    EXPECT_EQ(ocean_test::line_count(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("ocean: error: " + args[1], 0), 0u) << r.err;
  }
}

}  // namespace
