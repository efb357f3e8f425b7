// `ocean render --object ... [--float]`: built-in shapes and a glTF file in the picture, floating
// on the waves; bad input — a NaN or out-of-range coordinate or speed, an unknown kind, a missing,
// malformed or (with --float) open glTF mesh, --float without an object, a speed without
// --float — is one line and a
// non-zero exit with nothing written; so is a seabed depth that is not a positive number. Skips the
// rendering cases where no Vulkan device exists (fails them with OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli/cli_run.hpp"
#include "ocean/vk.hpp"
#include "support/glb.hpp"
#include "support/png_reader.hpp"
#include "support/require_devices.hpp"

namespace {

namespace fs = std::filesystem;
using ocean_test::line_count;

const std::string kSmall =
    " --width 64 --height 36 --quality low --resolution 64 --warmup 0 --camera 0,4,0 "
    "--target 20,0,0";

TEST(ObjectsCli, RefusesBadObjectsWithOneLine) {
  const ocean_test::ScratchDir dir("ocean_objects_cli_");
  const fs::path out = dir.path / "o.png";
  const fs::path garbage = dir.path / "garbage.glb";
  std::ofstream(garbage, std::ios::binary) << "glTF not really";
  std::string open_json = ocean_test::cube_json();
  open_json.replace(open_json.find("\"count\": 36"), 11, "\"count\": 30");
  const fs::path open =
      ocean_test::write_glb(dir.path / "open.glb", open_json, ocean_test::cube_bin());
  const std::pair<std::string, std::string> cases[] = {
      {"--object box,nan,0,0", "--object x"},
      {"--object box,0,0,1e9", "--object z"},
      {"--object box,0,0,0,720", "--object heading"},
      {"--object box,0,0", "KIND,X,Y,Z"},
      {"--object sphere,0,0,0", "is not box, buoy, boat"},
      {"--object " + (dir.path / "missing.glb").string() + ",0,0,0", "cannot read"},
      {"--object " + garbage.string() + ",0,0,0", "cannot read"},
      {"--object " + open.string() + ",0,0,0 --float", "cannot float"},
      {"--float", "--float needs"},
      {"--object boat,0,0,0,0,-1 --float", "--object speed"},
      {"--object boat,0,0,0,0,40 --float", "--object speed"},
      {"--object boat,0,0,0,0,5", "add --float"},
      {"--object boat,0,0,0,0,5,1 --float", "KIND,X,Y,Z"},
      {"--seabed -2", "--seabed"},
      {"--seabed nan", "--seabed"},
  };
  for (const auto& [args, words] : cases) {
    const ocean_test::CliRun r =
        ocean_test::run_cli("render --out " + out.string() + kSmall + " " + args);
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_EQ(line_count(r.err), 1) << args << ": " << r.err;
    EXPECT_NE(r.err.find("ocean: error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(words), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
}

TEST(ObjectsCli, RendersFloatingShapesAndAGltfMesh) {
  if (!ocean::vk::list_devices().ok()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const ocean_test::ScratchDir dir("ocean_objects_cli_ok_");
  const fs::path cube =
      ocean_test::write_glb(dir.path / "cube.glb", ocean_test::cube_json(), ocean_test::cube_bin());
  const fs::path out = dir.path / "float.png", plain = dir.path / "plain.png";
  ocean_test::CliRun r =
      ocean_test::run_cli("render --out " + plain.string() + kSmall + " --time 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = ocean_test::run_cli("render --out " + out.string() + kSmall + " --time 2 --float " +
                          "--object boat,20,0,0,90 --object buoy,15,0,-3 --object " +
                          cube.string() + ",15,0,3 --validation");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto a = ocean::io::read_png(out), b = ocean::io::read_png(plain);
  ASSERT_TRUE(a.ok() && b.ok());
  // The objects are in the picture: pixels differ from the same sea's without them (the CPU
  // simulation and the picture are deterministic), and only in the middle rows, around the
  // horizon-ward view of objects 15-20 m away.
  int differing = 0, outside = 0;
  const auto& pa = a.value().samples;
  const auto& pb = b.value().samples;
  for (std::size_t i = 0; i < pa.size(); ++i) {
    if (pa[i] == pb[i]) continue;
    ++differing;
    const std::size_t row = i / (3 * 64);
    outside += row < 8 || row > 30;
  }
  EXPECT_GT(differing, 20);
  EXPECT_EQ(outside, 0);
}

}  // namespace
