// `ocean bench`: the JSON rows carry the documented fields with consistent values, the row
// selection flags select, and bad input is one clear line with exit 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "cli/cli_run.hpp"

namespace {

TEST(BenchCli, JsonRowsHaveTheDocumentedFields) {
  const ocean_test::CliRun r =
      ocean_test::run_cli("bench --json --resolution 16,32 --cascades 2 --threads 1 --min-time 0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["machine"]["fma_peak_gflops_per_thread"].get<double>(), 0.0);
  EXPECT_FALSE(j["machine"]["simd_target"].get<std::string>().empty());
  EXPECT_GT(j["machine"]["copy_bandwidth_gbps"].get<double>(), 0.0);
  EXPECT_GT(j["machine"]["copy_bandwidth_16mib_gbps"].get<double>(), 0.0);
  const auto& rows = j["rows"];
  ASSERT_EQ(rows.size(), 2u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& row = rows[i];
    EXPECT_EQ(row["resolution"].get<int>(), i == 0 ? 16 : 32);
    EXPECT_EQ(row["cascades"].get<int>(), 2);
    EXPECT_EQ(row["threads"].get<int>(), 1);
    EXPECT_EQ(row["outputs"].get<std::string>(), "all");
    const double ours = row["ours_ms"].get<double>();
    EXPECT_GT(ours, 0.0);
    EXPECT_LE(row["ours_min_ms"].get<double>(), ours);
    EXPECT_GE(row["ours_max_ms"].get<double>(), ours);
    EXPECT_GT(row["ours_fft_only_ms"].get<double>(), 0.0);
    // FFTW is installed wherever the tests build (libfftw3-dev): the baseline columns are set
    // and the ratio is what it says.
    const double fftw = row["fftw_pipeline_ms"].get<double>();
    EXPECT_GT(fftw, 0.0);
    EXPECT_GT(row["fftw_fft_only_ms"].get<double>(), 0.0);
    EXPECT_DOUBLE_EQ(row["ratio"].get<double>(), ours / fftw);
    EXPECT_GT(row["memory_per_cascade_bytes"].get<double>(), 16.0 * 16.0 * 40.0);
    for (const char* stage : {"synthesis", "finalize", "mips"})
      EXPECT_GE(row["ours_stages_ms"][stage].get<double>(), 0.0) << stage;
  }
}

// The texture set a renderer needs (--outputs textures): the same rows without the float normal,
// Jacobian and foam arrays (20 bytes per texel less memory per cascade).
TEST(BenchCli, TextureOutputsLeaveOutTheOptionalArrays) {
  const std::string flags = "bench --json --resolution 16 --cascades 1 --threads 1 --min-time 0";
  const ocean_test::CliRun all = ocean_test::run_cli(flags);
  const ocean_test::CliRun lean = ocean_test::run_cli(flags + " --outputs textures");
  ASSERT_EQ(all.exit_code, 0) << all.err;
  ASSERT_EQ(lean.exit_code, 0) << lean.err;
  const auto row_of = [](const std::string& out) { return nlohmann::json::parse(out)["rows"][0]; };
  const nlohmann::json a = row_of(all.out), b = row_of(lean.out);
  EXPECT_EQ(b["outputs"].get<std::string>(), "textures");
  EXPECT_EQ(
      a["memory_per_cascade_bytes"].get<double>() - b["memory_per_cascade_bytes"].get<double>(),
      16.0 * 16.0 * 20.0);
  EXPECT_GT(b["ours_ms"].get<double>(), 0.0);
  EXPECT_GT(b["fftw_pipeline_ms"].get<double>(), 0.0);
}

// --frame-interval paces the timed frames as a frame loop would; the rows say so and still carry
// consistent figures. (How long a frame takes is the benchmark's to measure, not a test's.)
// Paced rows also time the same pipeline back to back in alternated rounds (the ratio's
// baseline), for each runner asked for.
TEST(BenchCli, FrameIntervalPacesTheFrames) {
  const ocean_test::CliRun r = ocean_test::run_cli(
      "bench --json --resolution 16 --cascades 1 --threads 2 --min-time 0 --frame-interval 20 "
      "--runner tbb,ready");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json rows = nlohmann::json::parse(r.out)["rows"];
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0]["runner"], "tbb");
  EXPECT_EQ(rows[1]["runner"], "ready");
  for (const nlohmann::json& row : rows) {
    EXPECT_EQ(row["frame_interval_ms"].get<double>(), 20.0);
    EXPECT_GE(row["frames"].get<int>(), 5 * 6);  // at least 5 frames in each of the 6 rounds
    const double ours = row["ours_ms"].get<double>();
    EXPECT_TRUE(std::isfinite(ours));
    EXPECT_GT(ours, 0.0);
    EXPECT_LE(row["ours_min_ms"].get<double>(), ours);
    EXPECT_GE(row["ours_max_ms"].get<double>(), ours);
    const double back_to_back = row["back_to_back_ms"].get<double>();
    EXPECT_GT(back_to_back, 0.0);
    EXPECT_DOUBLE_EQ(row["paced_ratio"].get<double>(), ours / back_to_back);
  }
  const ocean_test::CliRun unpaced =
      ocean_test::run_cli("bench --json --resolution 16 --cascades 1 --threads 1 --min-time 0");
  ASSERT_EQ(unpaced.exit_code, 0) << unpaced.err;
  EXPECT_EQ(nlohmann::json::parse(unpaced.out)["rows"][0]["frame_interval_ms"].get<double>(), 0.0);
  EXPECT_FALSE(nlohmann::json::parse(unpaced.out)["rows"][0].contains("back_to_back_ms"));
}

// --pacing: one row per period, thread count and runner; 90 and 120 Hz unless --frame-interval
// gives one; paced without and with the cache warm-up, each ratio the medians' and the rounds'
// spread bracketing their median.
TEST(BenchCli, PacingRowsGiveTheRatioAndItsSpread) {
  const ocean_test::CliRun r = ocean_test::run_cli(
      "bench --pacing --json --resolution 16 --cascades 1 --threads 1,2 --min-time 0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json out = nlohmann::json::parse(r.out);
  EXPECT_EQ(out["resolution"], 16);
  EXPECT_EQ(out["cascades"], 1);
  const int rounds = out["rounds"].get<int>();
  EXPECT_GE(rounds, 2);
  const nlohmann::json rows = out["rows"];
  ASSERT_EQ(rows.size(), 4u);  // 2 periods × 2 thread counts × the ready runner
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const nlohmann::json& row = rows[i];
    EXPECT_NEAR(row["frame_interval_ms"].get<double>(), i < 2 ? 1000.0 / 90 : 1000.0 / 120, 1e-9);
    EXPECT_EQ(row["threads"], i % 2 ? 2 : 1);
    EXPECT_EQ(row["runner"], "ready");
    const double paced = row["paced_ms"].get<double>(), b2b = row["back_to_back_ms"].get<double>();
    EXPECT_GT(paced, 0.0);
    EXPECT_GT(b2b, 0.0);
    EXPECT_DOUBLE_EQ(row["paced_ratio"].get<double>(), paced / b2b);
    EXPECT_LE(row["round_ratio_min"].get<double>(), row["round_ratio_median"].get<double>());
    EXPECT_LE(row["round_ratio_median"].get<double>(), row["round_ratio_max"].get<double>());
    EXPECT_GE(row["paced_frames"].get<int>(), 5 * rounds);
    EXPECT_GE(row["back_to_back_frames"].get<int>(), 5 * rounds);
    const double warmed = row["warmed_ms"].get<double>();
    EXPECT_GT(warmed, 0.0);
    EXPECT_DOUBLE_EQ(row["warmed_ratio"].get<double>(), warmed / b2b);
    EXPECT_LE(row["warmed_round_ratio_min"].get<double>(),
              row["warmed_round_ratio_median"].get<double>());
    EXPECT_LE(row["warmed_round_ratio_median"].get<double>(),
              row["warmed_round_ratio_max"].get<double>());
    EXPECT_GE(row["warmed_frames"].get<int>(), 5 * rounds);
    EXPECT_GT(row["warm_up_ms"].get<double>(), 0.0);
    for (const char* kind : {"paced_stages", "warmed_stages", "back_to_back_stages"})
      EXPECT_GT(row[kind]["synthesis_ms"].get<double>(), 0.0) << kind;
  }
  const ocean_test::CliRun one = ocean_test::run_cli(
      "bench --pacing --resolution 16 --cascades 1 --threads 1 --min-time 0 --frame-interval 4 "
      "--runner tbb");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_NE(one.out.find("(rounds' median [min, max])"), std::string::npos) << one.out;
  EXPECT_NE(one.out.find("   4.00  250    1    tbb"), std::string::npos) << one.out;
  EXPECT_NE(one.out.find("stages (synthesis, surface, mips; ms)"), std::string::npos) << one.out;
  for (const char* bad : {"bench --pacing --backend vulkan", "bench --pacing --overlap",
                          "bench --pacing --frame-interval 0"}) {
    const ocean_test::CliRun e = ocean_test::run_cli(bad);
    EXPECT_EQ(e.exit_code, 2) << bad;
    EXPECT_NE(e.err.find("--pacing"), std::string::npos) << bad << ": " << e.err;
    EXPECT_EQ(std::count(e.err.begin(), e.err.end(), '\n'), 1) << bad << ": " << e.err;
  }
}

TEST(BenchCli, TableForPeople) {
  const ocean_test::CliRun r =
      ocean_test::run_cli("bench --resolution 16 --cascades 1 --threads 1 --min-time 0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("fftw-pipe"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("FMA peak"), std::string::npos) << r.out;
}

// --overlap: the cascades alone, the noise map alone and both, per backend (the CPU always; Vulkan
// and CUDA where a device exists), and the overlap is the stated formula of the three times;
// without a CUDA row the JSON says why ("no CUDA device: ...", or a build without CUDA).
TEST(BenchCli, OverlapRowsFollowTheirDefinition) {
  const ocean_test::VulkanChildren vulkan;  // the Vulkan rows
  const ocean_test::CliRun r = ocean_test::run_cli(
      "bench --overlap --json --resolution 16 --cascades 1 --far-noise-resolution 16 --min-time 0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_NE(j["definition"].get<std::string>().find("min(cascades_ms, noise_ms)"),
            std::string::npos);
  const auto& rows = j["rows"];
  ASSERT_GE(rows.size(), 1u);
  EXPECT_EQ(rows[0]["backend"].get<std::string>(), "cpu");
  for (const auto& row : rows) {
    EXPECT_EQ(row["resolution"].get<int>(), 16);
    EXPECT_EQ(row["noise_resolution"].get<int>(), 16);
    const double c = row["cascades_ms"].get<double>(), n = row["noise_ms"].get<double>(),
                 b = row["both_ms"].get<double>();
    EXPECT_GT(c, 0.0);
    EXPECT_GT(n, 0.0);
    EXPECT_GT(b, 0.0);
    EXPECT_DOUBLE_EQ(row["sum_ms"].get<double>(), c + n);
    EXPECT_DOUBLE_EQ(row["overlap"].get<double>(), (c + n - b) / std::min(c, n));
  }
  const bool cuda_row = std::any_of(rows.begin(), rows.end(), [](const nlohmann::json& row) {
    return row["backend"].get<std::string>() == "cuda";
  });
  EXPECT_NE(cuda_row, j.contains("cuda_note")) << r.out;
  if (!cuda_row) {
    const std::string note = j["cuda_note"].get<std::string>();
    EXPECT_TRUE(note.starts_with("no CUDA device: ") || note == "built without CUDA") << note;
  }
}

TEST(BenchCli, BadInputIsOneLineAndExitTwo) {
  ocean_test::expect_usage_error("bench --resolution 100", "not a power of two");
  ocean_test::expect_usage_error("bench --resolution 4096", "--resolution");
  ocean_test::expect_usage_error("bench --cascades 5", "--cascades");
  ocean_test::expect_usage_error("bench --threads 0", "--threads");
  ocean_test::expect_usage_error("bench --threads nan", "--threads");
  ocean_test::expect_usage_error("bench --min-time -1", "--min-time");
  ocean_test::expect_usage_error("bench --outputs some", "--outputs");
  ocean_test::expect_usage_error("bench --runner fast", "--runner");
  ocean_test::expect_usage_error("bench --runner ''", "--runner is empty");
  ocean_test::expect_usage_error("bench --frame-interval -1", "--frame-interval");
  ocean_test::expect_usage_error("bench --frame-interval nan", "--frame-interval");
  ocean_test::expect_usage_error("bench --frame-interval 5000", "--frame-interval");
  ocean_test::expect_usage_error("bench --backend vulkan --frame-interval 2", "--frame-interval");
  ocean_test::expect_usage_error("bench --overlap --far-noise-resolution 8",
                                 "--far-noise-resolution");
  ocean_test::expect_usage_error("bench --overlap --backend vulkan", "--overlap");
  ocean_test::expect_usage_error("bench --overlap --table-one", "--overlap");
}

}  // namespace
