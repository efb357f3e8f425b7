// The OpenEXR reader read_exr (ocean/io.hpp) on headers that declare more than they hold or that
// OpenEXR would read differently from their declared sizes: each is refused before OpenEXR reads
// the header and allocates what the declaration asks for. Inputs of this kind were found by the
// fuzz target tests/fuzz/exr_reader_fuzz.cpp (its corpus keeps them).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "io_test_util.hpp"
#include "support/exr_reader.hpp"

namespace ocean::io {
namespace {

using test::read_file;
using test::TempDir;
using test::write_file;

std::string int32_bytes(std::int32_t value) {
  const auto u = static_cast<std::uint32_t>(value);
  std::string bytes(4, '\0');
  for (std::size_t i = 0; i < 4; ++i) bytes[i] = static_cast<char>((u >> (8 * i)) & 0xFFU);
  return bytes;
}

// A one-pixel, one-channel file from write_exr (Y = 0.5).
std::string one_pixel_exr(const std::filesystem::path& path) {
  const float value = 0.5f;
  const ExrChannel channel[] = {{"Y", &value}};
  EXPECT_TRUE(write_exr(path, 1, 1, channel, ExrPixelType::half).ok());
  return read_file(path);
}

// The file with an attribute inserted first in its header: name, type, declared size, value.
// The one-pixel file has one chunk, whose offset (a uint64 after the header) points just past
// itself; it is moved by the bytes inserted.
std::string with_attribute(std::string bytes, const std::string& name, const std::string& type,
                           std::int32_t size, const std::string& value) {
  std::string attribute = name;
  attribute.append(1, '\0').append(type).append(1, '\0').append(int32_bytes(size)).append(value);
  const auto uint64_at = [&](std::size_t at) {
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < 8; ++i)
      v |= std::uint64_t{static_cast<unsigned char>(bytes[at + i])} << (8 * i);
    return v;
  };
  std::size_t table = 8;
  while (table + 8 <= bytes.size() && uint64_at(table) != table + 8) ++table;
  EXPECT_LT(table + 8, bytes.size()) << "no chunk offset found";
  const std::uint64_t moved = uint64_at(table) + attribute.size();
  for (std::size_t i = 0; i < 8; ++i)
    bytes[table + i] = static_cast<char>((moved >> (8 * i)) & 0xFFU);
  return bytes.insert(8, attribute);  // after the magic number and the version word
}

Result<ExrImage> read_back(const TempDir& dir, const std::string& bytes) {
  const auto path = dir.path() / "edited.exr";
  write_file(path, bytes);
  return read_exr(path);
}

void expect_refused(const Result<ExrImage>& image, const std::string& needle) {
  ASSERT_FALSE(image.ok());
  EXPECT_EQ(image.status().code(), ErrorCode::io_error);
  EXPECT_NE(image.status().message().find(needle), std::string::npos) << image.status().message();
}

// OpenEXR 3.1 allocates an unknown attribute's declared size before reading it: 2 GiB for a file
// of 300 bytes, and seconds spent filling it under AddressSanitizer.
TEST(ExrReaderLimits, AttributeLargerThanTheFileIsRefused) {
  TempDir dir;
  const std::string file = one_pixel_exr(dir.path() / "a.exr");
  expect_refused(read_back(dir, with_attribute(file, "note", "opaque", 0x7fffffff, "abcd")),
                 "header attribute 'note' declares 2147483647 bytes, more than the file holds");
  expect_refused(read_back(dir, with_attribute(file, "note", "opaque", -1, "")),
                 "header attribute 'note' declares -1 bytes");
}

// OpenEXR reads a channel list up to its empty name, whatever its declared size: a size that
// disagrees puts OpenEXR's reading and the size out of step, and the bytes OpenEXR then takes
// for the next attribute's size are arbitrary.
TEST(ExrReaderLimits, ChannelListWhoseSizeDisagreesIsRefused) {
  TempDir dir;
  std::string file = one_pixel_exr(dir.path() / "a.exr");
  const std::string channels("channels\0chlist\0", 16);
  const std::size_t at = file.find(channels);
  ASSERT_NE(at, std::string::npos);
  // One channel "Y": its name, 16 bytes of fields, the list's empty name.
  ASSERT_EQ(file.substr(at + channels.size(), 4), int32_bytes(19));
  file.replace(at + channels.size(), 4, int32_bytes(20));
  expect_refused(read_back(dir, file),
                 "header attribute 'channels' of type 'chlist' declares 20 bytes, not 19");
}

TEST(ExrReaderLimits, FixedSizeTypeWithAnotherSizeIsRefused) {
  TempDir dir;
  const std::string file = one_pixel_exr(dir.path() / "a.exr");
  expect_refused(read_back(dir, with_attribute(file, "exposure", "float", 8, "abcdefgh")),
                 "header attribute 'exposure' of type 'float' declares 8 bytes, not 4");
}

// The data window is checked before OpenEXR (and the reader) size buffers from it: a file of a
// few hundred bytes declaring 16384 x 16384 pixels of two channels asks for 2 GiB of floats.
TEST(ExrReaderLimits, DataWindowBeyondTheSampleBudgetIsRefused) {
  TempDir dir;
  const float values[2] = {0.5f, 0.25f};
  const ExrChannel channels[] = {{"A", &values[0]}, {"B", &values[1]}};
  const auto path = dir.path() / "a.exr";
  ASSERT_TRUE(write_exr(path, 1, 1, channels, ExrPixelType::half).ok());
  std::string file = read_file(path);
  const std::string window("dataWindow\0box2i\0", 17);
  const std::size_t at = file.find(window);
  ASSERT_NE(at, std::string::npos);
  const std::size_t max_x = at + window.size() + 4 + 8;  // after the size, min.x and min.y
  file.replace(max_x, 8, int32_bytes(16383) + int32_bytes(16383));
  expect_refused(read_back(dir, file), "image is too large to read (more than 1 GiB of samples)");
  file.replace(max_x, 8, int32_bytes(16384) + int32_bytes(0));
  expect_refused(read_back(dir, file), "data window 16385x1 is out of range [1, 16384]");
}

// Rows are read in blocks of 256: an image of several blocks comes back bit-exact.
TEST(ExrReaderLimits, ImagesOfSeveralRowBlocksRoundTrip) {
  TempDir dir;
  const int w = 3, h = 600;
  std::vector<float> values(static_cast<std::size_t>(w * h));
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<float>(i) * 0.5f - 7.0f;
  const ExrChannel channel[] = {{"Z", values.data()}};
  const auto path = dir.path() / "tall.exr";
  ASSERT_TRUE(write_exr(path, w, h, channel, ExrPixelType::float32).ok());
  const Result<ExrImage> image = read_exr(path);
  ASSERT_TRUE(image.ok()) << image.status().message();
  EXPECT_EQ(image.value().width, w);
  EXPECT_EQ(image.value().height, h);
  ASSERT_EQ(image.value().planes.size(), 1u);
  EXPECT_EQ(image.value().planes[0], values);
}

// What OpenEXR reads as exactly the declared size is read on.
TEST(ExrReaderLimits, AttributesThatFitAreRead) {
  TempDir dir;
  std::string file = one_pixel_exr(dir.path() / "a.exr");
  file = with_attribute(file, "note", "opaque", 4, "abcd");
  file = with_attribute(file, "owner", "string", 5, "ocean");
  file = with_attribute(file, "exposure", "float", 4, int32_bytes(0));
  const Result<ExrImage> image = read_back(dir, file);
  ASSERT_TRUE(image.ok()) << image.status().message();
  ASSERT_EQ(image.value().planes.size(), 1u);
  EXPECT_EQ(image.value().planes[0][0], 0.5f);
}

// OpenEXR reads tiled files through buffers of whole tiles, sized from the "tiles" attribute: a
// tile of 4 × 67131648 pixels on an 8×8 image made it allocate 2 GiB (the library's height map
// fuzz target; the OpenEXR fuzz target had hidden it by setting OpenEXR's own tile limit).
TEST(ExrReaderLimits, TilesBeyondTheSampleBudgetAreRefused) {
  TempDir dir;
  const std::string file = one_pixel_exr(dir.path() / "a.exr");
  const auto tiledesc = [](std::int32_t x, std::int32_t y) {
    return int32_bytes(x) + int32_bytes(y) + std::string(1, '\0');
  };
  expect_refused(
      read_back(dir, with_attribute(file, "tiles", "tiledesc", 9, tiledesc(4, 67131648))),
      "tiles of 4x67131648 would need more than 1 GiB of samples to read");
  expect_refused(read_back(dir, with_attribute(file, "tiles", "tiledesc", 9, tiledesc(0, 16))),
                 "tiles of 0x16");
  expect_refused(
      read_back(dir, with_attribute(file, "tiles", "tiledesc", 9, tiledesc(16384, 16385))),
      "tiles of 16384x16385");
}

// The whole file is read for the header check under a stated limit: what is not a regular
// file (/dev/zero, a FIFO with no writer) and a file larger than the limit (a sparse one here: no
// disk used) are refused before a byte is read, each naming the file and the limit.
TEST(ExrReaderLimits, WhatIsNotARegularFileWithinTheLimitIsRefusedAtOnce) {
  TempDir dir;
  static_assert(kExrMaxFileBytes == std::uint64_t{2} << 30, "the messages below state 2 GiB");
  const std::string limit = "2147483648 bytes (2 GiB)";
  const std::filesystem::path fifo = dir.path() / "fifo.exr";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::filesystem::path huge = dir.path() / "huge.exr";
  { std::ofstream create(huge); }
  ASSERT_EQ(::truncate(huge.c_str(), (std::int64_t{2} << 30) + 1), 0);
  const std::pair<std::filesystem::path, std::string> cases[] = {
      {"/dev/zero",
       "cannot read '/dev/zero': it is a character device, not a regular file; an "
       "OpenEXR file is read whole, at most " +
           limit},
      {fifo, "cannot read '" + fifo.string() +
                 "': it is a FIFO, not a regular file; an OpenEXR file is read whole, at most " +
                 limit},
      {huge, "cannot read '" + huge.string() + "': it holds 2147483649 bytes, more than the " +
                 limit + " an OpenEXR file may hold"}};
  for (const auto& [path, message] : cases) {
    const Result<ExrImage> image = read_exr(path);
    ASSERT_FALSE(image.ok()) << path;
    EXPECT_EQ(image.status().code(), ErrorCode::io_error) << path;
    EXPECT_EQ(image.status().message(), message);
  }
}

}  // namespace
}  // namespace ocean::io
