// Sharded bakes and their merge (ocean::bake::shard_frames, parse_shard, BakeParams::shard,
// merge): the shards cover every frame once, a shard bakes only its block with a manifest saying
// so, and the merge of all shards is byte for byte a one-machine bake; a merge refuses shards of
// different bakes, a missing, repeated or incomplete shard and a manifest naming files outside its
// folder before touching anything, and holds its output folder as a bake does (lock, old
// manifest removed first, cancellation leaving "complete": false and no temporary).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ocean/bake.hpp"
#include "support/temp_dir.hpp"

namespace {

namespace fs = std::filesystem;
namespace bake = ocean::bake;

using ocean_test::TempDir;

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// `prefix` followed by `n` (append: g++ 12 -O3 warns falsely about "..." + std::to_string).
std::string numbered(std::string prefix, long long n) { return prefix.append(std::to_string(n)); }

void write_text(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// Every file of a folder by name with its bytes.
std::map<std::string, std::string> contents(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::directory_iterator(dir))
    files[e.path().filename().string()] = read_bytes(e.path());
  return files;
}

ocean::SimulationConfig shard_small_config(std::uint64_t seed = 5) {
  ocean::SimulationConfig c;
  c.resolution = 16;
  c.cascade_patch_sizes_m = {200};
  c.seed = seed;
  // A rough sea whose foam forms, moves and lingers (slow decay, frames half a second apart), so
  // that a frame's foam depends on the frames before it: what a shard's warm-up is for.
  c.sea.wind_sea.spectrum.wind_speed_mps = 25.0;
  c.choppiness = 2.0;
  c.foam.decay_per_s = 0.05;
  return c;
}

// Every file is fsynced: the bakes here are small, and only the byte-for-byte test writes every
// format.
bake::BakeParams params(const fs::path& dir, std::optional<bake::Shard> shard = {},
                        bake::Formats formats = {.npy = true}) {
  return {.output_dir = dir,
          .formats = formats,
          .frame_count = 5,
          .fps = 2,
          .start_time_s = 0.25,
          .shard = shard};
}

// Bakes shards 0..count−1 of shard_small_config() into root/s<i>; returns their folders.
std::vector<fs::path> bake_shards(const fs::path& root, long long count,
                                  bake::Formats formats = {.npy = true}) {
  std::vector<fs::path> dirs;
  for (long long i = 0; i < count; ++i) {
    dirs.push_back(root / numbered("s", i));
    const ocean::Status s = bake::bake(shard_small_config(), "cpu",
                                       params(dirs.back(), bake::Shard{i, count}, formats));
    EXPECT_TRUE(s.ok()) << s.message();
  }
  return dirs;
}

TEST(BakeShards, TheShardsCoverEveryFrameOnceInContiguousBlocks) {
  for (long long frames : {1LL, 2LL, 7LL, 100LL, 1000000LL}) {
    for (long long count : {1LL, 2LL, 3LL, 7LL, 64LL}) {
      if (count > frames) continue;
      long long next = 0;
      for (long long i = 0; i < count; ++i) {
        const bake::FrameRange r = bake::shard_frames(frames, {i, count});
        EXPECT_EQ(r.first, next);
        EXPECT_GE(r.end - r.first, frames / count);  // blocks differ by at most one frame
        EXPECT_LE(r.end - r.first, frames / count + 1);
        next = r.end;
      }
      EXPECT_EQ(next, frames);
    }
  }
}

TEST(BakeShards, ParseShardReadsIndexSlashCount) {
  const ocean::Result<bake::Shard> s = bake::parse_shard("2/5");
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s.value().index, 2);
  EXPECT_EQ(s.value().count, 5);
  for (const char* bad : {"5/5", "-1/3", "1/0", "1", "/3", "1/", "a/b", "1/2/3", " 1/2", "1/2 ",
                          "0/1000001", "0x1/2", "99999999/100000000"}) {
    const ocean::Result<bake::Shard> r = bake::parse_shard(bad, "--shard");
    ASSERT_FALSE(r.ok()) << bad;
    EXPECT_EQ(r.status().message().rfind("--shard = '", 0), 0u) << r.status().message();
    EXPECT_NE(r.status().message().find("is not I/N"), std::string::npos);
  }
}

TEST(BakeShards, AShardWritesItsBlockOnlyWithAManifestSayingSo) {
  TempDir root("bake_shard_");
  const fs::path dir = root.path / "s1";
  ASSERT_TRUE(bake::bake(shard_small_config(), "cpu", params(dir, bake::Shard{1, 3})).ok());
  const nlohmann::json m = nlohmann::json::parse(read_bytes(dir / "manifest.json"));
  EXPECT_EQ(m["shard"],
            (nlohmann::json{{"index", 1}, {"count", 3}, {"first_frame", 1}, {"last_frame", 2}}));
  EXPECT_EQ(m["complete"], true);
  EXPECT_EQ(m["frame_count"], 5);
  EXPECT_EQ(m["frames_written"], 2);
  ASSERT_EQ(m["frames"].size(), 2u);
  EXPECT_EQ(m["frames"][0]["index"], 1);
  EXPECT_DOUBLE_EQ(m["frames"][1]["time_s"].get<double>(), 0.25 + 2 / 2.0);
  EXPECT_TRUE(fs::exists(dir / "displacement_c0_f00002.npy"));
  EXPECT_FALSE(fs::exists(dir / "displacement_c0_f00000.npy"));
  EXPECT_FALSE(fs::exists(dir / "displacement_c0_f00003.npy"));
  // A shard beyond the frames is refused before anything is made.
  const ocean::Status s =
      bake::bake(shard_small_config(), "cpu", params(root.path / "x", bake::Shard{0, 8}));
  EXPECT_EQ(s.code(), ocean::ErrorCode::invalid_argument);
  EXPECT_FALSE(fs::exists(root.path / "x"));
}

TEST(BakeShards, TheMergeOfAllShardsIsByteForByteTheOneMachineBake) {
  TempDir root("bake_merge_");
  const bake::Formats all{.npy = true, .png = true, .exr = true};
  ASSERT_TRUE(bake::bake(shard_small_config(), "cpu", params(root.path / "one", {}, all)).ok());
  // The sea's foam carries history: frame 3 baked on its own is not frame 3 of the whole bake,
  // so a shard must step through the frames before its own.
  bake::BakeParams alone = params(root.path / "alone");
  alone.frame_count = 1;
  alone.start_time_s += 3 / alone.fps;
  ASSERT_TRUE(bake::bake(shard_small_config(), "cpu", alone).ok());
  ASSERT_NE(read_bytes(root.path / "alone" / "foam_c0_f00000.npy"),
            read_bytes(root.path / "one" / "foam_c0_f00003.npy"));
  for (long long count : {1LL, 3LL}) {
    std::vector<fs::path> dirs = bake_shards(root.path / numbered("", count), count, all);
    std::reverse(dirs.begin(), dirs.end());  // any order
    const fs::path merged = root.path / numbered("merged", count);
    const ocean::Status s = bake::merge(dirs, {.output_dir = merged});
    ASSERT_TRUE(s.ok()) << s.message();
    const auto expected = contents(root.path / "one"), got = contents(merged);
    EXPECT_EQ(got.size(), expected.size());
    for (const auto& [name, bytes] : expected) {
      ASSERT_TRUE(got.contains(name)) << name;
      EXPECT_TRUE(got.at(name) == bytes) << name << " differs";  // not printed: binary
    }
  }
}

TEST(BakeShards, TheMergeRefusesShardsThatAreNotOneWholeBake) {
  TempDir root("bake_merge_bad_");
  const std::vector<fs::path> dirs = bake_shards(root.path, 3);
  const fs::path out = root.path / "out";
  const auto refused = [&](std::vector<fs::path> shards, const std::string& fragment) {
    const ocean::Status s = bake::merge(shards, {.output_dir = out});
    EXPECT_EQ(s.code(), ocean::ErrorCode::invalid_argument) << s.message();
    EXPECT_NE(s.message().find(fragment), std::string::npos) << s.message();
    EXPECT_EQ(s.message().find('\n'), std::string::npos);
    EXPECT_FALSE(fs::exists(out)) << "nothing is touched before every check passed";
  };
  refused({}, "merge needs at least one shard folder");
  refused({dirs[0], dirs[2]}, "shard 1 of 3 is missing (frames 1 to 2; bake it with --shard 1/3)");
  refused({dirs[0], dirs[1], dirs[1], dirs[2]}, "shard 1 of 3 is given twice");
  // Another configuration's shard.
  const fs::path other = root.path / "other";
  ASSERT_TRUE(bake::bake(shard_small_config(6), "cpu", params(other, bake::Shard{1, 3})).ok());
  refused({dirs[0], other, dirs[2]}, "cannot merge: shard '" + other.string() +
                                         "' differs from shard '" + dirs[0].string() +
                                         "' in config.seed (6 vs 5)");
  // Another shard count.
  const fs::path half = root.path / "half";
  ASSERT_TRUE(bake::bake(shard_small_config(), "cpu", params(half, bake::Shard{1, 2})).ok());
  refused({dirs[0], half, dirs[2]}, "is shard 1 of 2 but");
  // A one-machine bake is no shard.
  const fs::path whole = root.path / "whole";
  ASSERT_TRUE(bake::bake(shard_small_config(), "cpu", params(whole)).ok());
  refused({whole}, "it has no \"shard\" entry");
  // An incomplete shard, a missing file, a manifest naming a file outside its folder, no manifest.
  const std::string manifest = read_bytes(dirs[1] / "manifest.json");
  nlohmann::ordered_json m = nlohmann::ordered_json::parse(manifest);
  m["complete"] = false;
  write_text(dirs[1] / "manifest.json", m.dump(2));
  refused(dirs, "shard 1 of 3 in '" + dirs[1].string() + "' is incomplete");
  m["complete"] = true;
  m["frames"][0]["files"][0] = "../s0/manifest.json";
  write_text(dirs[1] / "manifest.json", m.dump(2));
  refused(dirs, "which is not a plain file name");
  write_text(dirs[1] / "manifest.json", manifest);
  fs::remove(dirs[1] / "foam_c0_f00002.npy");
  refused(dirs, "lacks 'foam_c0_f00002.npy', which its manifest lists");
  write_text(dirs[1] / "manifest.json", "{\"shard\": ");
  refused(dirs, "is not a shard's manifest: not valid JSON");
  fs::remove(dirs[1] / "manifest.json");
  const ocean::Status s = bake::merge(dirs, {.output_dir = out});
  EXPECT_EQ(s.code(), ocean::ErrorCode::io_error);
  EXPECT_NE(s.message().find("cannot read manifest '" + (dirs[1] / "manifest.json").string()),
            std::string::npos)
      << s.message();
  // Into a shard's own folder.
  const std::vector<fs::path> good = bake_shards(root.path / "good", 2);
  const ocean::Status into = bake::merge(good, {.output_dir = good[1]});
  EXPECT_NE(into.message().find("is the folder of a shard"), std::string::npos);
}

TEST(BakeShards, TheMergeHoldsItsFolderAsABakeDoes) {
  TempDir root("bake_merge_tx_");
  const std::vector<fs::path> dirs = bake_shards(root.path, 2);
  const fs::path out = root.path / "out";
  // An old bake in the folder: a locked folder fails at once and leaves it alone.
  ASSERT_TRUE(bake::bake(shard_small_config(9), "cpu", params(out)).ok());
  const std::string old_manifest = read_bytes(out / "manifest.json");
  const fs::path lock = out / bake::kLockFileName;
  const int fd = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  const ocean::Status locked = bake::merge(dirs, {.output_dir = out});
  EXPECT_EQ(locked.code(), ocean::ErrorCode::io_error);
  EXPECT_NE(locked.message().find("is being baked by"), std::string::npos) << locked.message();
  EXPECT_EQ(read_bytes(out / "manifest.json"), old_manifest);
  ::close(fd);
  // Cancelled before the first file: the old bake is untouched.
  std::atomic<bool> cancel{true};
  ocean::Status s = bake::merge(dirs, {.output_dir = out, .cancel = &cancel});
  EXPECT_EQ(s.code(), ocean::ErrorCode::cancelled);
  EXPECT_EQ(read_bytes(out / "manifest.json"), old_manifest);
  // A merge that stops (a file's place is taken by a directory) removes the old manifest first,
  // leaves "complete": false with the frames copied whole, and no temporary, lock file or file
  // of the unfinished frame.
  fs::remove(out / "jacobian_c0_f00003.npy");
  fs::create_directory(out / "jacobian_c0_f00003.npy");
  for (const auto& e : fs::directory_iterator(out)) {  // the old bake's files of that frame
    if (e.path().filename().string().find("_f00003") != std::string::npos && !e.is_directory())
      fs::remove(e.path());
  }
  s = bake::merge(dirs, {.output_dir = out});
  EXPECT_EQ(s.code(), ocean::ErrorCode::io_error) << s.message();
  EXPECT_NE(s.message().find("jacobian_c0_f00003.npy"), std::string::npos) << s.message();
  const nlohmann::json m = nlohmann::json::parse(read_bytes(out / "manifest.json"));
  EXPECT_EQ(m["complete"], false);
  EXPECT_EQ(m["frames_written"], 3);
  EXPECT_EQ(m["frames"].size(), 3u);
  EXPECT_FALSE(m.contains("shard"));
  for (const auto& e : fs::directory_iterator(out)) {
    const std::string name = e.path().filename().string();
    EXPECT_EQ(name.find(".tmp-"), std::string::npos) << name;
    EXPECT_NE(name, bake::kLockFileName);
    if (name != "jacobian_c0_f00003.npy") {
      EXPECT_EQ(name.find("_f00003"), std::string::npos) << name << ": of the unfinished frame";
    }
  }
}

}  // namespace
