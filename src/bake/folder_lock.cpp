// src/bake/folder_lock.cpp — the output folder's lock: flock(2) on a file holding the pid.
//
// Why flock and not the file's existence: a lock file left by a killed process would block every
// later bake, and telling a dead holder from a live one by its pid races with pid reuse. The
// kernel drops a flock when the last descriptor of its holder closes, at death included.
//
// Why the inode check: the holder removes the file before letting go (so a finished bake leaves
// no lock file). A process that opened the file just before the removal then locks an inode no
// longer named by the path, while a third one may create and lock a new file there; comparing the
// locked inode with the one the path names, and starting again when they differ, closes that
// window.
#include "folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <string>
#include <utility>

#include "ocean/bake.hpp"
#include "ocean/io.hpp"

namespace ocean::bake::detail {
namespace {

Status cannot_write(const std::filesystem::path& file, int err) {
  return io_error("cannot write " + io::quoted(file) + ": " + io::errno_message(err));
}

// The pid a holder wrote into the lock file, or "" when there is none yet.
std::string holder_pid(int fd) {
  char text[32] = {};
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  std::string pid;
  for (ssize_t i = 0; i < n && std::isdigit(static_cast<unsigned char>(text[i])) != 0; ++i)
    pid += text[i];
  return pid;
}

bool same_file(int fd, const std::filesystem::path& path) {
  struct stat held {
  }, named{};
  return ::fstat(fd, &held) == 0 && ::lstat(path.c_str(), &named) == 0 &&
         held.st_dev == named.st_dev && held.st_ino == named.st_ino;
}

}  // namespace

FolderLock::FolderLock(FolderLock&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), file_(std::move(other.file_)) {}

FolderLock& FolderLock::operator=(FolderLock&& other) noexcept {
  if (this != &other) {
    release();
    fd_ = std::exchange(other.fd_, -1);
    file_ = std::move(other.file_);
  }
  return *this;
}

Result<FolderLock> FolderLock::take(const std::filesystem::path& dir) {
  const std::filesystem::path file = dir / kLockFileName;
  for (int attempt = 0; attempt < 100; ++attempt) {
    int fd = -1;
    do {
      fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0666);
    } while (fd < 0 && errno == EINTR);
    if (fd < 0) return cannot_write(file, errno);
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
      ::close(fd);
      return io_error("cannot write " + io::quoted(file) + ": it is not a regular file");
    }
    int locked = -1;
    do {
      locked = ::flock(fd, LOCK_EX | LOCK_NB);
    } while (locked != 0 && errno == EINTR);
    if (locked != 0) {
      const int err = errno;
      const std::string pid = err == EWOULDBLOCK ? holder_pid(fd) : std::string();
      ::close(fd);
      if (err != EWOULDBLOCK) return cannot_write(file, err);
      return io_error(io::quoted(dir) + " is being baked by " +
                      (pid.empty() ? std::string("another process") : "process " + pid) +
                      " (it holds " + io::quoted(file) + ")");
    }
    if (!same_file(fd, file)) {  // its holder removed it meanwhile: lock the new one
      ::close(fd);
      continue;
    }
    FolderLock lock;
    lock.fd_ = fd;
    lock.file_ = file;
    const std::string pid = std::to_string(static_cast<long long>(::getpid())) + "\n";
    errno = 0;
    if (::ftruncate(fd, 0) != 0 ||
        ::pwrite(fd, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
      const int err = errno != 0 ? errno : ENOSPC;  // a short write sets no errno
      lock.release();
      return cannot_write(file, err);
    }
    return lock;
  }
  return io_error("cannot lock " + io::quoted(file) + ": it keeps being replaced");
}

void FolderLock::release() noexcept {
  if (fd_ < 0) return;
  (void)::unlink(file_.c_str());  // while still locked: see the top of this file
  ::close(fd_);
  fd_ = -1;
}

}  // namespace ocean::bake::detail
