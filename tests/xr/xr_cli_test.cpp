// `ocean xr` against the project's test OpenXR runtime (tests/xr/runtime): the runtime checks
// every frame it receives (two views at the predicted display time, posed as located, each a
// swapchain image released during the frame and not black) and writes what it found to a JSON
// report; the tool prints the display times it was given and the simulation times it used.
// Without a runtime the tool says so in one line. The runtime's head is rolled and its eyes have
// asymmetric fields of view: the horizon measured in the eye images it received is tilted by the
// roll and lies where the views' own projections put it (docs/vr.md V.1–V.2), both eyes in one
// multiview pass and as two renders.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/cli_run.hpp"
#include "ocean/vk.hpp"
#include "support/png_reader.hpp"
#include "support/require_devices.hpp"

namespace {

using ocean_test::run_cli_argv;
using ocean_test::ScratchDir;

constexpr std::int64_t kPeriod_ns = 11'111'111;  // the test runtime's 90 Hz

void run_frames(bool validation, bool taa = false) {
  if (!ocean::vk::list_devices().ok()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  ScratchDir dir("ocean_xr_test");
  const std::string report = (dir.path / "report.json").string();
  const std::filesystem::path messages = dir.path / "validation.txt";
  std::vector<std::string> args = {"xr", "--frames", "5", "--quality", "low", "--json"};
  if (validation) args.push_back("--validation");
  if (taa) args.push_back("--taa");
  const ocean_test::CliRun r = run_cli_argv(
      args, {},
      {std::string("XR_RUNTIME_JSON=") + OCEAN_TEST_XR_RUNTIME_JSON,
       "OCEAN_TEST_XR_REPORT=" + report, "XR_CORE_VALIDATION_FILE_NAME=" + messages.string()});
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

// --taa (docs/rendering.md R.61): each eye jittered, its motion drawn in the multiview pass and
// blended into its own half of the history, with both validation layers silent; a render per
// eye (--no-multiview) would share one history between the eyes and is refused in one line.
TEST(XrCli, RunsFramesWithTemporalAntiAliasingUnderTheValidationLayers) {
  run_frames(true, true);
  if (!ocean::vk::list_devices().ok()) return;
  const ocean_test::CliRun r =
      run_cli_argv({"xr", "--taa", "--no-multiview", "--frames", "1"}, {},
                   {std::string("XR_RUNTIME_JSON=") + OCEAN_TEST_XR_RUNTIME_JSON});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--taa: draws both eyes in one multiview pass"), std::string::npos)
      << r.err;
}

// The horizon of one eye image, in the view's tangent coordinates (a, b): the direction
// (a, b, −1) of view space. The horizon is the brightest line of a column: the sky brightens
// down to it (the haze), and the sea's reflection, Fresnel's near 1 at grazing, darkens away
// below it. So per column the first row from the top below which the brightness falls; the
// horizon crosses that row, taken at its centre (±½ row). Columns whose row lies within 3 rows
// of the top or bottom are left out.
struct HorizonFit {
  double slope = 0.0;      // db/da
  double intercept = 0.0;  // b at a = 0
  double rms_rows = 0.0;   // residual, rows
  int columns = 0;
};
HorizonFit fit_horizon(const ocean::io::PngImage& img, const std::array<double, 4>& fov) {
  const double tl = std::tan(fov[0]), tr = std::tan(fov[1]);
  const double tu = std::tan(fov[2]), td = std::tan(fov[3]);
  const int w = img.width, h = img.height, ch = img.channels;
  const auto luma = [&](int x, int y) {
    const std::size_t i = static_cast<std::size_t>((y * w + x) * ch);
    return 0.2126 * img.samples[i] + 0.7152 * img.samples[i + 1] + 0.0722 * img.samples[i + 2];
  };
  std::vector<double> as, bs;
  for (int x = 0; x < w; ++x) {
    int peak = 0;
    while (peak + 1 < h && luma(x, peak + 1) >= luma(x, peak)) ++peak;
    if (peak < 3 || peak > h - 4) continue;
    // Pixel centres: column x at tangent tl + (x + ½)/w·(tr − tl); rows from the top (OpenXR's
    // image: up at the top row), row y spanning [y, y + 1).
    const double row = peak + 0.5;
    as.push_back(tl + (x + 0.5) / w * (tr - tl));
    bs.push_back(tu - row / h * (tu - td));
  }
  HorizonFit f;
  f.columns = static_cast<int>(as.size());
  if (f.columns < 2) return f;
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < as.size(); ++i) ma += as[i], mb += bs[i];
  ma /= double(as.size()), mb /= double(as.size());
  double sab = 0, saa = 0;
  for (std::size_t i = 0; i < as.size(); ++i)
    sab += (as[i] - ma) * (bs[i] - mb), saa += (as[i] - ma) * (as[i] - ma);
  f.slope = sab / saa;
  f.intercept = mb - f.slope * ma;
  double r2 = 0;
  for (std::size_t i = 0; i < as.size(); ++i) {
    const double r = (bs[i] - (f.intercept + f.slope * as[i])) / (tu - td) * h;
    r2 += r * r;
  }
  f.rms_rows = std::sqrt(r2 / double(as.size()));
  return f;
}

void check_horizon(bool multiview) {
  if (!ocean::vk::list_devices().ok()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  ScratchDir dir("ocean_xr_horizon");
  const std::string report = (dir.path / "report.json").string();
  std::vector<std::string> args = {"xr", "--frames", "2", "--quality", "low", "--json"};
  if (!multiview) args.push_back("--no-multiview");
  const ocean_test::CliRun r =
      run_cli_argv(args, {},
                   {std::string("XR_RUNTIME_JSON=") + OCEAN_TEST_XR_RUNTIME_JSON,
                    "OCEAN_TEST_XR_REPORT=" + report, "OCEAN_TEST_XR_IMAGES=" + dir.path.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json out = nlohmann::json::parse(r.out);
  if (multiview && !out["multiview"].get<bool>()) GTEST_SKIP() << "the device lacks multiview";
  EXPECT_EQ(out["multiview"].get<bool>(), multiview);
  std::ifstream in(report);
  ASSERT_TRUE(in.good()) << "the runtime wrote no report";
  const nlohmann::json seen = nlohmann::json::parse(in);
  EXPECT_EQ(seen["problems"], nlohmann::json::array()) << seen.dump();
  ASSERT_TRUE(seen.contains("saved_views")) << seen.dump();
  for (int eye = 0; eye < 2; ++eye) {
    const nlohmann::json& v = seen["saved_views"][eye];
    const auto q = v["orientation"].get<std::array<double, 4>>();  // x, y, z, w
    const auto fov = v["fov"].get<std::array<double, 4>>();        // left, right, up, down
    // The analytic horizon (OpenXR: the view looks along its −Z, +Y up): world up in view
    // space is u = R(q)ᵀ·(0, 1, 0), and the level directions (a, b, −1) satisfy
    // a·u_x + b·u_y − u_z = 0, i.e. b = u_z/u_y − (u_x/u_y)·a. (The horizon's dip below level
    // from 6 m on the Earth, √(2h/R) = 1.4 mrad, is under a tenth of a row here.)
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    const double ux = 2.0 * (x * y + w * z), uy = 1.0 - 2.0 * (x * x + z * z),
                 uz = 2.0 * (y * z - w * x);
    const double slope = -ux / uy, intercept = uz / uy;
    const auto img = ocean::io::read_png(dir.path / ("view" + std::to_string(eye) + ".png"));
    ASSERT_TRUE(img.ok()) << img.status().message();
    const HorizonFit f = fit_horizon(img.value(), fov);
    const double rows_per_tangent = img.value().height / (std::tan(fov[2]) - std::tan(fov[3]));
    std::printf(
        "eye %d: horizon at %.2f° (analytic %.2f°), at a = 0 b = %.4f (analytic %.4f), "
        "%d columns, rms %.2f rows\n",
        eye, std::atan(f.slope) * 180.0 / M_PI, std::atan(slope) * 180.0 / M_PI, f.intercept,
        intercept, f.columns, f.rms_rows);
    ASSERT_GT(f.columns, img.value().width / 2);
    // Each column's horizon is found to ½ row (the row it crosses): over the ~90 columns the
    // fitted angle within 1°, the line within a row where the view's axis meets it, the
    // residual under a row (uniform ±½ row: 0.29 rms).
    EXPECT_NEAR(std::atan(f.slope), std::atan(slope), 1.0 * M_PI / 180.0) << "eye " << eye;
    EXPECT_NEAR((f.intercept - intercept) * rows_per_tangent, 0.0, 1.0) << "eye " << eye;
    EXPECT_LT(f.rms_rows, 1.0) << "eye " << eye;
  }
}

TEST(XrCli, HorizonRolledAndPlacedByEachViewsProjection) { check_horizon(true); }

TEST(XrCli, HorizonRolledAndPlacedWithoutMultiview) { check_horizon(false); }

TEST(XrCli, NoRuntimeIsOneLineAndAFailure) {
  ScratchDir dir("ocean_xr_none");
  const ocean_test::CliRun r = run_cli_argv(
      {"xr", "--frames", "1"}, {}, {"XR_RUNTIME_JSON=" + (dir.path / "absent.json").string()});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(ocean_test::line_count(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("ocean: error: no OpenXR runtime", 0), 0u) << r.err;
}

// The loader reads the manifest XR_RUNTIME_JSON names with no bound of its own: the tool checks
// it first (a regular file of at most 1 MiB), so /dev/zero, a FIFO with no writer and a huge file
// are one line at once, naming the variable, the file and the limit, before any runtime loads.
TEST(XrCli, ARuntimeManifestThatIsNotASmallFileIsRefusedAtOnce) {
  ScratchDir dir("ocean_xr_manifest");
  const std::filesystem::path fifo = dir.path / "fifo.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::filesystem::path big = dir.path / "big.json";
  std::ofstream(big) << std::string((1 << 20) + 1, ' ');
  // Under an address-space limit and a time limit, so that reading without a bound fails the
  // test rather than filling the machine's memory or waiting for ever.
  const std::string limit = ocean_test::kAddressSanitizer ? "" : "ulimit -v 2000000; ";
  for (const std::filesystem::path& manifest : {std::filesystem::path("/dev/zero"), fifo, big}) {
    const ocean_test::CliRun r = ocean_test::run_cli_after(
        limit + "XR_RUNTIME_JSON='" + manifest.string() + "' timeout 60 ", "xr --frames 1");
    EXPECT_EQ(r.exit_code, 1) << manifest << ": " << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(ocean_test::line_count(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("ocean: error: XR_RUNTIME_JSON: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("'" + manifest.string() + "'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("1048576 bytes (1 MiB)"), std::string::npos) << r.err;
  }
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
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
