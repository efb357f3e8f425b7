// Tests for the io module: atomic replacement, .npy, OpenEXR and PNG round trips and bad inputs.
#include "ocean/io.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <thread>

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

std::span<const std::byte> bytes_of(const std::string& s) {
  return std::as_bytes(std::span<const char>(s));
}

void expect_error(const Status& s, ErrorCode code, const std::string& needle) {
  EXPECT_EQ(s.code(), code) << s.message();
  EXPECT_NE(s.message().find(needle), std::string::npos) << s.message();
}

// ---- atomic_file ----------------------------------------------------------------------------

TEST(AtomicFile, WritesReplacesAndLeavesNoTemporary) {
  TempDir dir;
  const fs::path target = dir.path() / "a.bin";
  ASSERT_TRUE(write_bytes_atomically(target, {bytes_of("hello "), bytes_of("world")}).ok());
  EXPECT_EQ(read_file(target), "hello world");
  ASSERT_TRUE(write_bytes_atomically(target, {bytes_of("new")}).ok());
  EXPECT_EQ(read_file(target), "new");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.bin"});
  // Permissions follow the umask like any other new file.
  const mode_t mask = ::umask(022);
  ::umask(mask);
  struct stat st {};
  ASSERT_EQ(::stat(target.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777U, 0666U & ~mask);
}

TEST(AtomicFile, OldContentsStayUntilTheRename) {
  TempDir dir;
  const fs::path target = dir.path() / "keep.txt";
  write_file(target, "old");
  Status s = write_atomically(target, [&](const fs::path& tmp) {
    EXPECT_EQ(tmp.parent_path(), target.parent_path());
    EXPECT_EQ(tmp.filename().string().rfind(".keep.txt.tmp-", 0), 0U) << tmp;
    EXPECT_TRUE(fs::is_regular_file(tmp));
    write_file(tmp, "half-written");
    EXPECT_EQ(read_file(target), "old");  // not visible yet
    return io_error("disk on fire");
  });
  EXPECT_EQ(s.code(), ErrorCode::io_error);
  EXPECT_EQ(s.message(), cat("cannot write '", target.string(), "': disk on fire"));
  EXPECT_EQ(read_file(target), "old");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"keep.txt"});
  // A throwing callback is reported the same way.
  s = write_atomically(target, [](const fs::path&) -> Status { throw std::runtime_error("boom"); });
  expect_error(s, ErrorCode::io_error, "': boom");
  EXPECT_EQ(read_file(target), "old");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"keep.txt"});
}

TEST(AtomicFile, MissingDirectoryNamesThePathAndLeavesNothing) {
  TempDir dir;
  const fs::path target = dir.path() / "missing" / "x.npy";
  bool called = false;
  const Status s =
      write_atomically(target, [&](const fs::path&) { return called = true, Status{}; });
  expect_error(s, ErrorCode::io_error, cat("cannot write '", target.string(), "': No such file"));
  EXPECT_FALSE(called);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, AControlCharacterInThePathKeepsTheMessageOnOneLine) {
  TempDir dir;
  const fs::path target = dir.path() / "new\nline" / "x\r.npy";
  for (const Status& s :
       {check_parent_writable(target), write_bytes_atomically(target, {bytes_of("data")})}) {
    ASSERT_EQ(s.code(), ErrorCode::io_error);
    EXPECT_EQ(s.message().find_first_of("\n\r"), std::string::npos) << s.message();
    EXPECT_NE(s.message().find("new\\nline"), std::string::npos) << s.message();
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, AVeryLongPathIsShortenedInTheMessage) {
  const fs::path target = fs::path("/nonexistent") / std::string(3000, 'a') / "x.npy";
  const Status s = check_parent_writable(target);
  ASSERT_EQ(s.code(), ErrorCode::io_error);
  EXPECT_LT(s.message().size(), 400u) << s.message().size();
}

TEST(AtomicFile, DirectoryInTheWayIsIoErrorAndLeavesNoTemporary) {
  TempDir dir;
  fs::create_directory(dir.path() / "d");
  write_file(dir.path() / "d" / "inside", "x");
  const Status s = write_bytes_atomically(dir.path() / "d", {bytes_of("data")});
  expect_error(s, ErrorCode::io_error, cat("cannot write '", (dir.path() / "d").string(), "'"));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"d"});
  EXPECT_EQ(read_file(dir.path() / "d" / "inside"), "x");
}

TEST(AtomicFile, RejectsPathsWithoutAFileName) {
  TempDir dir;
  EXPECT_EQ(write_bytes_atomically("", {}).code(), ErrorCode::invalid_argument);
  EXPECT_EQ(write_bytes_atomically(dir.path() / "", {}).code(), ErrorCode::invalid_argument);
  EXPECT_EQ(write_bytes_atomically(dir.path() / "..", {}).code(), ErrorCode::invalid_argument);
  EXPECT_EQ(write_atomically(dir.path() / "f", WriteCallback{}).code(),
            ErrorCode::invalid_argument);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, ConcurrentWritersNeverLeaveAPartialFile) {
  TempDir dir;
  const fs::path target = dir.path() / "shared.bin";
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t) {
    threads.emplace_back([&target, t] {
      const std::string content(10000, static_cast<char>('a' + t));
      for (int i = 0; i < 20; ++i)
        EXPECT_TRUE(write_bytes_atomically(target, {bytes_of(content)}).ok());
    });
  }
  for (auto& th : threads) th.join();
  const std::string final_content = read_file(target);
  ASSERT_EQ(final_content.size(), 10000U);
  EXPECT_EQ(final_content, std::string(10000, final_content[0]));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"shared.bin"});
}

TEST(EnsureDirectory, CreatesNestedAndReportsObstacles) {
  TempDir dir;
  EXPECT_TRUE(ensure_directory(dir.path() / "a" / "b" / "c").ok());
  EXPECT_TRUE(fs::is_directory(dir.path() / "a" / "b" / "c"));
  EXPECT_TRUE(ensure_directory(dir.path() / "a").ok());  // already there
  EXPECT_TRUE(ensure_directory("").ok());
  write_file(dir.path() / "file", "x");
  expect_error(ensure_directory(dir.path() / "file"), ErrorCode::io_error,
               cat("'", (dir.path() / "file").string(), "' exists and is not a directory"));
  expect_error(ensure_directory(dir.path() / "file" / "sub"), ErrorCode::io_error,
               cat("cannot create directory '", (dir.path() / "file" / "sub").string(), "'"));
}

// A directory nobody may write into: creating one inside it is an io_error that says why. Root
// ignores permissions, so the attempt runs in a child process as the unprivileged user
// "nobody" (65534); the directory is readable and searchable by all, writable by none.
TEST(EnsureDirectory, ReportsAPermissionDenied) {
  TempDir dir;
  fs::permissions(dir.path(), fs::perms::others_exec | fs::perms::group_exec,
                  fs::perm_options::add);
  const fs::path locked = dir.path() / "locked";
  fs::create_directory(locked);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                              fs::perms::group_exec | fs::perms::others_read |
                              fs::perms::others_exec);
  const int outcome = test::exit_status_as_unprivileged([&] {
    const Status s = ensure_directory(locked / "x");
    return s.code() == ErrorCode::io_error &&
                   s.message().find("Permission denied") != std::string::npos &&
                   s.message().find((locked / "x").string()) != std::string::npos
               ? 0
               : 1;
  });
  EXPECT_EQ(outcome, 0) << "1: ensure_directory did not report the denial; 2: could not drop to "
                           "an unprivileged user (the test needs root's setuid or a non-root "
                           "user); else the child died";
  EXPECT_FALSE(fs::exists(locked / "x"));
}

// ---- npy --------------------------------------------------------------------------------------

std::vector<float> special_values(std::size_t n) {
  std::vector<float> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<float>(i) * 0.37f - 5.0f;
  const float specials[] = {std::numeric_limits<float>::quiet_NaN(), -0.0f,
                            std::numeric_limits<float>::infinity(),  1e-45f,
                            std::bit_cast<float>(0x7fc01234U),       -3.4e38f};
  for (std::size_t i = 0; i < n && i < std::size(specials); ++i) v[i] = specials[i];
  return v;
}

TEST(Npy, RoundTripsBitExactlyWithAlignedHeader) {
  TempDir dir;
  const std::vector<std::vector<std::size_t>> shapes = {
      {}, {0}, {7}, {2, 3}, {3, 0, 2}, {2, 3, 4}, {1, 1, 1, 1, 5}};
  for (const auto& shape : shapes) {
    std::size_t n = 1;
    for (auto d : shape) n *= d;
    const std::vector<float> data = special_values(n);
    const fs::path p = dir.path() / "a.npy";
    ASSERT_TRUE(write_npy(p, data.data(), shape).ok());
    const std::string bytes = read_file(p);
    const std::size_t header_len =
        static_cast<unsigned char>(bytes[8]) + 256U * static_cast<unsigned char>(bytes[9]);
    EXPECT_EQ((10 + header_len) % 64, 0U);
    EXPECT_EQ(bytes[9 + header_len], '\n');
    EXPECT_EQ(bytes.size(), 10 + header_len + 4 * n);
    Result<NpyArray> r = read_npy(p);
    ASSERT_TRUE(r.ok()) << r.status().message();
    EXPECT_EQ(r.value().shape, shape);
    ASSERT_EQ(r.value().data.size(), n);
    if (n > 0) {
      EXPECT_EQ(std::memcmp(r.value().data.data(), data.data(), 4 * n), 0);
    }
  }
}

TEST(Npy, HeaderIsByteForByteWhatNumpyWrites) {
  TempDir dir;
  const float data[6] = {};
  const std::size_t shape[2] = {2, 3};
  ASSERT_TRUE(write_npy(dir.path() / "a.npy", data, shape).ok());
  std::string expected("\x93NUMPY\x01\x00\x76\x00", 10);
  expected += "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }";
  expected.append(128 - 1 - expected.size(), ' ').append("\n");
  EXPECT_EQ(read_file(dir.path() / "a.npy").substr(0, 128), expected);
  const std::size_t one[1] = {6};
  ASSERT_TRUE(write_npy(dir.path() / "b.npy", data, one).ok());
  EXPECT_NE(read_file(dir.path() / "b.npy").find("'shape': (6,), }"), std::string::npos);
}

// A .npy file with an arbitrary header text (padded to 16 bytes, as old numpy did).
std::string make_npy(std::string header, std::size_t data_bytes, char major = 1) {
  header.append(15 - (10 + header.size()) % 16, ' ').push_back('\n');
  std::string out("\x93NUMPY", 6);
  out.push_back(major);
  out.push_back('\0');
  out.push_back(static_cast<char>(header.size() & 0xFF));
  out.push_back(static_cast<char>(header.size() >> 8));
  return out + header + std::string(data_bytes, '\0');
}

TEST(Npy, ReaderAcceptsOtherValidSpellings) {
  TempDir dir;
  const fs::path p = dir.path() / "v.npy";
  for (const std::string h :
       {"{\"shape\": (2, 2), \"fortran_order\": False, \"descr\": \"<f4\"}",
        "{'descr':'<f4','fortran_order':False,'shape':(2L,2L)}",
        "{ 'descr' : '<f4' , 'fortran_order' : False , 'shape' : ( 2 , 2 , ) , }"}) {
    write_file(p, make_npy(h, 16));
    Result<NpyArray> r = read_npy(p);
    ASSERT_TRUE(r.ok()) << h << ": " << r.status().message();
    EXPECT_EQ(r.value().shape, (std::vector<std::size_t>{2, 2}));
  }
}

TEST(Npy, ReaderNamesTheProblem) {
  TempDir dir;
  const fs::path p = dir.path() / "bad.npy";
  const std::string ok_dict = "{'descr': '<f4', 'fortran_order': False, 'shape': (3,), }";
  const auto check = [&](const std::string& bytes, const std::string& needle) {
    write_file(p, bytes);
    Result<NpyArray> r = read_npy(p);
    ASSERT_FALSE(r.ok()) << needle;
    expect_error(r.status(), ErrorCode::invalid_argument, needle);
    EXPECT_NE(r.status().message().find(p.string()), std::string::npos);
  };
  check("PK\x03\x04 this is a zip", "wrong magic");
  check("", "wrong magic");
  check(make_npy(ok_dict, 12, 2), "version 2.0 is not supported");
  check(make_npy(ok_dict, 12).substr(0, 30), "truncated header");
  check(make_npy(ok_dict, 11), "truncated data");
  check(make_npy(ok_dict, 13), "1 unexpected bytes after the data");
  check(make_npy("{'descr': '>f4', 'fortran_order': False, 'shape': (3,), }", 12), "'>f4'");
  check(make_npy("{'descr': '<f8', 'fortran_order': False, 'shape': (3,), }", 24), "'<f8'");
  check(make_npy("{'descr': '<f4', 'fortran_order': True, 'shape': (3,), }", 12), "Fortran");
  check(make_npy("{'descr': '<f4', 'shape': (3,), }", 12), "lacks 'fortran_order'");
  check(make_npy("{'descr': '<f4', 'fortran_order': False, 'shape': (3,), 'x': 1}", 12),
        "unexpected header key 'x'");
  check(make_npy("{'descr': '<f4', 'fortran_order': False, 'shape': (3), }", 12), "tuple");
  check(make_npy("{'descr': '<f4', 'fortran_order': False, 'shape': (-3,), }", 12), "shape");
  check(
      make_npy("{'descr': '<f4', 'fortran_order': False, 'shape': (4294967296, 4294967296), }", 0),
      "overflows");
  check(make_npy("{'descr': [('a', '<f4')], 'fortran_order': False, 'shape': (3,), }", 12),
        "'descr'");
  Result<NpyArray> missing = read_npy(dir.path() / "none.npy");
  expect_error(missing.status(), ErrorCode::io_error, "No such file or directory");
  expect_error(read_npy(dir.path()).status(), ErrorCode::io_error, "Is a directory");
}

TEST(Npy, WriterRejectsBadArguments) {
  TempDir dir;
  const fs::path p = dir.path() / "x.npy";
  const std::size_t shape[1] = {4};
  expect_error(write_npy(p, nullptr, shape), ErrorCode::invalid_argument, "null");
  const std::vector<std::size_t> many(33, 1);
  const float one = 1.0f;
  expect_error(write_npy(p, &one, many), ErrorCode::invalid_argument, "33 dimensions");
  const std::size_t huge[2] = {std::size_t{1} << 40, std::size_t{1} << 40};
  expect_error(write_npy(p, &one, huge), ErrorCode::invalid_argument, "overflows");
  EXPECT_TRUE(dir.entries().empty());
  const std::size_t empty[1] = {0};
  EXPECT_TRUE(write_npy(p, nullptr, empty).ok());
  expect_error(write_npy(dir.path() / "no" / "x.npy", &one, {}), ErrorCode::io_error,
               cat("cannot write '", (dir.path() / "no" / "x.npy").string(), "'"));
}

}  // namespace
}  // namespace ocean::io
