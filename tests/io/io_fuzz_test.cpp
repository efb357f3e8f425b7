// Fuzz tests for the io readers: truncated and corrupted files never crash and never pass as valid.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "io_test_util.hpp"
#include "support/exr_reader.hpp"
#include "support/npy_reader.hpp"
#include "support/png_reader.hpp"

namespace ocean::io {
namespace {

using test::cat;
using test::read_file;
using test::TempDir;
using test::write_file;
namespace fs = std::filesystem;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::size_t pick(std::mt19937& rng, std::size_t n) {
  return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
}

// Flips 1-3 random bits within the first `limit` bytes; returns the touched offsets.
std::vector<std::size_t> corrupt(std::string& bytes, std::size_t limit, std::mt19937& rng) {
  std::vector<std::size_t> touched;
  const std::size_t flips = 1 + pick(rng, 3);
  for (std::size_t i = 0; i < flips; ++i) {
    const std::size_t at = pick(rng, std::min(limit, bytes.size()));
    bytes[at] = static_cast<char>(bytes[at] ^ (1 << pick(rng, 8)));
    touched.push_back(at);
  }
  return touched;
}

TEST(NpyFuzz, TruncationsAndHeaderCorruptionsAreCleanErrors) {
  TempDir dir;
  const fs::path p = dir.path() / "f.npy";
  const std::vector<float> data = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  const std::size_t shape[2] = {3, 4};
  ASSERT_TRUE(write_npy(p, data.data(), shape).ok());
  const std::string valid = read_file(p);
  ASSERT_EQ(valid.size(), 128U + 48U);
  std::mt19937 rng(20240601);

  for (std::size_t len = 0; len < valid.size(); ++len) {  // every truncation fails
    write_file(p, valid.substr(0, len));
    Result<NpyArray> r = read_npy(p);
    ASSERT_FALSE(r.ok()) << "length " << len;
    EXPECT_EQ(r.status().code(), ErrorCode::invalid_argument) << r.status().message();
    EXPECT_NE(r.status().message().find("cannot read '"), std::string::npos);
  }
  for (int iteration = 0; iteration < 3000; ++iteration) {  // header corruptions
    std::string bytes = valid;
    const std::vector<std::size_t> touched = corrupt(bytes, 128, rng);
    write_file(p, bytes);
    Result<NpyArray> r = read_npy(p);
    if (!r.ok()) {
      EXPECT_EQ(r.status().code(), ErrorCode::invalid_argument) << r.status().message();
      EXPECT_FALSE(r.status().message().empty());
      continue;
    }
    // Success only when the header still means the same: whitespace swapped for whitespace.
    for (const std::size_t at : touched) {
      EXPECT_TRUE(bytes[at] == valid[at] || (is_space(bytes[at]) && is_space(valid[at])))
          << "offset " << at << " byte " << int{static_cast<unsigned char>(bytes[at])};
    }
    EXPECT_EQ(r.value().shape, (std::vector<std::size_t>{3, 4}));
    EXPECT_EQ(r.value().data, data);
  }
  for (int iteration = 0; iteration < 500; ++iteration) {  // garbage, with or without magic
    std::string bytes(pick(rng, 300), '\0');
    for (char& c : bytes) c = static_cast<char>(pick(rng, 256));
    if (iteration % 2 == 0) bytes = valid.substr(0, 10) + bytes;
    write_file(p, bytes);
    EXPECT_FALSE(read_npy(p).ok());
  }
}

TEST(PngFuzz, TruncationsAndCorruptionsAreCleanErrors) {
  TempDir dir;
  const fs::path p = dir.path() / "f.png";
  std::vector<std::uint8_t> px(24 * 10 * 3);
  for (std::size_t i = 0; i < px.size(); ++i) px[i] = static_cast<std::uint8_t>(i * 7);
  ASSERT_TRUE(write_png8(p, 24, 10, 3, px.data()).ok());
  const std::string valid = read_file(p);
  const std::vector<std::uint16_t> expected(px.begin(), px.end());
  std::mt19937 rng(7);
  for (std::size_t len = 0; len < valid.size(); ++len) {
    write_file(p, valid.substr(0, len));
    Result<PngImage> r = read_png(p);
    ASSERT_FALSE(r.ok()) << "length " << len;
    EXPECT_EQ(r.status().code(), ErrorCode::io_error);
  }
  for (int iteration = 0; iteration < 1000; ++iteration) {
    std::string bytes = valid;
    corrupt(bytes, bytes.size(), rng);
    write_file(p, bytes);
    Result<PngImage> r = read_png(p);
    // Every chunk is CRC-protected; anything that still decodes must decode to the same image.
    if (r.ok()) {
      EXPECT_EQ(r.value().samples, expected);
    }
  }
}

TEST(ExrFuzz, TruncationsAndCorruptionsNeverCrash) {
  TempDir dir;
  const fs::path p = dir.path() / "f.exr";
  std::vector<float> a(20 * 12), b(20 * 12);
  for (std::size_t i = 0; i < a.size(); ++i) {
    a[i] = static_cast<float>(i) * 0.25f;
    b[i] = -static_cast<float>(i);
  }
  const ExrChannel channels[] = {{"a", a.data()}, {"b", b.data()}};
  const Status written = write_exr(p, 20, 12, channels, ExrPixelType::half);
  ASSERT_TRUE(written.ok()) << written.message();
  const std::string valid = read_file(p);
  std::mt19937 rng(11);
  for (std::size_t len = 0; len < valid.size(); len += 1 + len / 16) {
    write_file(p, valid.substr(0, len));
    Result<ExrImage> r = read_exr(p);
    EXPECT_FALSE(r.ok()) << "length " << len;
    if (!r.ok()) {
      EXPECT_EQ(r.status().code(), ErrorCode::io_error);
    }
  }
  for (int iteration = 0; iteration < 400; ++iteration) {
    std::string bytes = valid;
    corrupt(bytes, bytes.size(), rng);
    write_file(p, bytes);
    Result<ExrImage> r = read_exr(p);
    if (!r.ok()) continue;  // OpenEXR has no checksums: some corruptions go unnoticed
    const ExrImage& im = r.value();
    ASSERT_EQ(im.planes.size(), im.channel_names.size());
    for (const auto& plane : im.planes) {
      EXPECT_EQ(plane.size(),
                static_cast<std::size_t>(im.width) * static_cast<std::size_t>(im.height));
    }
  }
}

}  // namespace
}  // namespace ocean::io
