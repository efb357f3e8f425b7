// `ocean view` end to end: under an Xvfb server this test starts itself, a few frames with the
// validation layer write a screenshot of the right size that shows sky above water; without a
// display the command fails with one line and exit 1; bad flags are usage errors before any
// window opens. The window tests skip where Xvfb or a Vulkan device is missing (fail with
// OCEAN_REQUIRE_DEVICES=1).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "cli/cli_run.hpp"
#include "ocean/backends.hpp"
#include "support/png_reader.hpp"
#include "support/require_devices.hpp"

namespace {

namespace fs = std::filesystem;

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return false;
  const std::string dirs(path);
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    if (::access((fs::path(dirs.substr(start, end - start)) / program).c_str(), X_OK) == 0)
      return true;
    start = end + 1;
  }
  return false;
}

bool vulkan_available(std::string* why) {
  for (const ocean::BackendInfo& b : ocean::list_backends()) {
    if (b.name == "vulkan") {
      *why = b.detail;
      return b.available;
    }
  }
  *why = "no vulkan backend in this build";
  return false;
}

// An Xvfb server on a display it picks itself (-displayfd), stopped on destruction.
class Xvfb {
 public:
  Xvfb() {
    int fds[2];
    if (::pipe(fds) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {
      ::close(fds[0]);
      const int null = ::open("/dev/null", O_WRONLY);
      ::dup2(null, 1), ::dup2(null, 2);
      const std::string fd = std::to_string(fds[1]);
      ::execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "640x480x24", "-nolisten",
               "tcp", static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(fds[1]);
    // Xvfb writes the display number and a newline once it accepts connections.
    std::string number;
    pollfd p{fds[0], POLLIN, 0};
    while (pid_ > 0 && ::poll(&p, 1, 20000) == 1) {
      char c = 0;
      if (::read(fds[0], &c, 1) != 1 || c == '\n') break;
      number += c;
    }
    ::close(fds[0]);
    if (!number.empty()) display_ = ":" + number;
  }
  ~Xvfb() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  Xvfb(const Xvfb&) = delete;
  Xvfb& operator=(const Xvfb&) = delete;
  [[nodiscard]] const std::string& display() const { return display_; }

 private:
  pid_t pid_ = -1;
  std::string display_;
};

class ViewCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!on_path("Xvfb")) {
      skip_ = "Xvfb is not installed (apt-get install xvfb)";
      return;
    }
    std::string why;
    if (!vulkan_available(&why)) {
      skip_ = "vulkan unavailable: " + why;
      return;
    }
    server_.emplace();
    if (!server_->display().empty()) ::setenv("DISPLAY", server_->display().c_str(), 1);
  }
  static void TearDownTestSuite() { server_.reset(); }

  void SetUp() override {
    if (!skip_.empty()) OCEAN_SKIP_OR_FAIL(skip_);
    ASSERT_FALSE(server_->display().empty()) << "Xvfb did not start";
    dir_ = fs::temp_directory_path() / ("ocean_view_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    if (!dir_.empty()) fs::remove_all(dir_, ec);
  }

  static inline std::optional<Xvfb> server_;
  static inline std::string skip_;
  fs::path dir_;
};

// Mean luminance of rows [y0, y1) of an 8-bit RGB image.
double mean_luma(const ocean::io::PngImage& im, int y0, int y1) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < im.width; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * im.width + x) * 3;
      sum += 0.2126 * im.samples[i] + 0.7152 * im.samples[i + 1] + 0.0722 * im.samples[i + 2];
    }
  return sum / ((y1 - y0) * im.width);
}

TEST_F(ViewCli, ScreenshotShowsSkyAboveWater) {
  const fs::path png = dir_ / "view.png";
  const ocean_test::CliRun r = ocean_test::run_cli(
      "view --frames 3 --width 320 --height 200 --quality low --resolution 64 "
      "--validation --screenshot " +
      png.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote " + png.string() + " (320x200"), std::string::npos) << r.out;
  const auto read = ocean::io::read_png(png);
  ASSERT_TRUE(read.ok()) << read.status().message();
  const ocean::io::PngImage& im = read.value();
  ASSERT_EQ(im.width, 320);
  ASSERT_EQ(im.height, 200);
  ASSERT_EQ(im.channels, 3);
  ASSERT_EQ(im.bit_depth, 8);
  // Not a uniform picture: sky, horizon and waves spread the luminance.
  const double mean = mean_luma(im, 0, im.height);
  double var = 0.0;
  for (std::size_t i = 0; i < im.samples.size(); i += 3) {
    const double l =
        0.2126 * im.samples[i] + 0.7152 * im.samples[i + 1] + 0.0722 * im.samples[i + 2];
    var += (l - mean) * (l - mean);
  }
  EXPECT_GT(std::sqrt(var / static_cast<double>(im.samples.size() / 3)), 8.0);
  // The camera looks slightly down at the horizon: daylight sky on top, darker water below.
  EXPECT_GT(mean_luma(im, 0, im.height / 5), mean_luma(im, im.height - im.height / 5, im.height));
}

// --taa (R.61) in the window: the jittered frames blended along the motion vectors, validation
// on; the screenshot still shows sky above water, of the plain screenshot's mean brightness
// within 3 %.
TEST_F(ViewCli, TemporalAntiAliasingRuns) {
  const std::string flags =
      "view --frames 4 --width 320 --height 200 --quality low --resolution 64 --validation";
  const fs::path plain = dir_ / "plain.png", taa = dir_ / "taa.png";
  const ocean_test::CliRun a = ocean_test::run_cli(flags + " --screenshot " + plain.string());
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const ocean_test::CliRun b = ocean_test::run_cli(flags + " --taa --screenshot " + taa.string());
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const auto p = ocean::io::read_png(plain), q = ocean::io::read_png(taa);
  ASSERT_TRUE(p.ok() && q.ok());
  EXPECT_NE(p.value().samples, q.value().samples);
  const ocean::io::PngImage& im = q.value();
  EXPECT_GT(mean_luma(im, 0, im.height / 5), mean_luma(im, im.height - im.height / 5, im.height));
  EXPECT_NEAR(mean_luma(im, 0, im.height) / mean_luma(p.value(), 0, im.height), 1.0, 0.03);
}

TEST_F(ViewCli, DebugViewsAndTheVulkanBackendRun) {
  const ocean_test::CliRun r = ocean_test::run_cli(
      "view --frames 2 --width 256 --height 160 --quality low --resolution 64 --cascades 300,70 "
      "--backend vulkan --view lod --validation");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;  // nothing printed without --screenshot
}

// The lagoon seen from above with the boat circling it (validation on): the island in the
// middle of the picture is drawn as sand (land, R.64), brighter than the deep water at the
// corners; without --shallows the middle is water like the corners.
TEST_F(ViewCli, LagoonAndBoatDrawFromAbove) {
  const auto shoot = [&](const std::string& flags) {
    const fs::path png = dir_ / "lagoon.png";
    const ocean_test::CliRun r = ocean_test::run_cli(
        "view --frames 2 --width 160 --height 160 --quality low --resolution 64 --validation "
        "--camera 0,150,1 --target 0,0,0 " +
        flags + " --screenshot " + png.string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    auto read = ocean::io::read_png(png);
    EXPECT_TRUE(read.ok()) << read.status().message();
    return read.ok() ? std::move(read).value() : ocean::io::PngImage{};
  };
  // Mean green of a 20-pixel square at (x0, y0).
  const auto patch = [](const ocean::io::PngImage& im, int x0, int y0) {
    if (im.width != 160 || im.height != 160) return 0.0;
    double sum = 0.0;
    for (int y = y0; y < y0 + 20; ++y)
      for (int x = x0; x < x0 + 20; ++x) sum += im.samples[(y * 160 + x) * 3 + 1];
    return sum / 400.0;
  };
  const auto corners = [&](const ocean::io::PngImage& im) {
    return (patch(im, 0, 0) + patch(im, 140, 0) + patch(im, 0, 140) + patch(im, 140, 140)) / 4;
  };
  const ocean::io::PngImage lagoon = shoot("--shallows lagoon --boat");
  const ocean::io::PngImage sea = shoot("");
  // The island is pale sand, the deep sea dark blue; the shallows at the corners (11 m deep)
  // lie between.
  EXPECT_GT(patch(lagoon, 70, 70), 4.0 * patch(sea, 70, 70));
  EXPECT_GT(patch(lagoon, 70, 70), 1.3 * corners(lagoon));
  EXPECT_GT(corners(lagoon), 2.0 * corners(sea));
}

TEST(ViewCliNoDisplay, FailsWithOneLine) {
  const char* saved = std::getenv("DISPLAY");
  const std::string display = saved != nullptr ? saved : "";
  ::unsetenv("DISPLAY");
  ::unsetenv("WAYLAND_DISPLAY");
  const ocean_test::CliRun r = ocean_test::run_cli("view --frames 1");
  if (!display.empty()) ::setenv("DISPLAY", display.c_str(), 1);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(r.err,
            "ocean: error: ocean view needs a display: glfwInit failed (set DISPLAY or run under "
            "xvfb-run)\n");
}

TEST(ViewCliNoDisplay, BadFlagsAreUsageErrors) {
  // All of these fail before a window is opened, display or not.
  ocean_test::expect_usage_error("view --frames -1", "--frames");
  ocean_test::expect_usage_error("view --frames 2.5", "--frames");
  ocean_test::expect_usage_error("view --width 10", "--width");
  ocean_test::expect_usage_error("view --quality bogus", "--quality");
  ocean_test::expect_usage_error("view --view sketch", "--view");
  ocean_test::expect_usage_error("view --backend opengl", "--backend");
  ocean_test::expect_usage_error("view --camera 0,-2000,0", "--camera");
  ocean_test::expect_usage_error("view --screenshot shot.jpg", "--screenshot");
  ocean_test::expect_usage_error("view --taa --backend vulkan", "--taa: not with --backend");
  ocean_test::expect_usage_error("view --taa --sphere", "--taa: not with --sphere");
  ocean_test::expect_usage_error("view --resolution 100", "resolution");
  ocean_test::expect_usage_error("view --shallows reef", "--shallows");
}

}  // namespace
