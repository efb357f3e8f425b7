// What a merge (ocean::bake::merge) checks before it writes anything, against shards a careless
// or hostile hand has changed: every manifest records each file's size and CRC-32 (checked here
// against zlib's, the reference implementation); a frame file or a manifest that is a symbolic
// link, a FIFO, a device, a socket or a directory is refused without being opened for reading; a
// file whose size or CRC-32 is not its manifest's, or a manifest of the older format without
// them, is refused; shards that differ in any entry that changes the frames are refused, naming
// the entry and both values; a manifest is read under its size limit. Every refusal is one line,
// names the shard, and leaves the output folder unmade.
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>
#include <zlib.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "ocean/bake.hpp"
#include "ocean/waves.hpp"
#include "support/temp_dir.hpp"

namespace {

namespace fs = std::filesystem;
namespace bake = ocean::bake;

using ocean_test::TempDir;
using CheckedJson = nlohmann::ordered_json;

std::string checks_read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void checks_write(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary | std::ios::trunc) << text;
}

CheckedJson checks_manifest(const fs::path& dir) {
  return CheckedJson::parse(checks_read(dir / "manifest.json"));
}

// The CRC-32 of a file's bytes as zlib computes it (the same as Python's zlib.crc32), in the
// manifest's form: eight lower-case hexadecimal digits.
std::string zlib_crc32_hex(const std::string& bytes) {
  const uLong crc = crc32(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(bytes.data()),
                          static_cast<uInt>(bytes.size()));
  char text[16];
  std::snprintf(text, sizeof text, "%08lx", static_cast<unsigned long>(crc));
  return text;
}

ocean::SimulationConfig checks_config(std::uint64_t seed = 5) {
  ocean::SimulationConfig c;
  c.resolution = 16;
  c.cascade_patch_sizes_m = {200};
  c.seed = seed;
  return c;
}

// Five frames at 2 fps from 0.25 s: shard 1 of 3 holds frames 1 and 2, shard 2 frames 3 and 4.
bake::BakeParams checks_params(const fs::path& dir, std::optional<bake::Shard> shard) {
  return {.output_dir = dir,
          .formats = {.npy = true},
          .frame_count = 5,
          .fps = 2,
          .start_time_s = 0.25,
          .shard = shard};
}

// Bakes shards 0..2 of checks_config() into root/s<i>.
std::vector<fs::path> checks_bake_shards(const fs::path& root) {
  std::vector<fs::path> dirs;
  for (long long i = 0; i < 3; ++i) {
    dirs.push_back(root / ("s" + std::to_string(i)));
    const ocean::Status s =
        bake::bake(checks_config(), "cpu", checks_params(dirs.back(), bake::Shard{i, 3}));
    EXPECT_TRUE(s.ok()) << s.message();
  }
  return dirs;
}

// Merges `shards` into `out` and expects a refusal with `code` whose one-line message holds
// `fragment`, the output folder not made.
void expect_merge_refused(const std::vector<fs::path>& shards, const fs::path& out,
                          ocean::ErrorCode code, const std::string& fragment) {
  const ocean::Status s = bake::merge(shards, {.output_dir = out});
  EXPECT_EQ(s.code(), code) << s.message();
  EXPECT_NE(s.message().find(fragment), std::string::npos)
      << "expected: " << fragment << "\ngot:      " << s.message();
  EXPECT_EQ(s.message().find('\n'), std::string::npos) << s.message();
  EXPECT_FALSE(fs::exists(out)) << "nothing is written before every check passed";
}

// While alive, opens a FIFO for writing (and closes it) if the test is still blocked on it after
// a few seconds, so that a reader that waits for a writer fails the test instead of hanging it.
class FifoUnblocker {
 public:
  explicit FifoUnblocker(fs::path fifo)
      : fifo_(std::move(fifo)), thread_([this] {
          std::unique_lock<std::mutex> lock(mutex_);
          if (cv_.wait_for(lock, std::chrono::seconds(5), [this] { return done_; })) return;
          const int fd = ::open(fifo_.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
          if (fd >= 0) ::close(fd);
        }) {}
  ~FifoUnblocker() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    cv_.notify_one();
    thread_.join();
  }
  FifoUnblocker(const FifoUnblocker&) = delete;
  FifoUnblocker& operator=(const FifoUnblocker&) = delete;

 private:
  fs::path fifo_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool done_ = false;
  std::thread thread_;
};

TEST(BakeMergeChecks, EveryManifestRecordsEachFilesSizeAndCrc32) {
  TempDir root("bake_checks_sums_");
  const fs::path whole = root.path / "whole", shard = root.path / "shard";
  ASSERT_TRUE(bake::bake(checks_config(), "cpu", checks_params(whole, {})).ok());
  bake::BakeParams p = checks_params(shard, bake::Shard{1, 3});
  p.formats = {.npy = true, .png = true, .exr = true};
  ASSERT_TRUE(bake::bake(checks_config(), "cpu", p).ok());
  for (const fs::path& dir : {whole, shard}) {
    const CheckedJson m = checks_manifest(dir);
    ASSERT_TRUE(m.contains("start_time_s")) << dir;
    EXPECT_EQ(m["start_time_s"], 0.25);
    ASSERT_GE(m["frames"].size(), 2u);
    for (const CheckedJson& frame : m["frames"]) {
      ASSERT_TRUE(frame.contains("bytes") && frame.contains("crc32")) << frame.dump();
      ASSERT_EQ(frame["bytes"].size(), frame["files"].size());
      ASSERT_EQ(frame["crc32"].size(), frame["files"].size());
      for (std::size_t i = 0; i < frame["files"].size(); ++i) {
        const std::string bytes = checks_read(dir / frame["files"][i].get<std::string>());
        EXPECT_EQ(frame["bytes"][i], bytes.size()) << frame["files"][i];
        EXPECT_EQ(frame["crc32"][i], zlib_crc32_hex(bytes)) << frame["files"][i];
      }
    }
  }
}

TEST(BakeMergeChecks, RefusesALinkOrASpecialFileInPlaceOfAFrameFile) {
  TempDir root("bake_checks_special_");
  const std::vector<fs::path> dirs = checks_bake_shards(root.path);
  const fs::path out = root.path / "out";
  const std::string name = "foam_c0_f00002.npy";
  const fs::path file = dirs[1] / name;
  const std::string shard = "shard 1 of 3 in '" + dirs[1].string() + "': '" + name + "' is ";
  const auto refused = [&](const std::string& what) {
    expect_merge_refused(dirs, out, ocean::ErrorCode::invalid_argument, shard + what);
  };
  // A link to the very bytes the manifest lists is refused all the same: never followed.
  fs::rename(file, dirs[1] / "foam_copy.npy");
  fs::create_symlink("foam_copy.npy", file);
  refused("a symbolic link");
  fs::remove(file);
  fs::create_symlink("/dev/zero", file);
  refused("a symbolic link");
  fs::remove(file);
  ASSERT_EQ(::mkfifo(file.c_str(), 0644), 0);
  {
    const FifoUnblocker unblock(file);
    refused("a FIFO, not a regular file");
  }
  fs::remove(file);
  fs::create_directory(file);
  refused("a directory, not a regular file");
  fs::remove(file);
  {
    const int sock = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    ASSERT_GE(sock, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    ASSERT_LT(file.string().size(), sizeof address.sun_path);
    std::strcpy(address.sun_path, file.c_str());
    ASSERT_EQ(::bind(sock, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
    refused("a socket, not a regular file");
    ::close(sock);
    fs::remove(file);
  }
  if (::geteuid() == 0) {  // making a device node needs root (CI runs the tests as root)
    ASSERT_EQ(::mknod(file.c_str(), S_IFCHR | 0644, makedev(1, 5)), 0);  // as /dev/zero
    refused("a character device, not a regular file");
    fs::remove(file);
  }
  fs::rename(dirs[1] / "foam_copy.npy", file);
  const ocean::Status s = bake::merge(dirs, {.output_dir = out});
  EXPECT_TRUE(s.ok()) << s.message();
}

TEST(BakeMergeChecks, RefusesAManifestThatIsALinkASpecialFileOrTooLarge) {
  TempDir root("bake_checks_manifest_");
  const std::vector<fs::path> dirs = checks_bake_shards(root.path);
  const fs::path out = root.path / "out";
  const fs::path manifest = dirs[1] / "manifest.json";
  const std::string cannot = "cannot read manifest '" + manifest.string() + "': ";
  fs::rename(manifest, dirs[1] / "manifest.copy");
  fs::create_symlink("manifest.copy", manifest);
  expect_merge_refused(dirs, out, ocean::ErrorCode::io_error, cannot + "it is a symbolic link");
  fs::remove(manifest);
  fs::create_symlink("/dev/zero", manifest);
  expect_merge_refused(dirs, out, ocean::ErrorCode::io_error, cannot + "it is a symbolic link");
  fs::remove(manifest);
  ASSERT_EQ(::mkfifo(manifest.c_str(), 0644), 0);
  {
    const FifoUnblocker unblock(manifest);
    const auto start = std::chrono::steady_clock::now();
    expect_merge_refused(dirs, out, ocean::ErrorCode::io_error,
                         cannot + "it is a FIFO, not a regular file");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(4))
        << "a FIFO is refused at once, not waited on";
  }
  fs::remove(manifest);
  fs::create_directory(manifest);
  expect_merge_refused(dirs, out, ocean::ErrorCode::io_error,
                       cannot + "it is a directory, not a regular file");
  fs::remove(manifest);
  // 100 MB (sparse): refused after reading at most the limit and one byte.
  checks_write(manifest, "");
  fs::resize_file(manifest, 100'000'000);
  expect_merge_refused(dirs, out, ocean::ErrorCode::invalid_argument,
                       "manifest '" + manifest.string() +
                           "' is larger than 67108864 bytes (64 MiB), the most a manifest may "
                           "hold");
  fs::remove(manifest);
  fs::rename(dirs[1] / "manifest.copy", manifest);
  const ocean::Status s = bake::merge(dirs, {.output_dir = out});
  EXPECT_TRUE(s.ok()) << s.message();
}

TEST(BakeMergeChecks, RefusesAFileWhoseSizeOrCrc32IsNotTheManifests) {
  TempDir root("bake_checks_crc_");
  const std::vector<fs::path> dirs = checks_bake_shards(root.path);
  const fs::path out = root.path / "out";
  const std::string name = "jacobian_c0_f00004.npy";
  const fs::path file = dirs[2] / name;
  const std::string good = checks_read(file);
  const std::string shard =
      "cannot merge: shard 2 of 3 in '" + dirs[2].string() + "': '" + name + "' ";
  // One bit flipped in the last value: same size, another CRC-32.
  std::string flipped = good;
  flipped.back() = static_cast<char>(flipped.back() ^ 0x01);
  checks_write(file, flipped);
  expect_merge_refused(dirs, out, ocean::ErrorCode::invalid_argument,
                       shard + "has CRC-32 " + zlib_crc32_hex(flipped) + ", its manifest says " +
                           zlib_crc32_hex(good) +
                           ": the file changed after the bake; bake the shard again");
  checks_write(file, good.substr(0, 100));
  expect_merge_refused(dirs, out, ocean::ErrorCode::invalid_argument,
                       shard + "holds 100 bytes, its manifest says " + std::to_string(good.size()) +
                           ": the file changed after the bake; bake the shard again");
  checks_write(file, good);
  // A manifest of the older format (no start time, no sizes and CRC-32s) is refused whole.
  const std::string manifest = checks_read(dirs[1] / "manifest.json");
  CheckedJson old = CheckedJson::parse(manifest);
  old.erase("start_time_s");
  for (CheckedJson& frame : old["frames"]) {
    frame.erase("bytes");
    frame.erase("crc32");
  }
  checks_write(dirs[1] / "manifest.json", old.dump(2));
  expect_merge_refused(dirs, out, ocean::ErrorCode::invalid_argument,
                       "cannot merge: shard 1 of 3 in '" + dirs[1].string() +
                           "': its manifest records no start time, file sizes or CRC-32s (an "
                           "older ocean wrote it): bake the shard again");
  checks_write(dirs[1] / "manifest.json", manifest);
  const ocean::Status s = bake::merge(dirs, {.output_dir = out});
  EXPECT_TRUE(s.ok()) << s.message();
}

// Shard 1 baked apart with one parameter changed, or its manifest edited, in place of the real
// one: refused, naming the entry and both values ("b vs a").
TEST(BakeMergeChecks, RefusesShardsThatDifferInAnyEntryThatChangesTheFrames) {
  TempDir root("bake_checks_fields_");
  const std::vector<fs::path> dirs = checks_bake_shards(root.path);
  const fs::path out = root.path / "out";
  const fs::path other = root.path / "other";
  const auto differs = [&](const std::string& field) {
    expect_merge_refused({dirs[0], other, dirs[2]}, out, ocean::ErrorCode::invalid_argument,
                         "cannot merge: shard '" + other.string() + "' differs from shard '" +
                             dirs[0].string() + "' in " + field);
  };
  const auto bake_other = [&](const ocean::SimulationConfig& c, const bake::BakeParams& p) {
    fs::remove_all(other);
    const ocean::Status s = bake::bake(c, "cpu", p);
    ASSERT_TRUE(s.ok()) << s.message();
  };
  const bake::BakeParams base = checks_params(other, bake::Shard{1, 3});
  bake::BakeParams p = base;
  p.fps = 3;
  bake_other(checks_config(), p);
  differs("fps (3 vs 2)");
  p = base;
  p.start_time_s = 0.5;
  bake_other(checks_config(), p);
  differs("start_time_s (0.5 vs 0.25)");
  p = base;
  p.frame_count = 6;
  bake_other(checks_config(), p);
  differs("frame_count (6 vs 5)");
  p = base;
  p.formats = {.npy = true, .png = true};
  bake_other(checks_config(), p);
  differs("formats ([\"npy\",\"png\"] vs [\"npy\"])");
  bake_other(checks_config(6), base);
  differs("config.seed (6 vs 5)");
  ocean::SimulationConfig windy = checks_config();
  windy.sea.wind_sea.spectrum.wind_speed_mps = 12.5;
  bake_other(windy, base);
  differs("config.sea.wind_sea.wind_speed_mps (12.5 vs 10)");
  // Entries edited in the manifest of a real shard 1.
  bake_other(checks_config(), base);
  const CheckedJson real = checks_manifest(other);
  const auto edited = [&](const auto& edit) {
    CheckedJson m = real;
    edit(m);
    checks_write(other / "manifest.json", m.dump(2));
  };
  edited([](CheckedJson& m) { m["backend"] = "cuda"; });
  differs("backend (\"cuda\" vs \"cpu\")");
  edited([](CheckedJson& m) { m["height_png_range_m"] = 9.5; });
  differs("height_png_range_m (9.5 vs ");
  edited([](CheckedJson& m) { m["cascades"][0]["resolution"] = 32; });
  differs("cascades[0].resolution (32 vs 16)");
  edited([](CheckedJson& m) { m["calm"] = true; });
  differs("calm (true vs false)");
  edited([](CheckedJson& m) { m["layout"] = "column-major"; });
  differs("layout (\"column-major\" vs ");
  edited([](CheckedJson& m) { m["config"].erase("foam"); });
  differs("config.foam (absent vs {");
  edited([](CheckedJson& m) { m["extra"] = 1; });
  differs("extra (1 vs absent)");
  // A frame at another time than start_time_s + f/fps.
  edited([](CheckedJson& m) { m["frames"][1]["time_s"] = 9.0; });
  expect_merge_refused({dirs[0], other, dirs[2]}, out, ocean::ErrorCode::invalid_argument,
                       "cannot merge: shard 1 of 3 in '" + other.string() +
                           "': frame 2 is at time_s 9, not start_time_s + 2/fps = 1.25");
  // A frame listing the files of another (which would overwrite them in the output).
  edited([](CheckedJson& m) {
    for (const char* key : {"files", "bytes", "crc32"}) m["frames"][1][key] = m["frames"][0][key];
  });
  expect_merge_refused({dirs[0], other, dirs[2]}, out, ocean::ErrorCode::invalid_argument,
                       "cannot merge: shard 1 of 3 in '" + other.string() +
                           "': frame 2 lists 'displacement_c0_f00001.npy', which is not a file "
                           "of frame 2");
  edited([](CheckedJson&) {});
  const std::vector<fs::path> whole{dirs[0], other, dirs[2]};
  const ocean::Status s = bake::merge(whole, {.output_dir = out});
  EXPECT_TRUE(s.ok()) << s.message();
}

// The local layer changes the frames too: its wakes and waveforms are in the manifest.
TEST(BakeMergeChecks, RefusesShardsOfAnotherLocalLayer) {
  TempDir root("bake_checks_layer_");
  const auto layer = [](double speed_mps) {
    ocean::waves::LayerParams lp;
    lp.area = {.origin_m = {-40.0, -40.0}, .size_m = 80.0, .resolution = 16};
    lp.wakes.push_back({.x_m = 20.0, .heading_deg = 180.0, .speed_mps = speed_mps});
    return std::shared_ptr<const ocean::waves::LocalLayer>(
        ocean::waves::LocalLayer::make(lp).value());
  };
  std::vector<fs::path> dirs;
  for (long long i = 0; i < 2; ++i) {
    dirs.push_back(root.path / ("s" + std::to_string(i)));
    bake::BakeParams p = checks_params(dirs.back(), bake::Shard{i, 2});
    p.local_layer = layer(i == 0 ? 4.0 : 6.0);
    const ocean::Status s = bake::bake(checks_config(), "cpu", p);
    ASSERT_TRUE(s.ok()) << s.message();
  }
  expect_merge_refused(dirs, root.path / "out", ocean::ErrorCode::invalid_argument,
                       "cannot merge: shard '" + dirs[1].string() + "' differs from shard '" +
                           dirs[0].string() + "' in local_layer.wakes[0].speed_mps (6 vs 4)");
}

}  // namespace
