// The PNG readers (the test reader of tests/support and, through the same chunk walk of
// src/io/png_detail.hpp, the height map reader) on chunks that declare more than the file holds
// or more than the readers' limit: refused before libpng allocates what the chunk declares.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "io_test_util.hpp"
#include "ocean/io.hpp"
#include "support/png_reader.hpp"

namespace ocean::io {
namespace {

using test::read_file;
using test::TempDir;
using test::write_file;

// A 1×1 grayscale PNG whose ancillary chunk after IHDR ('sBIP', 10 bytes) is followed by an
// 'sPLT' chunk declaring 0x73424954 = 1933723988 bytes: libpng allocated that much before
// reading (found by tests/fuzz/png_reader_fuzz.cpp, libFuzzer's out-of-memory limit).
const unsigned char kDeclares2GB[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
    0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x00, 0x00, 0x00,
    0x00, 0x3a, 0x7e, 0x9b, 0x55, 0x00, 0x00, 0x00, 0x0a, 0x73, 0x42, 0x49, 0x50, 0x4c,
    0x54, 0x45, 0x54, 0x49, 0x44, 0x41, 0x54, 0x08, 0x99, 0x00, 0x8b, 0x00, 0xc9, 0x73,
    0x42, 0x49, 0x54, 0x73, 0x50, 0x4c, 0x54, 0x45, 0x42, 0x49, 0x54};

std::string big_endian(std::uint32_t v) {
  return {static_cast<char>(v >> 24U), static_cast<char>((v >> 16U) & 0xFFU),
          static_cast<char>((v >> 8U) & 0xFFU), static_cast<char>(v & 0xFFU)};
}

// A 2×2 gray PNG from write_png8 with `chunk` inserted after IHDR (signature 8 + IHDR 25 bytes).
std::string with_chunk_after_ihdr(const TempDir& dir, const std::string& chunk) {
  const std::uint8_t pixels[4] = {0, 64, 128, 255};
  const auto path = dir.path() / "plain.png";
  EXPECT_TRUE(write_png8(path, 2, 2, 1, pixels).ok());
  std::string bytes = read_file(path);
  return bytes.insert(33, chunk);
}

Result<PngImage> read_bytes(const TempDir& dir, const std::string& bytes) {
  const auto path = dir.path() / "edited.png";
  write_file(path, bytes);
  return read_png(path);
}

void expect_refused(const Result<PngImage>& image, const std::string& needle) {
  ASSERT_FALSE(image.ok());
  EXPECT_NE(image.status().message().find(needle), std::string::npos) << image.status().message();
}

TEST(PngReaderLimits, ChunkLargerThanTheFileIsRefused) {
  TempDir dir;
  expect_refused(read_bytes(dir, std::string(reinterpret_cast<const char*>(kDeclares2GB),
                                             sizeof kDeclares2GB)),
                 "chunk 'sPLT' declares 1933723988 bytes, more than the file holds");
}

TEST(PngReaderLimits, AncillaryChunkOverTheLimitIsRefusedNamingIt) {
  TempDir dir;
  const std::uint32_t length = kPngMaxChunkBytes + 1;
  std::string chunk = big_endian(length) + "zTXt";
  chunk.append(length, 'a').append(4, '\0');  // data, CRC (never checked: refused before)
  const Result<PngImage> image = read_bytes(dir, with_chunk_after_ihdr(dir, chunk));
  expect_refused(image,
                 "chunk 'zTXt' declares 8388609 bytes, more than the reader's limit of "
                 "8388608 bytes (8 MiB)");
  EXPECT_NE(image.status().message().find("edited.png"), std::string::npos);
}

TEST(PngReaderLimits, ChunkTypeThatIsNotFourLettersIsRefused) {
  TempDir dir;
  const std::string chunk = big_endian(0) + std::string("a\0bc", 4) + big_endian(0);
  expect_refused(read_bytes(dir, with_chunk_after_ihdr(dir, chunk)),
                 "a chunk type is not four letters");
}

TEST(PngReaderLimits, SpecialFilesAreRefused) {
  expect_refused(read_png("/dev/zero"), "it is not a regular file");
}

TEST(PngReaderLimits, FilesWithinTheLimitsStillRead) {
  TempDir dir;
  const std::uint8_t pixels[4] = {0, 64, 128, 255};
  const auto path = dir.path() / "plain.png";
  ASSERT_TRUE(write_png8(path, 2, 2, 1, pixels).ok());
  const Result<PngImage> image = read_png(path);
  ASSERT_TRUE(image.ok()) << image.status().message();
  EXPECT_EQ(image.value().samples, (std::vector<std::uint16_t>{0, 64, 128, 255}));
}

}  // namespace
}  // namespace ocean::io
