// `ocean render --stereo [--ipd M]`: a side-by-side picture twice the width, its halves the two
// eyes (different where the sea is near); `--motion-vectors FILE.png`: a picture of the same
// size, grey (still) in the sky and not in the moving sea. A negative, NaN or out-of-range IPD,
// --ipd without --stereo, --stereo with a contact sheet or with motion vectors, a motion file
// that is not .png: one line, non-zero exit, nothing written. Skips the rendering case where no
// Vulkan device exists (fails it with OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "cli/cli_run.hpp"
#include "ocean/vk.hpp"
#include "support/png_reader.hpp"
#include "support/require_devices.hpp"

namespace {

namespace fs = std::filesystem;

fs::path stereo_scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("ocean_stereo_cli_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir / name;
}

const std::string kStereoSmall =
    " --width 64 --height 40 --quality low --resolution 64 --warmup 0 --validation";

TEST(StereoCli, WritesBothEyesSideBySide) {
  if (!ocean::vk::list_devices().ok()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const fs::path out = stereo_scratch("stereo.png");
  // Looking down at the water 3 m below, the eyes 0.5 m apart see it shifted.
  const ocean_test::CliRun r = ocean_test::run_cli(
      "render --stereo --ipd 0.5 --camera 0,3,0 "
      "--target 10,-1,0 --out " +
      out.string() + kStereoSmall);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto png = ocean::io::read_png(out);
  ASSERT_TRUE(png.ok()) << png.status().message();
  EXPECT_EQ(png.value().width, 128);
  EXPECT_EQ(png.value().height, 40);
  const auto& px = png.value().samples;
  long near_difference = 0;
  for (int y = 30; y < 40; ++y)
    for (int x = 0; x < 64; ++x)
      for (int c = 0; c < 3; ++c)
        near_difference += std::abs(px[static_cast<std::size_t>((y * 128 + x) * 3 + c)] -
                                    px[static_cast<std::size_t>((y * 128 + x + 64) * 3 + c)]);
  EXPECT_GT(near_difference, 64 * 10 * 3);  // more than 1 LSB a value on average
}

TEST(StereoCli, WritesMotionVectors) {
  if (!ocean::vk::list_devices().ok()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const fs::path out = stereo_scratch("colour.png"), motion = stereo_scratch("motion.png");
  const ocean_test::CliRun r = ocean_test::run_cli("render --motion-vectors " + motion.string() +
                                                   " --out " + out.string() + kStereoSmall);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto png = ocean::io::read_png(motion);
  ASSERT_TRUE(png.ok()) << png.status().message();
  ASSERT_EQ(png.value().width, 64);
  ASSERT_EQ(png.value().height, 40);
  const auto& px = png.value().samples;
  const auto at = [&](int x, int y, int c) {
    return px[static_cast<std::size_t>((y * 64 + x) * 3 + c)];
  };
  EXPECT_EQ(at(10, 1, 0), 128);  // the sky: a still camera, no motion
  EXPECT_EQ(at(10, 1, 1), 128);
  int moving = 0;
  for (int x = 0; x < 64; ++x) moving += at(x, 38, 0) != 128 || at(x, 38, 1) != 128 ? 1 : 0;
  EXPECT_GT(moving, 32);  // the waves near the camera move
}

TEST(StereoCli, BadInputIsOneLine) {
  const fs::path out = stereo_scratch("bad.png");
  for (const char* flags : {"--stereo --ipd -0.064", "--stereo --ipd nan", "--stereo --ipd 2",
                            "--stereo --ipd x", "--ipd 0.064", "--stereo --contact-sheet sheet.png",
                            "--stereo --motion-vectors m.png", "--motion-vectors m.jpg"}) {
    const ocean_test::CliRun r =
        ocean_test::run_cli(std::string("render ") + flags + " --out " + out.string() + kStereoSmall);
    EXPECT_NE(r.exit_code, 0) << flags;
    EXPECT_EQ(ocean_test::line_count(r.err), 1) << flags << ": " << r.err;
    EXPECT_EQ(r.err.rfind("ocean: error: ", 0), 0u) << flags << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << flags;
  }
}

}  // namespace
