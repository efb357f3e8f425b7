// src/io/atomic_file.cpp — write-to-temporary, fsync, rename-over-target, fsync-directory.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <exception>
#include <string>
#include <system_error>

#include "format_detail.hpp"
#include "ocean/io.hpp"

namespace ocean::io {
namespace {

std::atomic<unsigned long long> g_temporary_counter{0};

// Leaves room for ".<name>.tmp-<pid>-<counter>" within the usual 255-byte NAME_MAX.
constexpr std::size_t kMaxNameBytesInTemporary = 200;

Status write_error(const std::filesystem::path& path, const std::string& reason) {
  std::string message = "cannot write ";
  message.append(quoted(path)).append(": ").append(reason);
  return io_error(std::move(message));
}

std::filesystem::path temporary_name(const std::filesystem::path& dir, const std::string& leaf) {
  // Built with append rather than operator+ to dodge a g++ 12 -O3 -Wrestrict false positive.
  std::string name(1, '.');
  name.append(leaf, 0, std::min(leaf.size(), kMaxNameBytesInTemporary));
  name.append(".tmp-").append(std::to_string(static_cast<long long>(::getpid())));
  name.append("-").append(std::to_string(g_temporary_counter.fetch_add(1)));
  return dir / name;
}

// Reserves a fresh temporary name (O_EXCL) and leaves an empty file there; returns 0 or errno.
int create_temporary(const std::filesystem::path& dir, const std::string& leaf,
                     std::filesystem::path& temporary) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    temporary = temporary_name(dir, leaf);
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);  // empty file, nothing to lose
      return 0;
    }
    if (errno != EEXIST && errno != EINTR) return errno;
  }
  return EEXIST;
}

// The target may be replaced: nothing is there, or a regular file, or a symbolic link that
// dangles or leads to a regular file. A device, FIFO, socket or directory is refused: renaming
// over it would put a file where a device node was (`--plot /dev/full` run as root).
Status check_target(const std::filesystem::path& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) {
    // Absent is a new file; any other failure (a missing directory) is reported by the
    // creation of the temporary, with its own errno.
    return Status::ok_status();
  }
  if (S_ISREG(st.st_mode)) return Status::ok_status();
  if (S_ISLNK(st.st_mode)) {
    if (::stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return Status::ok_status();
    return write_error(
        path, std::string("it links to ") + detail::file_kind(st.st_mode) + ", not a regular file");
  }
  return write_error(
      path, std::string("it is ") + detail::file_kind(st.st_mode) + ", not a regular file");
}

// fsync of the finished temporary; returns 0 or errno.
int sync_file(const std::filesystem::path& file) {
  int fd = -1;
  do {
    fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  } while (fd < 0 && errno == EINTR);
  if (fd < 0) return errno;
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    return EINVAL;  // the callback replaced the temporary with something that is not a file
  }
  int err = ::fsync(fd) == 0 ? 0 : errno;
  if (::close(fd) != 0 && err == 0 && errno != EINTR) err = errno;
  return err;
}

// Writes all bytes, retrying on EINTR and short writes; returns 0 or an errno value.
int write_all(int fd, const std::byte* data, std::size_t n) {
  constexpr std::size_t kChunk = std::size_t{1} << 30;
  while (n > 0) {
    const ssize_t w = ::write(fd, data, std::min(n, kChunk));
    if (w < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    data += w;
    n -= static_cast<std::size_t>(w);
  }
  return 0;
}

}  // namespace

std::string errno_message(int err) noexcept {
  try {
    return std::system_category().message(err);
  } catch (...) {
    return {};
  }
}

Status write_atomically(const std::filesystem::path& path, const WriteCallback& write) {
  std::filesystem::path temporary;
  bool created = false;
  try {
    const std::string leaf = path.filename().string();
    if (leaf.empty() || leaf == "." || leaf == "..") {
      std::string message = "cannot write ";
      message.append(quoted(path)).append(": the path must end in a file name");
      return invalid_argument(std::move(message));
    }
    if (!write) return invalid_argument("write_atomically: empty write callback");
    const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : ".";
    if (Status target = check_target(path); !target.ok()) return target;

    if (const int err = create_temporary(dir, leaf, temporary); err != 0) {
      return write_error(path, errno_message(err));
    }
    created = true;
    const auto fail = [&](const std::string& reason) {
      (void)::unlink(temporary.c_str());
      return write_error(path, reason);
    };

    Status written = write(temporary);
    if (!written.ok()) {
      return fail(written.message().empty() ? std::string("the writer failed") : written.message());
    }
    if (const int err = sync_file(temporary); err != 0) {
      return fail("cannot sync the temporary file: " + errno_message(err));
    }
    // Again, now that the write may have taken a while: a device may have appeared meanwhile.
    if (Status target = check_target(path); !target.ok()) {
      (void)::unlink(temporary.c_str());
      return target;
    }
    if (::rename(temporary.c_str(), path.c_str()) != 0) return fail(errno_message(errno));
    created = false;
    // Make the rename itself durable; failure here does not undo a complete write.
    if (const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dfd >= 0) {
      (void)::fsync(dfd);
      ::close(dfd);
    }
    return Status::ok_status();
  } catch (const std::exception& e) {
    if (created) (void)::unlink(temporary.c_str());
    try {
      return write_error(path, e.what());
    } catch (...) {
      return io_error("cannot write file: out of memory");
    }
  } catch (...) {
    if (created) (void)::unlink(temporary.c_str());
    try {
      return write_error(path, "unknown exception from the writer");
    } catch (...) {
      return io_error("cannot write file: out of memory");
    }
  }
}

Status write_bytes_atomically(const std::filesystem::path& path,
                              std::initializer_list<std::span<const std::byte>> parts) {
  return write_atomically(path, [parts](const std::filesystem::path& temporary) -> Status {
    int fd = -1;
    do {
      fd = ::open(temporary.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    } while (fd < 0 && errno == EINTR);
    if (fd < 0) return io_error(errno_message(errno));
    for (const std::span<const std::byte> part : parts) {
      if (const int err = write_all(fd, part.data(), part.size()); err != 0) {
        ::close(fd);
        return io_error(errno_message(err));
      }
    }
    if (::close(fd) != 0 && errno != EINTR) return io_error(errno_message(errno));
    return Status::ok_status();
  });
}

Status ensure_directory(const std::filesystem::path& dir) {
  try {
    const auto fail = [&](const std::string& reason) {
      std::string message = "cannot create directory '";
      message.append(dir.string()).append("': ").append(reason);
      return io_error(std::move(message));
    };
    if (dir.empty()) return Status::ok_status();
    std::error_code ec;
    if (std::filesystem::is_directory(dir, ec)) return Status::ok_status();
    // Find the deepest existing ancestor that is not a directory, to name it in the message.
    for (std::filesystem::path p = dir; !p.empty(); p = p.parent_path()) {
      const std::filesystem::file_status st = std::filesystem::status(p, ec);
      if (std::filesystem::exists(st)) {
        if (!std::filesystem::is_directory(st)) {
          std::string reason(1, '\'');
          reason.append(p.string()).append("' exists and is not a directory");
          return fail(reason);
        }
        break;
      }
      if (p == p.parent_path()) break;
    }
    std::filesystem::create_directories(dir, ec);
    // Another process may have created it meanwhile; that is success too.
    if (std::filesystem::is_directory(dir)) return Status::ok_status();
    return fail(ec ? ec.message() : std::string("it could not be created"));
  } catch (const std::exception& e) {
    try {
      std::string message = "cannot create directory '";
      message.append(dir.string()).append("': ").append(e.what());
      return io_error(std::move(message));
    } catch (...) {
      return io_error("cannot create directory: out of memory");
    }
  }
}

std::string quoted(const std::filesystem::path& path) {
  // Built with append rather than operator+ to dodge a g++ 12 -O3 -Wrestrict false positive.
  std::string text(1, '\'');
  text.append(excerpt(path.string(), 240)).append(1, '\'');
  return text;
}

Status check_parent_writable(const std::filesystem::path& path) {
  const std::filesystem::path dir =
      path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
  std::error_code ec;
  if (std::filesystem::is_directory(dir, ec) && ::access(dir.c_str(), W_OK) == 0)
    return check_target(path);
  return io_error(
      "cannot write " + quoted(path) + ": " +
      (std::filesystem::exists(dir, ec) ? "Permission denied" : "No such file or directory"));
}

}  // namespace ocean::io
