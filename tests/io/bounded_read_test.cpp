// io::read_bounded (ocean/io.hpp): a file read whole under a stated limit, whatever it is.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <string>

#include "io_test_util.hpp"
#include "ocean/io.hpp"

namespace ocean::io {
namespace {

using test::TempDir;
using test::write_file;

void expect_message(const Status& status, ErrorCode code, const std::string& needle) {
  EXPECT_EQ(status.code(), code) << status.message();
  EXPECT_NE(status.message().find(needle), std::string::npos) << status.message();
  EXPECT_EQ(status.message().find('\n'), std::string::npos);
}

TEST(BoundedRead, FileAtTheLimitIsReadWholeAndOneBytePastItIsRefused) {
  TempDir dir;
  const auto path = dir.path() / "doc.json";
  write_file(path, std::string(100, 'x'));
  const Result<std::string> at = read_bounded(path, {.max_bytes = 100, .what = "manifest"});
  ASSERT_TRUE(at.ok()) << at.status().message();
  EXPECT_EQ(at.value(), std::string(100, 'x'));

  const Result<std::string> past = read_bounded(path, {.max_bytes = 99, .what = "manifest"});
  ASSERT_FALSE(past.ok());
  expect_message(
      past.status(), ErrorCode::invalid_argument,
      "manifest '" + path.string() + "' is larger than 99 bytes, the most a manifest may hold");
}

// Without a `what`, the messages are the format readers' own "cannot read '<path>': ...".
TEST(BoundedRead, WithoutWhatTheMessagesAreTheReadersPlainForm) {
  TempDir dir;
  const auto path = dir.path() / "map.npy";
  write_file(path, std::string(2048, 'x'));
  const Result<std::string> big = read_bounded(path, {.max_bytes = 1024, .what = {}});
  ASSERT_FALSE(big.ok());
  expect_message(
      big.status(), ErrorCode::invalid_argument,
      "cannot read '" + path.string() + "': it is larger than 1024 bytes (1 KiB), the limit");
  const Result<std::string> absent =
      read_bounded(dir.path() / "absent.npy", {.max_bytes = 1024, .what = {}});
  ASSERT_FALSE(absent.ok());
  expect_message(
      absent.status(), ErrorCode::io_error,
      "cannot read '" + (dir.path() / "absent.npy").string() + "': No such file or directory");
}

TEST(BoundedRead, LimitsAreStatedInBytesAndBinaryUnits) {
  EXPECT_EQ(byte_limit_text(1048576), "1048576 bytes (1 MiB)");
  EXPECT_EQ(byte_limit_text(std::uint64_t{3} << 30), "3221225472 bytes (3 GiB)");
  EXPECT_EQ(byte_limit_text(2048), "2048 bytes (2 KiB)");
  EXPECT_EQ(byte_limit_text(1000), "1000 bytes");
}

// /dev/zero never ends: it is refused after max_bytes + 1 bytes, not read until memory runs out.
TEST(BoundedRead, EndlessDeviceIsRefusedAtTheLimit) {
  const auto start = std::chrono::steady_clock::now();
  const Result<std::string> zero =
      read_bounded("/dev/zero", {.max_bytes = 1 << 20, .what = "environment map"});
  ASSERT_FALSE(zero.ok());
  expect_message(zero.status(), ErrorCode::invalid_argument,
                 "'/dev/zero' is larger than 1048576 bytes (1 MiB), the most an environment map");
  // Structure, not speed: the refusal came from the bound, long before a minute of reading.
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::minutes(1));

  const Result<std::string> regular =
      read_bounded("/dev/zero", {.max_bytes = 1 << 20, .what = "manifest", .regular_only = true});
  ASSERT_FALSE(regular.ok());
  expect_message(regular.status(), ErrorCode::io_error,
                 "cannot read manifest '/dev/zero': it is a character device, not a regular file");
}

TEST(BoundedRead, FifoWithoutWriterIsRefusedAfterTheWait) {
  TempDir dir;
  const auto fifo = dir.path() / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const Result<std::string> text =
      read_bounded(fifo, {.max_bytes = 10, .what = "preset", .fifo_wait_ms = 50});
  ASSERT_FALSE(text.ok());
  expect_message(
      text.status(), ErrorCode::io_error,
      "cannot read preset '" + fifo.string() + "': no process wrote to the FIFO within 50 ms");
  const Result<std::string> regular = read_bounded(
      fifo, {.max_bytes = 10, .what = "manifest", .regular_only = true, .fifo_wait_ms = 50});
  ASSERT_FALSE(regular.ok());
  expect_message(regular.status(), ErrorCode::io_error, "it is a FIFO, not a regular file");
}

TEST(BoundedRead, SymbolicLinkIsRefusedWithNoFollow) {
  TempDir dir;
  const auto target = dir.path() / "real.json";
  const auto link = dir.path() / "link.json";
  write_file(target, "{}");
  std::filesystem::create_symlink(target, link);
  const Result<std::string> followed = read_bounded(link, {.max_bytes = 10, .what = "manifest"});
  ASSERT_TRUE(followed.ok()) << followed.status().message();
  EXPECT_EQ(followed.value(), "{}");
  const Result<std::string> refused =
      read_bounded(link, {.max_bytes = 10, .what = "manifest", .no_follow = true});
  ASSERT_FALSE(refused.ok());
  expect_message(refused.status(), ErrorCode::io_error,
                 "cannot read manifest '" + link.string() + "': it is a symbolic link");
}

TEST(BoundedRead, MissingFileNamesTheReason) {
  TempDir dir;
  const Result<std::string> text =
      read_bounded(dir.path() / "absent", {.max_bytes = 10, .what = "preset"});
  ASSERT_FALSE(text.ok());
  expect_message(text.status(), ErrorCode::io_error, "': No such file or directory");
}

}  // namespace
}  // namespace ocean::io
