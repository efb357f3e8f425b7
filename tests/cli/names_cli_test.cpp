// Names and values typed by a user are data. The commands that write user-named files (bake's
// directory and contact sheet, spectrum's plot, lod's OBJ and PNG) write exactly the names given,
// whatever bytes they hold; and a huge bad value (100 kB, near the kernel's 128 kB limit on one
// argument) for a number, a name or an output flag comes back as one short line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "cli/cli_run.hpp"
#include "ocean/core.hpp"

namespace {

using ocean_test::line_count;

namespace fs = std::filesystem;

// printf conversions, shell quoting and substitution, spaces, a newline and bytes that are not
// UTF-8, in one name.
const std::string kHostile = "a%s%n%05d%05d 'q' \"d\" $(touch injected) `touch b`;\n\xff";

TEST(NamesCli, BakeWritesItsDirectoryAndSheetUnderTheNamesGiven) {
  ocean_test::ScratchDir dir("ocean_names_bake_");
  const std::string sheet = kHostile + ".png";
  const ocean_test::CliRun r =
      ocean_test::run_cli_argv({"bake", "--resolution", "16", "--cascades", "50", "--out", kHostile,
                                "--contact-sheet", sheet},
                               dir.path);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(ocean_test::listing(dir.path), (std::set<std::string>{kHostile, sheet}));
  EXPECT_TRUE(fs::exists(dir.path / kHostile / "manifest.json"));
}

TEST(NamesCli, SpectrumPlotAndLodFilesAreWrittenUnderTheNamesGiven) {
  ocean_test::ScratchDir dir("ocean_names_plot_");
  const std::string plot = kHostile + ".png";
  ocean_test::CliRun r = ocean_test::run_cli_argv({"spectrum", "--plot", plot}, dir.path);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(ocean_test::listing(dir.path), (std::set<std::string>{plot}));

  ocean_test::ScratchDir lod("ocean_names_lod_");
  const std::string obj = kHostile + ".obj", png = kHostile + "layout.png";
  r = ocean_test::run_cli_argv(
      {"lod", "--camera", "0,10,0", "--target", "1,0,0", "--out", obj, "--png", png}, lod.path);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(ocean_test::listing(lod.path), (std::set<std::string>{obj, png}));
}

// The contract for a huge bad value: a non-zero exit, nothing on stdout, one line on stderr of
// fewer than 300 bytes, nothing written.
void expect_short_refusal(const std::vector<std::string>& args) {
  ocean_test::ScratchDir dir("ocean_names_huge_");
  const ocean_test::CliRun r = ocean_test::run_cli_argv(args, dir.path);
  std::string shown;
  for (const std::string& a : args) shown += ocean::excerpt(a, 24) + " ";
  shown += "(stderr " + std::to_string(r.err.size()) + " bytes)";
  EXPECT_NE(r.exit_code, 0) << shown;
  EXPECT_TRUE(r.out.empty()) << shown;
  EXPECT_LT(r.err.size(), 300u) << shown << ": " << r.err.substr(0, 300);
  EXPECT_EQ(line_count(r.err), 1) << shown;
  EXPECT_EQ(r.err.rfind("ocean: error: ", 0), 0u) << shown << ": " << r.err.substr(0, 300);
  EXPECT_TRUE(ocean_test::listing(dir.path).empty()) << shown;
}

const std::string kHuge(100000, 'x');
// 50 000 numbers: "1,1,...,1".
const std::string kManyNumbers = [] {
  std::string s = "1";
  for (int i = 0; i < 49999; ++i) s += ",1";
  return s;
}();

TEST(NamesCli, HugeValuesComeBackAsOneShortLine) {
  const std::vector<std::string> lod = {"--camera", "0,10,0", "--target", "1,0,0"};
  const auto with = [](std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"spectrum", "--hs", kHuge, "--tp", "8", "--omega", "1"},
           {"spectrum", "--omega", "1," + kHuge},
           {"spectrum", "--omega", "1", "--depth-factor", kHuge},
           {"spectrum", "--omega", "1", "--gamma", "1e" + std::string(100000, '9')},
           {"spectrum", "--plot", kHuge + ".png"},
           {"spectrum", "--plot", "d/" + kHuge + ".png"},
           {"bake", "--out", kHuge},
           {"bake", "--out", "d", "--fps", kHuge},
           {"bake", "--out", "d", "--frames", kHuge},
           {"bake", "--out", "d", "--format", kHuge},
           {"bake", "--out", "d", "--resolution", "16", "--contact-sheet", kHuge + ".png"},
           {"bake", "--out", "d", "--resolution", kHuge},
           {"bake", "--out", "d", "--cascades", "50," + kHuge},
           {"stats", "--seed", kHuge},
           with({"lod", "--aspect", kHuge}, lod),
           with({"lod", "--center", kHuge}, lod),
           with({"lod", "--preset", kHuge}, lod),
           with({"lod", "--out", kHuge + ".obj"}, lod),
           with({"lod", "--png", kHuge + ".png"}, lod),
           {"lod", "--camera", kHuge, "--target", "1,0,0"},
           {"lod", "--camera", "1," + kHuge, "--target", "1,0,0"},
           {"lod", "--camera", kManyNumbers, "--target", "1,0,0"},
           {"bench", "--backend", kHuge},
           {"bench", "--outputs", kHuge},
           {"bench", "--resolution", kHuge},
           {"bench", "--min-time", kHuge},
       }) {
    expect_short_refusal(args);
  }
}

#ifdef OCEAN_HAS_VULKAN
TEST(NamesCli, HugeRenderValuesComeBackAsOneShortLine) {
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"render", "--out", kHuge + ".png"},
           {"render", "--out", kHuge},
           {"render", "--out", kHuge + "%s.png"},
           {"render", "--out", kHuge + "%s%d%d.png", "--frames", "2"},
           {"render", "--frames", kHuge},
           {"render", "--fps", kHuge},
           {"render", "--width", kHuge},
           {"render", "--camera", kHuge},
           {"render", "--camera", "0,-2000." + std::string(100000, '0') + ",0"},
           {"render", "--sky", kHuge},
           {"render", "--quality", kHuge},
           {"render", "--view", kHuge},
           {"render", "--backend", kHuge},
           {"render", "--contact-sheet", kHuge + ".png"},
       }) {
    expect_short_refusal(args);
  }
}
#endif

#ifdef OCEAN_HAS_VIEW
TEST(NamesCli, HugeViewValuesComeBackAsOneShortLine) {
  expect_short_refusal({"view", "--screenshot", kHuge});
  expect_short_refusal({"view", "--screenshot", kHuge + ".png"});
}
#endif

}  // namespace
