// What a bake's manifest records for a merge to check: every file's size and CRC-32 (checked here
// against zlib's, the reference implementation) and the start time.
#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

#include "ocean/bake.hpp"
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

}  // namespace
