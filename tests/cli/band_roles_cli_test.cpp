// `--band-roles` (docs/math.md M.7.8): a shade-only band does not move the surface `ocean query`
// sees, a displace-only band moves it as before; `ocean bake` records the roles and writes a
// shade-only band's displacement as zeros; bad lists are one line.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/cli_run.hpp"
#include "support/npy_reader.hpp"

namespace {

namespace fs = std::filesystem;

// Heights (choppiness 0: the query's point is the texel's own, so heights add up band by band).
constexpr const char* kSea =
    "query --resolution 32 --cascades 200,47 --seed 4 --time 2 --choppiness 0 --json "
    "--at '1,2;10,-20;-30,40;77,5'";

std::vector<double> heights(const std::string& roles) {
  const auto r =
      ocean_test::run_cli(std::string(kSea) + (roles.empty() ? "" : " --band-roles ") + roles);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  if (r.exit_code != 0) return {};
  return nlohmann::json::parse(r.out)["height_m"].get<std::vector<double>>();
}

TEST(BandRolesCli, ShadeOnlyBandsDoNotMoveTheQueriedSurface) {
  const std::vector<double> full = heights("");
  const std::vector<double> low = heights("both,shade");
  const std::vector<double> high = heights("shade,both");
  ASSERT_EQ(full.size(), 4u);
  ASSERT_EQ(low.size(), 4u);
  ASSERT_EQ(high.size(), 4u);
  for (std::size_t i = 0; i < full.size(); ++i) {
    EXPECT_NE(low[i], full[i]) << i;
    EXPECT_NEAR(low[i] + high[i], full[i], 1e-9 * (1.0 + std::abs(full[i]))) << i;
  }
  EXPECT_EQ(heights("both,displace"), full);
  EXPECT_EQ(heights("displace,displace"), full);
  EXPECT_EQ(heights("shade,shade"), (std::vector<double>(4, 0.0)));
}

TEST(BandRolesCli, BakeRecordsTheRolesAndBadListsAreOneLine) {
  ocean_test::ScratchDir dir("band_roles_bake_");
  const fs::path out = dir.path / "baked";
  const auto r = ocean_test::run_cli(
      "bake --resolution 16 --cascades 100,23 --frames 1 "
      "--band-roles displace,shade --out " +
      out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream manifest(out / "manifest.json");
  const auto m = nlohmann::json::parse(manifest);
  EXPECT_EQ(m["config"]["band_roles"], (nlohmann::json{"displace", "shade"})) << m.dump();
  const auto d = ocean::io::read_npy(out / "displacement_c1_f00000.npy");
  ASSERT_TRUE(d.ok()) << d.status().message();
  for (float v : d.value().data) ASSERT_EQ(v, 0.0f);
  ocean_test::expect_usage_error(std::string(kSea) + " --band-roles both,wobble", "'wobble'");
  ocean_test::expect_usage_error(std::string(kSea) + " --band-roles both", "one per cascade");
  ocean_test::expect_usage_error(std::string(kSea) + " --band-roles ,", "band role ''");
}

}  // namespace
