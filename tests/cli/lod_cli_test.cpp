// `ocean lod`: counts, the OBJ export (watertight, only the square's boundary is open), the
// layout picture and the usage and runtime error contracts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli/cli_run.hpp"
#include "support/png_reader.hpp"

namespace {

using ocean_test::line_count;

using ocean_test::expect_usage_error;
using ocean_test::run_cli;

std::filesystem::path temp_file(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("ocean_lod_" + std::to_string(::getpid()) + "_" + name);
}

TEST(CliLod, JsonCountsAreConsistent) {
  const auto r = run_cli("lod --camera 0,30,0 --target 100,0,100 --preset high --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["max_level"], 4);
  EXPECT_EQ(j["vertices"], 64);
  const auto per_level = j["patches_per_level"].get<std::vector<int>>();
  const auto per_config = j["patches_per_config"].get<std::vector<int>>();
  int sum_level = 0, sum_config = 0;
  for (int n : per_level) sum_level += n;
  for (int n : per_config) sum_config += n;
  EXPECT_GT(j["patches"].get<int>(), 0);
  EXPECT_EQ(sum_level, j["patches"].get<int>());
  EXPECT_EQ(sum_config, j["patches"].get<int>());
  EXPECT_LE(j["batches"].size(), 16u);
  EXPECT_EQ(j["draws"], j["batches"].size());
  // Without culling there are more patches.
  const auto all = run_cli("lod --camera 0,30,0 --target 100,0,100 --preset high --json --no-cull");
  ASSERT_EQ(all.exit_code, 0) << all.err;
  EXPECT_GT(nlohmann::json::parse(all.out)["patches"].get<int>(), j["patches"].get<int>());
}

TEST(CliLod, ObjOfTheWholeSquareIsWatertight) {
  const auto path = temp_file("all.obj");
  const auto r = run_cli(
      "lod --camera 130,12,-70 --target 400,0,0 --preset low --ocean-size 2048 "
      "--center 0,0 --no-cull --out " +
      path.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("patches"), std::string::npos);
  std::ifstream in(path);
  std::vector<std::pair<double, double>> v;
  std::map<std::pair<int, int>, int> edges;
  std::string line;
  std::size_t faces = 0;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      double x = 0, y = 1, z = 0;
      s >> x >> y >> z;
      EXPECT_EQ(y, 0.0);
      EXPECT_LE(std::max(std::abs(x), std::abs(z)), 1024.0);
      v.emplace_back(x, z);
    } else if (tag == "f") {
      int a[3];
      s >> a[0] >> a[1] >> a[2];
      ++faces;
      for (int k = 0; k < 3; ++k) {
        const int p = a[k], q = a[(k + 1) % 3];
        ++edges[{std::min(p, q), std::max(p, q)}];
      }
    }
  }
  ASSERT_GT(faces, 0u);
  for (const auto& [e, n] : edges) {
    const auto [x0, z0] = v[static_cast<std::size_t>(e.first - 1)];
    const auto [x1, z1] = v[static_cast<std::size_t>(e.second - 1)];
    const bool boundary =
        (x0 == x1 && std::abs(x0) == 1024.0) || (z0 == z1 && std::abs(z0) == 1024.0);
    ASSERT_EQ(n, boundary ? 1 : 2) << x0 << "," << z0 << " - " << x1 << "," << z1;
  }
  std::filesystem::remove(path);
}

TEST(CliLod, LayoutPictureShowsTheLevelsAndTheCamera) {
  const auto path = temp_file("layout.png");
  const auto r =
      run_cli("lod --camera 0,30,0 --target 100,0,100 --ocean-size 4096 --png " + path.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto png = ocean::io::read_png(path);
  ASSERT_TRUE(png.ok()) << png.status().message();
  const auto& im = png.value();
  EXPECT_EQ(im.width, 1150);  // the 900 px map and its key
  EXPECT_EQ(im.height, 900);
  ASSERT_EQ(im.channels, 3);
  const auto count = [&](int r0, int g0, int b0, int x0, int x1) {
    int n = 0;
    for (int y = 0; y < im.height; ++y) {
      for (int x = x0; x < x1; ++x) {
        const std::size_t i = (static_cast<std::size_t>(y) * im.width + x) * 3;
        n += im.samples[i] == r0 && im.samples[i + 1] == g0 && im.samples[i + 2] == b0;
      }
    }
    return n;
  };
  // Patches in the colours of their levels, culled grey and the camera's red on the map; the
  // key has swatches of them and dark text.
  const int levels[][3] = {{49, 54, 149},   {69, 117, 180},  {116, 173, 209},
                           {171, 217, 233}, {254, 224, 144}, {253, 174, 97},
                           {244, 109, 67},  {215, 48, 39},   {165, 0, 38}};
  int patch_pixels = 0;
  for (const auto& c : levels) patch_pixels += count(c[0], c[1], c[2], 0, 900);
  EXPECT_GT(patch_pixels, 100000);
  EXPECT_GT(count(225, 225, 225, 0, 900), 1000);
  EXPECT_GT(count(220, 0, 0, 0, 900), 20);
  EXPECT_GT(count(69, 117, 180, 900, 1150), 100);
  EXPECT_GT(count(25, 25, 25, 900, 1150), 100);
  std::filesystem::remove(path);
  // An unwritable picture: one line, exit 1, nothing left.
  const auto bad = temp_file("missing_png_dir") / "x.png";
  const auto failed = run_cli("lod --camera 0,10,0 --target 1,0,0 --png " + bad.string());
  EXPECT_EQ(failed.exit_code, 1);
  EXPECT_NE(failed.err.find("cannot write"), std::string::npos) << failed.err;
  EXPECT_EQ(line_count(failed.err), 1) << failed.err;
  EXPECT_FALSE(std::filesystem::exists(bad.parent_path()));
}

TEST(CliLod, UsageErrors) {
  expect_usage_error("lod --camera 1,2,3 --target 1,2,3", "--target equals --camera");
  expect_usage_error("lod --camera nan,2,3 --target 0,0,0", "--camera");
  expect_usage_error("lod --camera inf,2,3 --target 0,0,0", "--camera");
  expect_usage_error("lod --camera 1,2 --target 0,0,0", "--camera");
  expect_usage_error("lod --camera 0,10,0 --target 1,0,0 --preset extreme", "--preset");
  expect_usage_error("lod --camera 0,10,0 --target 1,0,0 --ocean-size 100", "--ocean-size");
  expect_usage_error("lod --camera 0,10,0 --target 1,0,0 --fov 0", "--fov");
  expect_usage_error("lod --camera 0,10,0 --target 1,0,0 --center 1", "--center");
  expect_usage_error("lod --target 1,0,0", "--camera");
}

TEST(CliLod, UnwritableOutputFailsWithoutAPartialFile) {
  const auto path = temp_file("missing_dir") / "x.obj";
  const auto r = run_cli("lod --camera 0,10,0 --target 1,0,0 --out " + path.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("cannot write"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
