// `ocean render --band-roles` (docs/math.md M.7.8): the renderer draws what the frame carries,
// so the short band as both, shade-only (no motion) and displace-only (flat shading) gives three
// different pictures. Skips without a Vulkan device (fails with OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>

#include "cli/cli_run.hpp"
#include "ocean/vk.hpp"
#include "support/png_reader.hpp"
#include "support/require_devices.hpp"

namespace {

namespace fs = std::filesystem;

TEST(BandRolesCli, RenderDrawsEachRoleDifferently) {
  if (!ocean::vk::list_devices().ok()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  ocean_test::ScratchDir dir("band_roles_render_");
  const auto render = [&](const std::string& roles) {
    const fs::path out = dir.path / (roles + ".png");
    const auto r = ocean_test::run_cli(
        "render --width 64 --height 36 --quality low --resolution 32 --cascades 60,13 --warmup 0 "
        "--camera 0,6,0 --target 30,0,10 --band-roles " +
        roles + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    auto png = ocean::io::read_png(out);
    EXPECT_TRUE(png.ok());
    return png.ok() ? png.value().samples : std::vector<std::uint16_t>{};
  };
  const auto both = render("both,both");
  const auto shade = render("both,shade");
  const auto displace = render("both,displace");
  ASSERT_FALSE(both.empty());
  EXPECT_NE(shade, both);
  EXPECT_NE(displace, both);
  EXPECT_NE(shade, displace);
}

}  // namespace
