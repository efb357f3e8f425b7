// The Vulkan backend from the command line: `ocean info` lists it and its devices, `ocean
// validate --backend vulkan --json` passes, and `ocean bake --backend vulkan` writes .npy files
// that agree with `--backend cpu` within the conformance bounds (ocean/conformance.hpp: the CPU
// and the device bounds together; packed maps within 1 LSB). Skips where no Vulkan device
// exists, or fails there with OCEAN_REQUIRE_DEVICES=1.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/cli_run.hpp"
#include "ocean/backends.hpp"
#include "ocean/conformance.hpp"
#include "support/npy_reader.hpp"
#include "support/require_devices.hpp"

namespace {

namespace fs = std::filesystem;

bool vulkan_available(std::string* why) {
  for (const ocean::BackendInfo& b : ocean::list_backends()) {
    if (b.name == "vulkan") {
      *why = b.detail;
      return b.available;
    }
  }
  return false;
}

TEST(VulkanCli, InfoListsBackendsAndDevices) {
  const ocean_test::CliRun r = ocean_test::run_cli("info --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  bool listed = false;
  for (const auto& b : j["backends"]) listed = listed || b["name"] == "vulkan";
  EXPECT_TRUE(listed);
  std::string why;
  if (vulkan_available(&why)) {
    EXPECT_FALSE(j["vulkan"]["devices"].empty());
  }
}

TEST(VulkanCli, ValidatePassesAndReportsTheError) {
  std::string why;
  if (!vulkan_available(&why)) {
    const ocean_test::CliRun r = ocean_test::run_cli("validate --backend vulkan --json");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_TRUE(r.out.empty());
    EXPECT_NE(r.err.find("vulkan"), std::string::npos) << r.err;
    OCEAN_SKIP_OR_FAIL("vulkan unavailable: " + why);
  }
  const ocean_test::CliRun r = ocean_test::run_cli("validate --backend vulkan --json");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["pass"].get<bool>());
  EXPECT_FALSE(j["device"].get<std::string>().empty());
  // The Vulkan backend is held to the device bounds, and the JSON says which.
  const ocean::conformance::Bounds& bounds = ocean::conformance::kDeviceBounds;
  EXPECT_EQ(j["bounds"]["displacement_rel_hs"].get<double>(), bounds.displacement_rel_hs);
  EXPECT_EQ(j["bounds"]["normal"].get<double>(), bounds.normal);
  EXPECT_LE(j["max_error_rel_hs"].get<double>(), bounds.displacement_rel_hs);
  EXPECT_LE(j["errors"]["height_rel_hs"].get<double>(), bounds.height_rel_hs);
}

// `ocean bench --table-one`: VR-GIS FFT+Perlin's Table I measured here — one row per size with
// both backends' times and their ratio, and the source's printed figures beside the sizes it
// has (its 128² row: 31.68 and 4.01 ms). Which backend is faster is the benchmark's to say.
TEST(VulkanCli, BenchTableOneHasBothBackendsAndTheSourceRow) {
  std::string why;
  if (!vulkan_available(&why)) OCEAN_SKIP_OR_FAIL("vulkan unavailable: " + why);
  const ocean_test::CliRun r =
      ocean_test::run_cli("bench --table-one --json --resolution 16,128 --min-time 0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["device"].get<std::string>().empty());
  ASSERT_EQ(j["rows"].size(), 2u);
  for (const auto& row : j["rows"]) {
    const double cpu = row["cpu_ms"].get<double>(), gpu = row["gpu_ms"].get<double>();
    EXPECT_GT(cpu, 0.0);
    EXPECT_GT(gpu, 0.0);
    EXPECT_DOUBLE_EQ(row["cpu_over_gpu"].get<double>(), cpu / gpu);
    EXPECT_EQ(row["cascades"].get<int>(), 1);
  }
  EXPECT_FALSE(j["rows"][0].contains("source_ratio"));
  EXPECT_EQ(j["rows"][1]["source_cpu_ms"].get<double>(), 31.68);
  EXPECT_EQ(j["rows"][1]["source_gpu_ms"].get<double>(), 4.01);
  ocean_test::expect_usage_error("bench --table-one --backend vulkan", "--table-one");
  ocean_test::expect_usage_error("bench --table-one --frame-interval 5", "--table-one");
}

TEST(VulkanCli, BakeAgreesWithTheCpuBackend) {
  std::string why;
  if (!vulkan_available(&why)) OCEAN_SKIP_OR_FAIL("vulkan unavailable: " + why);
  const fs::path root = fs::temp_directory_path() / ("vulkan_bake_" + std::to_string(::getpid()));
  fs::remove_all(root);
  const std::string flags =
      "bake --wind-speed 12 --fetch 40000 --resolution 64 --cascades 300,70 --seed 5 "
      "--frames 3 --fps 10 --time 2 --set choppiness=1.1 --out ";
  for (const char* backend : {"cpu", "vulkan"}) {
    const ocean_test::CliRun r =
        ocean_test::run_cli(flags + (root / backend).string() + " --backend " + backend);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(root / "cpu")) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".npy") continue;
    const auto a = ocean::io::read_npy(entry.path());
    const auto b = ocean::io::read_npy(root / "vulkan" / name);
    ASSERT_TRUE(a.ok() && b.ok()) << name;
    ASSERT_EQ(a.value().shape, b.value().shape) << name;
    const std::vector<float>& x = a.value().data;
    const std::vector<float>& y = b.value().data;
    double max_diff = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i)
      max_diff = std::max(max_diff, std::abs(static_cast<double>(x[i]) - y[i]));
    // Both backends are within their bounds of the scalar reference pipeline: of each other,
    // within the sum.
    const auto sum = [](double ocean::conformance::Bounds::*field) {
      return ocean::conformance::kCpuBounds.*field + ocean::conformance::kDeviceBounds.*field;
    };
    const auto starts = [&](const char* prefix) { return name.rfind(prefix, 0) == 0; };
    double bound = 0.0;
    if (starts("nfs_")) bound = 1.0 / 255 + 1e-6;  // 1 LSB of the RGBA8 map
    if (starts("normal_")) bound = sum(&ocean::conformance::Bounds::normal);
    if (starts("jacobian_")) bound = sum(&ocean::conformance::Bounds::jacobian);
    if (starts("foam_")) bound = sum(&ocean::conformance::Bounds::foam);
    if (starts("displacement_")) {
      // Hs of this cascade alone, 4·σ of the height (the y of each texel): no more than the
      // frame's Hs, which the bound is relative to.
      double sum_h = 0.0, sum_h2 = 0.0;
      for (std::size_t i = 1; i < x.size(); i += 3)
        sum_h += x[i], sum_h2 += static_cast<double>(x[i]) * x[i];
      const double texels = static_cast<double>(x.size() / 3);
      const double hs = 4.0 * std::sqrt(sum_h2 / texels - (sum_h / texels) * (sum_h / texels));
      bound = sum(&ocean::conformance::Bounds::displacement_rel_hs) * hs;
    }
    ASSERT_GT(bound, 0.0) << name;
    EXPECT_LE(max_diff, bound) << name;
    ++compared;
  }
  EXPECT_GT(compared, 20);
  fs::remove_all(root);
}

}  // namespace

namespace {

// `ocean bench --backend vulkan` reports every GPU stage from timestamp queries.
TEST(VulkanCli, BenchReportsGpuStages) {
  std::string why;
  if (!vulkan_available(&why)) OCEAN_SKIP_OR_FAIL("vulkan unavailable: " + why);
  const ocean_test::CliRun r =
      ocean_test::run_cli("bench --backend vulkan --json --resolution 32 --cascades 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["rows"].size(), 1u);
  const auto& row = j["rows"][0];
  EXPECT_EQ(row["resolution"].get<int>(), 32);
  EXPECT_EQ(row["cascades"].get<int>(), 2);
  double sum = 0.0;
  for (const char* stage : {"evolve_fft_rows", "fft_columns", "finalize", "mips", "readback"}) {
    const double ms = row["gpu_stages_ms"][stage].get<double>();
    EXPECT_GT(ms, 0.0) << stage;
    sum += ms;
  }
  // The stages are differences of consecutive timestamps and the total the first to the last:
  // their sum is the total but for rounding (an identity, not a timing).
  EXPECT_NEAR(sum, row["gpu_total_ms"].get<double>(), 1e-9 * sum);
  EXPECT_EQ(row["outputs"].get<std::string>(), "all");
  // The texture set a renderer needs: the optional arrays are not read back, every stage still
  // reported.
  const ocean_test::CliRun lean = ocean_test::run_cli(
      "bench --backend vulkan --json --resolution 32 --cascades 2 --outputs textures");
  ASSERT_EQ(lean.exit_code, 0) << lean.err;
  const nlohmann::json lean_json = nlohmann::json::parse(lean.out);
  const auto& lean_row = lean_json["rows"][0];
  EXPECT_EQ(lean_row["outputs"].get<std::string>(), "textures");
  EXPECT_GT(lean_row["gpu_stages_ms"]["readback"].get<double>(), 0.0);
}

}  // namespace
