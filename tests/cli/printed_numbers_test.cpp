// Numbers the tool prints are numbers: `ocean dispersion` and `ocean spectrum` at extreme but
// valid inputs print finite values (never nan, inf or a JSON null), and values outside the
// dispersion's domain or a loop period that would freeze the sea are one-line usage errors.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/cli_run.hpp"

namespace {

using ocean_test::CliRun;
using ocean_test::expect_usage_error;
const auto run_printed = ocean_test::run_cli;

// Every number in a JSON document is finite, and nothing is null (how JSON writes nan and inf).
void expect_finite(const nlohmann::json& j, const std::string& where) {
  if (j.is_array() || j.is_object()) {
    for (const auto& item : j) expect_finite(item, where);
  } else {
    EXPECT_FALSE(j.is_null()) << where;
    if (j.is_number()) {
      EXPECT_TRUE(std::isfinite(j.get<double>())) << where;
    }
  }
}

void expect_no_nan_or_inf(const std::string& text, const std::string& where) {
  for (const char* word : {"nan", "inf", "NaN", "Inf", "null"}) {
    EXPECT_EQ(text.find(word), std::string::npos) << where << " printed " << word << ":\n" << text;
  }
}

const char* const kDispersionRuns[] = {
    "--k 1e-200,1e-100,1,1e100,1e200",
    "--capillary --k 1e-200,1e-100,1,1e100,1e200",
    "--capillary --depth 1e-100 --k 1e-200,1e-100,1,1e100,1e200",
    "--depth 1e300 --gravity 0.1 --k 1e-200,1e200",
    "--capillary --omega 1e-20,1e20,1e100",
    "--depth 1e-100 --omega 1e-200,1e-100,1e-60",
};

TEST(CliPrintedNumbers, DispersionAtTheEndsOfItsDomainPrintsFiniteNumbers) {
  for (const char* args : kDispersionRuns) {
    const CliRun json = run_printed(std::string("dispersion --json ") + args);
    ASSERT_EQ(json.exit_code, 0) << args << ": " << json.err;
    expect_finite(nlohmann::json::parse(json.out), args);
    const CliRun table = run_printed(std::string("dispersion ") + args);
    ASSERT_EQ(table.exit_code, 0) << args << ": " << table.err;
    expect_no_nan_or_inf(table.out, args);
  }
}

// ω = 1e20 rad/s in sea water is a capillary wave, ω² = T·k³ to 1e-25 (Lamb 1932, §267).
TEST(CliPrintedNumbers, CapillaryInverseIsConvergedFarOut) {
  const CliRun r = run_printed("dispersion --capillary --omega 1e20 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double k = std::cbrt(1e40 / (0.0728 / 1025.0));
  EXPECT_NEAR(j["k"][0].get<double>(), k, 1e-14 * k);
}

TEST(CliPrintedNumbers, DispersionRefusesValuesOutsideItsDomain) {
  expect_usage_error("dispersion --k 1e308",
                     "--k = 1e+308 is out of range: must be in [1e-200, 1e+200]");
  expect_usage_error("dispersion --k 1,0", "--k = 0 is out of range: must be in [1e-200, 1e+200]");
  expect_usage_error("dispersion --k 5e-324", "--k = 5e-324 is out of range");
  expect_usage_error("dispersion --omega 1e-300", "--omega = 1e-300 is out of range: must be in [");
  expect_usage_error("dispersion --capillary --omega 1e301", "--omega = 1e+301 is out of range");
  expect_usage_error("dispersion --depth 1e-300 --k 1", "--depth = 1e-300 is out of range");
  expect_usage_error("dispersion --gravity 1e300 --k 1", "--gravity = 1e+300 is out of range");
}

TEST(CliPrintedNumbers, SpectrumAtExtremeFrequenciesIsZeroNotNan) {
  const std::string omega = " --omega 4.9406564584124654e-324,1e-300,1e300,1.7976931348623157e308";
  for (const char* sea :
       {"--model pierson-moskowitz --hs 2 --tp 8", "--model pierson-moskowitz --wind-speed 15",
        "--model jonswap --wind-speed 100 --fetch 1e8 --gravity 0.1",
        "--model tma --hs 2 --tp 8 --depth 1e-100",
        "--model tma --hs 2 --tp 8 --depth 1e300 --depth-factor thompson-vincent",
        "--model phillips --wind-speed 100 --phillips-amplitude 1e6",
        "--model phillips --wind-speed 10 --cutoff-length 0.5"}) {
    const CliRun json = run_printed(std::string("spectrum --json ") + sea + omega);
    ASSERT_EQ(json.exit_code, 0) << sea << ": " << json.err;
    const auto j = nlohmann::json::parse(json.out);
    expect_finite(j, sea);
    for (const auto& s : j["S"]) EXPECT_EQ(s.get<double>(), 0.0) << sea;
    const CliRun table = run_printed(std::string("spectrum ") + sea + omega);
    ASSERT_EQ(table.exit_code, 0) << sea << ": " << table.err;
    expect_no_nan_or_inf(table.out, sea);
  }
}

// A 50 m patch in deep water: its longest wave has ω = √(g·2π/50) = 1.11 rad/s and stands still
// for a loop period below 2π/ω = 5.659 s. The flag that sets the loop period gets one line.
TEST(CliPrintedNumbers, LoopPeriodThatFreezesTheSeaIsAUsageError) {
  for (const char* command : {"stats --seeds 1", "bake --frames 1 --out /nonexistent/never"}) {
    expect_usage_error(std::string(command) + " --resolution 16 --cascades 50 --loop-period 5",
                       "loop_period_s = 5 is too short: the longest waves (50 m) would stand "
                       "still; must be 0 (no loop) or in [5.659");
  }
}

}  // namespace
