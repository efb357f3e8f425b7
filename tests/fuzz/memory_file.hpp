// A fuzz input as a file, for code that reads from a path: the bytes go into an anonymous
// in-memory file (memfd_create) whose path is /proc/self/fd/<n>. Nothing touches the disk, and
// each input is a fresh file, so runs do not depend on one another.
#pragma once

#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace ocean::fuzz {

class MemoryFile {
 public:
  /// Holds a copy of `size` bytes at `data`. A failure of the system calls aborts: the fuzz
  /// target cannot run without them.
  MemoryFile(const std::uint8_t* data, std::size_t size) {
    fd_ = ::memfd_create("fuzz-input", MFD_CLOEXEC);
    if (fd_ < 0) fail("memfd_create");
    std::size_t written = 0;
    while (written < size) {
      const ssize_t n = ::write(fd_, data + written, size - written);
      if (n <= 0) fail("write");
      written += static_cast<std::size_t>(n);
    }
    path_ = "/proc/self/fd/" + std::to_string(fd_);
  }
  ~MemoryFile() { ::close(fd_); }
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;

  /// A path that opens the bytes from their start, for as long as this object lives.
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  [[noreturn]] static void fail(const char* call) {
    std::perror(call);
    std::abort();
  }

  int fd_ = -1;
  std::filesystem::path path_;
};

/// What `read` (a reader taking a path) returns for the input given as a file.
template <class Read>
auto read_as_file(const std::uint8_t* data, std::size_t size, Read read) {
  const MemoryFile file(data, size);
  return read(file.path());
}

}  // namespace ocean::fuzz
