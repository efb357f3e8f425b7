// `ocean bake --shard I/N` and `ocean bake --merge DIR... --out OUT`: three shards baked apart and
// merged are byte for byte the one-machine bake; a missing shard is named; the flags refuse what
// they cannot do, in one line, before anything is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using ocean_test::listing;
using ocean_test::read_whole_file;
using ocean_test::run_cli;
using ocean_test::ScratchDir;

// A small sea with lingering foam (frames depend on the frames before them), four frames.
const std::string kBake =
    "bake --resolution 16 --cascades 200,47 --wind-speed 25 --fetch 100000 --choppiness 2 "
    "--set foam.decay_per_s=0.05 --frames 4 --fps 2 --format npy --format png ";

TEST(BakeShardCli, ShardsMergedAreByteForByteTheOneMachineBake) {
  ScratchDir dir("ocean_cli_shards_");
  const std::string d = dir.path.string();
  ASSERT_EQ(run_cli(kBake + "--out " + d + "/one").exit_code, 0);
  for (int i = 0; i < 3; ++i) {
    const std::string n = std::to_string(i);
    const ocean_test::CliRun r = run_cli(kBake + "--shard " + n + "/3 --out " + d + "/s" + n);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const nlohmann::json shard =
      nlohmann::json::parse(read_whole_file(dir.path / "s2" / "manifest.json"));
  EXPECT_EQ(shard["shard"]["first_frame"], 2);
  EXPECT_EQ(shard["shard"]["last_frame"], 3);
  const ocean_test::CliRun merged =
      run_cli("bake --merge " + d + "/s1 " + d + "/s0 " + d + "/s2 --out " + d + "/merged");
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_NE(merged.err.find("merged 3 shard(s)"), std::string::npos) << merged.err;
  const auto names = listing(dir.path / "one");
  ASSERT_EQ(listing(dir.path / "merged"), names);
  for (const std::string& name : names) {
    EXPECT_TRUE(read_whole_file(dir.path / "one" / name) ==
                read_whole_file(dir.path / "merged" / name))
        << name << " differs";
  }

  // A missing shard is named, with what to run; nothing is written.
  const ocean_test::CliRun missing =
      run_cli("bake --merge " + d + "/s0 " + d + "/s2 --out " + d + "/partial");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(missing.err,
            "ocean: error: shard 1 of 3 is missing (frame 1; bake it with --shard 1/3)\n");
  EXPECT_FALSE(fs::exists(dir.path / "partial"));
}

// A shard of another bake, a frame file changed after its bake or replaced by a link: the merge
// refuses in one line naming the shard, the entry or the file, and writes nothing.
TEST(BakeShardCli, AMergeRefusesAnotherBakesShardOrAChangedFileInOneLine) {
  ScratchDir dir("ocean_cli_shard_checks_");
  const std::string d = dir.path.string();
  for (int i = 0; i < 2; ++i) {
    const std::string n = std::to_string(i);
    ASSERT_EQ(run_cli(kBake + "--shard " + n + "/2 --out " + d + "/s" + n).exit_code, 0);
  }
  std::string fast = kBake;
  fast.replace(fast.find("--fps 2"), 7, "--fps 3");
  ASSERT_EQ(run_cli(fast + "--shard 1/2 --out " + d + "/fast").exit_code, 0);
  const auto refused = [&](const std::string& shards, const std::string& message) {
    const ocean_test::CliRun r = run_cli("bake --merge " + shards + " --out " + d + "/out");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err, "ocean: error: " + message + "\n");
    EXPECT_FALSE(fs::exists(dir.path / "out"));
  };
  refused(d + "/s0 " + d + "/fast",
          "cannot merge: shard '" + d + "/fast' differs from shard '" + d + "/s0' in fps (3 vs 2)");
  const fs::path file = dir.path / "s1" / "foam_c1_f00003.npy";
  const std::string bytes = read_whole_file(file);
  fs::remove(file);
  fs::create_symlink("foam_c1_f00002.npy", file);
  refused(d + "/s0 " + d + "/s1",
          "cannot merge: shard 1 of 2 in '" + d + "/s1': 'foam_c1_f00003.npy' is a symbolic link");
  fs::remove(file);
  std::ofstream(file, std::ios::binary) << bytes.substr(0, 64);
  refused(d + "/s0 " + d + "/s1", "cannot merge: shard 1 of 2 in '" + d +
                                      "/s1': 'foam_c1_f00003.npy' holds 64 bytes, " +
                                      "its manifest says " + std::to_string(bytes.size()) +
                                      ": the file changed after the bake; bake the shard again");
}

TEST(BakeShardCli, BadShardAndMergeFlagsFailInOneLine) {
  ScratchDir dir("ocean_cli_shard_flags_");
  const std::string out = " --out " + (dir.path / "x").string();
  const auto fails = [&](const std::string& args, const std::string& message, int code = 2) {
    const ocean_test::CliRun r = run_cli(args);
    EXPECT_EQ(r.exit_code, code) << args;
    EXPECT_EQ(r.err, "ocean: error: " + message + "\n") << args;
    EXPECT_FALSE(fs::exists(dir.path / "x")) << args;
  };
  const std::string not_shard =
      "' is not I/N: must be a shard index 0 to N-1, a slash and a count 1 to 1000000";
  fails(kBake + "--shard 3/3" + out, "--shard = '3/3" + not_shard);
  fails(kBake + "--shard 1" + out, "--shard = '1" + not_shard);
  fails(kBake + "--shard -1/2" + out, "--shard = '-1/2" + not_shard);
  fails(kBake + "--shard 0/5" + out, "--shard 0/5: 4 frame(s) make at most 4 shard(s)");
  fails("bake --merge a b --frames 3" + out,
        "--merge takes only --out: --frames belongs to a bake, not to a merge");
  fails("bake --merge a b", "--merge needs --out DIR");
  fails("bake --merge " + (dir.path / "nowhere").string() + out,
        "cannot read manifest '" + (dir.path / "nowhere" / "manifest.json").string() +
            "': No such file or directory",
        1);
}

}  // namespace
