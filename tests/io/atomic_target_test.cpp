// What the atomic writer may replace (ocean/io.hpp): a regular file, a new path, a symbolic link
// that dangles or leads to a regular file; never a directory, device, FIFO or socket, which are
// refused before anything is written. Every target lives in a scratch directory: the device is a
// copy of /dev/null made there with mknod, so no real device node is ever at risk.
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstring>

#include "io_test_util.hpp"
#include "ocean/io.hpp"

namespace ocean::io {
namespace {

using test::cat;
using test::read_file;
using test::TempDir;
using test::write_file;
namespace fs = std::filesystem;

// Writes "new" to `target` through write_atomically; `called` tells whether the callback ran.
Status write_new(const fs::path& target, bool& called) {
  called = false;
  return write_atomically(target, [&](const fs::path& temporary) {
    called = true;
    write_file(temporary, "new");
    return Status{};
  });
}

// The refusal every kind gets: io_error naming the path and the kind, the callback never run,
// the directory as it was (no temporary left), the thing at `target` still what it was.
void expect_refused(const TempDir& dir, const fs::path& target, const std::string& reason) {
  struct stat before {};
  ASSERT_EQ(::lstat(target.c_str(), &before), 0) << target;
  const std::vector<std::string> entries = dir.entries();
  bool called = false;
  const Status s = write_new(target, called);
  EXPECT_EQ(s.code(), ErrorCode::io_error) << s.message();
  EXPECT_EQ(s.message(), cat("cannot write '", target.string(), "': ", reason));
  EXPECT_FALSE(called);
  EXPECT_EQ(dir.entries(), entries);
  struct stat after {};
  ASSERT_EQ(::lstat(target.c_str(), &after), 0) << target;
  EXPECT_EQ(after.st_mode, before.st_mode);
  EXPECT_EQ(after.st_ino, before.st_ino);
  // The check before long work says the same.
  EXPECT_EQ(check_parent_writable(target).message(), s.message());
}

TEST(AtomicTarget, RefusesAFifo) {
  TempDir dir;
  const fs::path fifo = dir.path() / "pipe.png";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expect_refused(dir, fifo, "it is a FIFO, not a regular file");
}

TEST(AtomicTarget, RefusesADirectoryEvenAnEmptyOne) {
  TempDir dir;
  fs::create_directory(dir.path() / "empty");
  expect_refused(dir, dir.path() / "empty", "it is a directory, not a regular file");
}

TEST(AtomicTarget, RefusesASocket) {
  TempDir dir;
  const fs::path path = dir.path() / "s.sock";
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  ASSERT_LT(path.string().size(), sizeof address.sun_path);
  std::strncpy(address.sun_path, path.c_str(), sizeof address.sun_path - 1);
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
  expect_refused(dir, path, "it is a socket, not a regular file");
  ::close(fd);
}

TEST(AtomicTarget, RefusesADeviceAndALinkToOne) {
  TempDir dir;
  // A link to the real /dev/null: refusing it touches only the link in the scratch directory.
  const fs::path link = dir.path() / "null-link.png";
  fs::create_symlink("/dev/null", link);
  expect_refused(dir, link, "it links to a character device, not a regular file");
  // A device node of its own (root, or CAP_MKNOD) stands for the device itself.
  const fs::path node = dir.path() / "null.png";
  if (::mknod(node.c_str(), S_IFCHR | 0666, ::makedev(1, 3)) != 0)
    GTEST_SKIP() << "mknod: " << std::strerror(errno) << " (the link case above ran)";
  expect_refused(dir, node, "it is a character device, not a regular file");
}

TEST(AtomicTarget, ReplacesALinkToARegularFileOrADanglingLink) {
  TempDir dir;
  const fs::path file = dir.path() / "file.txt", link = dir.path() / "link.txt";
  write_file(file, "old");
  fs::create_symlink(file, link);
  bool called = false;
  ASSERT_TRUE(write_new(link, called).ok());
  EXPECT_TRUE(called);
  // The link itself is replaced by the new file; the file it led to keeps its contents.
  EXPECT_FALSE(fs::is_symlink(link));
  EXPECT_EQ(read_file(link), "new");
  EXPECT_EQ(read_file(file), "old");

  const fs::path dangling = dir.path() / "dangling.txt";
  fs::create_symlink(dir.path() / "nowhere", dangling);
  ASSERT_TRUE(write_new(dangling, called).ok());
  EXPECT_FALSE(fs::is_symlink(dangling));
  EXPECT_EQ(read_file(dangling), "new");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"dangling.txt", "file.txt", "link.txt"}));
}

}  // namespace
}  // namespace ocean::io
