// Tests for the io module's image files: OpenEXR (half and float) and PNG (8-bit, 16-bit gray).
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cmath>
#include <csignal>
#include <cstring>
#include <functional>
#include <limits>
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

void expect_image_error(const Status& s, ErrorCode code, const std::string& needle) {
  EXPECT_EQ(s.code(), code) << s.message();
  EXPECT_NE(s.message().find(needle), std::string::npos) << s.message();
}

// A smooth but non-trivial test pattern; differs per channel so swaps are caught.
std::vector<float> pattern(int w, int h, float scale) {
  std::vector<float> v(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  for (std::size_t i = 0; i < v.size(); ++i) {
    v[i] = scale * std::sin(0.1f * static_cast<float>(i)) + 0.001f * static_cast<float>(i);
  }
  return v;
}

// ---- OpenEXR --------------------------------------------------------------------------------

TEST(Exr, FloatRoundTripIsBitExact) {
  TempDir dir;
  const int w = 37, h = 19;  // not square: catches transposed rows and columns
  std::vector<float> height = pattern(w, h, 3.0f), foam = pattern(w, h, -0.5f);
  height[0] = std::numeric_limits<float>::quiet_NaN();
  height[1] = -0.0f;
  const ExrChannel channels[] = {{"height", height.data()}, {"foam", foam.data()}};
  const fs::path p = dir.path() / "f.exr";
  const Status written = write_exr(p, w, h, channels, ExrPixelType::float32);
  ASSERT_TRUE(written.ok()) << written.message();
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"f.exr"});
  Result<ExrImage> r = read_exr(p);
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_EQ(r.value().width, w);
  EXPECT_EQ(r.value().height, h);
  // OpenEXR orders channels by name.
  EXPECT_EQ(r.value().channel_names, (std::vector<std::string>{"foam", "height"}));
  EXPECT_EQ(r.value().pixel_types,
            (std::vector<ExrPixelType>{ExrPixelType::float32, ExrPixelType::float32}));
  ASSERT_EQ(r.value().planes.size(), 2U);
  EXPECT_EQ(std::memcmp(r.value().planes[0].data(), foam.data(), foam.size() * 4), 0);
  EXPECT_EQ(std::memcmp(r.value().planes[1].data(), height.data(), height.size() * 4), 0);

  // ZIP compression: the "compression" attribute holds ZIP_COMPRESSION = 3.
  const std::string bytes = read_file(p);
  const std::string attr("compression\0compression\0\x01\0\0\0", 28);
  const std::size_t at = bytes.find(attr);
  ASSERT_NE(at, std::string::npos);
  EXPECT_EQ(bytes[at + attr.size()], 3);
}

TEST(Exr, HalfRoundTripIsWithinHalfPrecision) {
  TempDir dir;
  const int w = 16, h = 9;
  std::vector<float> v = pattern(w, h, 100.0f);
  v[0] = 1e6f;   // beyond half range
  v[1] = 1e-6f;  // subnormal in half
  const ExrChannel channels[] = {{"Y", v.data()}};
  const fs::path p = dir.path() / "h.exr";
  const Status written = write_exr(p, w, h, channels, ExrPixelType::half);
  ASSERT_TRUE(written.ok()) << written.message();
  Result<ExrImage> r = read_exr(p);
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_EQ(r.value().pixel_types, std::vector<ExrPixelType>{ExrPixelType::half});
  const std::vector<float>& got = r.value().planes.at(0);
  EXPECT_TRUE(std::isinf(got[0]));
  for (std::size_t i = 1; i < v.size(); ++i) {
    // Half has an 11-bit significand: relative error <= 2^-11; subnormals step 2^-24.
    EXPECT_NEAR(got[i], v[i], std::abs(v[i]) * 0x1p-11f + 0x1p-25f) << i;
  }
}

TEST(Exr, RejectsBadInputsAndWritesNothing) {
  TempDir dir;
  const fs::path p = dir.path() / "bad.exr";
  const std::vector<float> v(16, 1.0f);
  const ExrChannel one[] = {{"R", v.data()}};
  expect_image_error(write_exr(p, 0, 4, one, ExrPixelType::half), ErrorCode::invalid_argument, "0x4");
  expect_image_error(write_exr(p, 16385, 1, one, ExrPixelType::half), ErrorCode::invalid_argument,
               "16384");
  expect_image_error(write_exr(p, 4, 4, {}, ExrPixelType::half), ErrorCode::invalid_argument,
               "0 channels");
  const ExrChannel null_data[] = {{"R", nullptr}};
  expect_image_error(write_exr(p, 4, 4, null_data, ExrPixelType::half), ErrorCode::invalid_argument,
               "null");
  const ExrChannel dup[] = {{"R", v.data()}, {"R", v.data()}};
  expect_image_error(write_exr(p, 4, 4, dup, ExrPixelType::half), ErrorCode::invalid_argument, "twice");
  const ExrChannel unnamed[] = {{"", v.data()}};
  expect_image_error(write_exr(p, 4, 4, unnamed, ExrPixelType::half), ErrorCode::invalid_argument,
               "name");
  const ExrChannel long_name[] = {{std::string(256, 'x'), v.data()}};
  expect_image_error(write_exr(p, 4, 4, long_name, ExrPixelType::float32), ErrorCode::invalid_argument,
               "255");
  EXPECT_TRUE(dir.entries().empty());
  const fs::path missing = dir.path() / "no" / "x.exr";
  expect_image_error(write_exr(missing, 4, 4, one, ExrPixelType::half), ErrorCode::io_error,
               cat("cannot write '", missing.string(), "': No such file or directory"));
  EXPECT_TRUE(dir.entries().empty());
  // A directory in the way: io_error, no temporary left behind.
  fs::create_directory(dir.path() / "d.exr");
  EXPECT_EQ(write_exr(dir.path() / "d.exr", 4, 4, one, ExrPixelType::half).code(),
            ErrorCode::io_error);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"d.exr"});
}

TEST(Exr, ReaderRejectsNonExrFiles) {
  TempDir dir;
  expect_image_error(read_exr(dir.path() / "none.exr").status(), ErrorCode::io_error,
               "No such file or directory");
  write_file(dir.path() / "t.exr", "plain text, not an image");
  expect_image_error(read_exr(dir.path() / "t.exr").status(), ErrorCode::io_error, "wrong magic");
  write_file(dir.path() / "m.exr", std::string("\x76\x2f\x31\x01\x02\0\0\0", 8));
  expect_image_error(read_exr(dir.path() / "m.exr").status(), ErrorCode::io_error, "m.exr");
}

// ---- PNG --------------------------------------------------------------------------------------

TEST(Png, EightBitRoundTripsAreExactForAllChannelCounts) {
  TempDir dir;
  const int w = 13, h = 7;
  for (int c = 1; c <= 4; ++c) {
    std::vector<std::uint8_t> px(static_cast<std::size_t>(w * h * c));
    for (std::size_t i = 0; i < px.size(); ++i) px[i] = static_cast<std::uint8_t>(i * 37 + 11);
    const fs::path p = dir.path() / (cat("c", std::to_string(c), ".png"));
    ASSERT_TRUE(write_png8(p, w, h, c, px.data()).ok());
    Result<PngImage> r = read_png(p);
    ASSERT_TRUE(r.ok()) << r.status().message();
    EXPECT_EQ(r.value().width, w);
    EXPECT_EQ(r.value().height, h);
    EXPECT_EQ(r.value().channels, c);
    EXPECT_EQ(r.value().bit_depth, 8);
    EXPECT_EQ(r.value().samples, std::vector<std::uint16_t>(px.begin(), px.end()));
  }
  EXPECT_EQ(dir.entries().size(), 4U);  // no temporaries
}

TEST(Png, SixteenBitGrayRoundTripIsExact) {
  TempDir dir;
  const int w = 300, h = 5;
  std::vector<std::uint16_t> px(static_cast<std::size_t>(w * h));
  for (std::size_t i = 0; i < px.size(); ++i) px[i] = static_cast<std::uint16_t>(i * 4099 + 7);
  px[0] = 0;
  px[1] = 65535;
  px[2] = 0x0102;  // byte order matters
  const fs::path p = dir.path() / "g16.png";
  ASSERT_TRUE(write_png16_gray(p, w, h, px.data()).ok());
  Result<PngImage> r = read_png(p);
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_EQ(r.value().channels, 1);
  EXPECT_EQ(r.value().bit_depth, 16);
  EXPECT_EQ(r.value().samples, px);
  // IHDR: bit depth 16, colour type 0 (gray).
  const std::string bytes = read_file(p);
  EXPECT_EQ(bytes.substr(12, 4), "IHDR");
  EXPECT_EQ(bytes[24], 16);
  EXPECT_EQ(bytes[25], 0);
}

TEST(Png, RejectsBadInputsAndNonPngFiles) {
  TempDir dir;
  const fs::path p = dir.path() / "x.png";
  const std::uint8_t px[64] = {};
  expect_image_error(write_png8(p, 4, 4, 0, px), ErrorCode::invalid_argument, "channels = 0");
  expect_image_error(write_png8(p, 4, 4, 5, px), ErrorCode::invalid_argument, "channels = 5");
  expect_image_error(write_png8(p, 0, 4, 1, px), ErrorCode::invalid_argument, "0x4");
  expect_image_error(write_png8(p, 4, 4, 1, nullptr), ErrorCode::invalid_argument, "null");
  expect_image_error(write_png16_gray(p, 4, -1, nullptr), ErrorCode::invalid_argument, "4x-1");
  EXPECT_TRUE(dir.entries().empty());
  const fs::path missing = dir.path() / "no" / "x.png";
  expect_image_error(write_png8(missing, 4, 4, 1, px), ErrorCode::io_error,
               cat("cannot write '", missing.string(), "': No such file or directory"));
  EXPECT_TRUE(dir.entries().empty());
  write_file(p, "GIF89a not a png at all");
  expect_image_error(read_png(p).status(), ErrorCode::io_error, cat("cannot read '", p.string(), "'"));
  expect_image_error(read_png(dir.path() / "none.png").status(), ErrorCode::io_error,
               "No such file or directory");
  expect_image_error(read_png(dir.path()).status(), ErrorCode::io_error, "cannot read");
}

// A file size limit makes writes fail with EFBIG midway (including the writes OpenEXR performs
// in OutputFile's destructor): every writer reports it and leaves the old file in place.
TEST(WriteErrors, FailingWritesAreReportedAndKeepTheOldFile) {
  TempDir dir;
  std::mt19937 rng(3);
  std::vector<float> noise(256 * 256);  // incompressible
  for (float& v : noise) v = std::uniform_real_distribution<float>(-1, 1)(rng);
  const std::size_t shape[1] = {noise.size()};
  const ExrChannel channels[] = {{"Y", noise.data()}};
  std::vector<std::uint8_t> png_noise(noise.size() * 3);
  for (auto& b : png_noise) b = static_cast<std::uint8_t>(rng());
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit old_limit{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  const std::vector<std::pair<std::string, std::function<Status(const fs::path&)>>> writers = {
      {"a.npy", [&](const fs::path& p) { return write_npy(p, noise.data(), shape); }},
      {"a.exr",
       [&](const fs::path& p) { return write_exr(p, 256, 256, channels, ExrPixelType::float32); }},
      {"a.png", [&](const fs::path& p) { return write_png8(p, 256, 256, 3, png_noise.data()); }}};
  for (const auto& [name, write] : writers) {
    write_file(dir.path() / name, "old contents");
    rlimit small = old_limit;
    small.rlim_cur = 64 * 1024;
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    const Status s = write(dir.path() / name);
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &old_limit), 0);
    expect_image_error(s, ErrorCode::io_error, cat("cannot write '", (dir.path() / name).string(), "'"));
    EXPECT_NE(s.message().find("File too large"), std::string::npos) << s.message();
    EXPECT_EQ(read_file(dir.path() / name), "old contents");
  }
  std::signal(SIGXFSZ, old_handler);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.exr", "a.npy", "a.png"}));
}

}  // namespace
}  // namespace ocean::io
