// `ocean render --sphere` (docs/rendering.md R.30–R.38): a small planet from orbit written as a
// PNG, the planet's disc where geometry puts it; bad input — a radius ≤ 0, NaN, infinite, a
// camera inside the planet, a latitude beyond the pole, the place flags without --sphere — is
// one line and a non-zero exit. Skips the rendering case where no Vulkan device exists (fails
// it with OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>

#include "cli/cli_run.hpp"
#include "ocean/vk.hpp"
#include "support/png_reader.hpp"
#include "support/require_devices.hpp"

namespace {

TEST(SphereCli, BadInputIsOneLine) {
  ocean_test::expect_usage_error("render --sphere --planet-radius 0", "--planet-radius");
  ocean_test::expect_usage_error("render --sphere --planet-radius -5000", "--planet-radius");
  ocean_test::expect_usage_error("render --sphere --planet-radius nan", "--planet-radius");
  ocean_test::expect_usage_error("render --sphere --planet-radius inf",
                                 "--sphere needs a finite --planet-radius");
  ocean_test::expect_usage_error("render --sphere --planet-radius 5000 --camera 0,-30,0",
                                 "the camera is inside the planet");
  ocean_test::expect_usage_error(
      "render --sphere --planet-radius 5000 --camera 100,-3,0 --target 0,-3000,0",
      "the camera is inside the planet");
  ocean_test::expect_usage_error("render --sphere --latitude 91", "--latitude");
  ocean_test::expect_usage_error("render --sphere --latitude nan", "--latitude");
  ocean_test::expect_usage_error("render --sphere --altitude -5", "--altitude");
  ocean_test::expect_usage_error("render --latitude 30", "need --sphere");
  ocean_test::expect_usage_error("render --sphere --view wireframe", "wireframe");
  // --planet-radius alone still bends the flat sea (R.15), where a camera may dive (R.50) but
  // not below 1000 m.
  ocean_test::expect_usage_error("render --planet-radius 5000 --camera 0,-3000,0", "1000 m below");
}

TEST(SphereCli, ASmallPlanetFromOrbit) {
  if (!ocean::vk::list_devices().ok()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const ocean_test::ScratchDir dir("ocean_sphere_cli");
  const auto out = dir.path / "planet.png";
  // A 5 km planet, the eye 10 km up looking at its centre: its disc's angular radius is
  // asin(R/d) = 19.5°, so with a 60° field of view the centre is sea and the corners sky.
  const ocean_test::CliRun r = ocean_test::run_cli(
      "render --sphere --planet-radius 5000 --latitude 20 --longitude 30 --altitude 10000 "
      "--target 0,-5000,1 --fov 60 --width 64 --height 64 --quality low --resolution 64 "
      "--warmup 0 --validation --out " +
      out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto png = ocean::io::read_png(out);
  ASSERT_TRUE(png.ok()) << png.status().message();
  EXPECT_EQ(png.value().width, 64);
  const auto& px = png.value().samples;
  const auto blue = [&](int x, int y) {
    return int(px[static_cast<std::size_t>((y * 64 + x) * 3 + 2)]);
  };
  const auto red = [&](int x, int y) {
    return int(px[static_cast<std::size_t>((y * 64 + x) * 3)]);
  };
  // The sky's corner is bright blue; the deep water at the disc's centre is dark.
  EXPECT_GT(blue(1, 1), blue(32, 32) + 20);
  EXPECT_GT(blue(1, 1) + red(1, 1), blue(32, 32) + red(32, 32));
}

}  // namespace
