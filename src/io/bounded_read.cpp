// src/io/bounded_read.cpp — a whole file read under a size limit (see ocean/io.hpp).
#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <exception>
#include <string>

#include "format_detail.hpp"
#include "ocean/io.hpp"

namespace ocean::io {
namespace {

using detail::FdGuard;

std::string cannot_read(const ReadLimits& limits, const std::filesystem::path& path,
                        const std::string& why) {
  std::string message = "cannot read ";
  if (!limits.what.empty()) message.append(limits.what).append(" ");
  message.append("'").append(excerpt(path.string())).append("': ");
  return message.append(why);
}

// For a FIFO: waits up to `wait_ms` for a writer (or its data); then, whatever `fd` is, makes
// its reads blocking. Returns the reason of a failure, empty on success.
std::string wait_for_writer(int fd, int wait_ms) {
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISFIFO(st.st_mode)) {
    pollfd p{.fd = fd, .events = POLLIN, .revents = 0};
    int ready = 0;
    do {
      ready = ::poll(&p, 1, wait_ms);
    } while (ready < 0 && errno == EINTR);
    if (ready == 0) {
      return "no process wrote to the FIFO within " + (wait_ms % 1000 == 0
                                                           ? std::to_string(wait_ms / 1000) + " s"
                                                           : std::to_string(wait_ms) + " ms");
    }
  }
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags < 0 || ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) < 0) return errno_message(errno);
  return {};
}

Result<std::string> read_opened(const std::filesystem::path& path, const ReadLimits& limits) {
  FdGuard guard;
  const int flags = O_RDONLY | O_CLOEXEC | O_NONBLOCK | (limits.no_follow ? O_NOFOLLOW : 0);
  do {
    guard.fd = ::open(path.c_str(), flags);
  } while (guard.fd < 0 && errno == EINTR);
  if (guard.fd < 0) {
    const int err = errno;
    if (err == ELOOP && limits.no_follow)
      return io_error(cannot_read(limits, path, "it is a symbolic link"));
    return io_error(cannot_read(limits, path, errno_message(err)));
  }
  if (limits.regular_only) {
    struct stat st {};
    if (::fstat(guard.fd, &st) != 0)
      return io_error(cannot_read(limits, path, errno_message(errno)));
    if (!S_ISREG(st.st_mode)) {
      return io_error(cannot_read(
          limits, path,
          std::string("it is ") + detail::file_kind(st.st_mode) + ", not a regular file"));
    }
  }
  if (std::string why = wait_for_writer(guard.fd, limits.fifo_wait_ms); !why.empty())
    return io_error(cannot_read(limits, path, why));
  // Sized from the file's own size when it has one (one read, no growth for a regular file),
  // else grown by doubling from 64 KiB as the file delivers bytes: a 1 GiB limit is not 1 GiB
  // held for a 1 kB file, and never more than one byte past the limit is held.
  const std::uint64_t cap = limits.max_bytes + 1;
  struct stat st {};
  std::uint64_t room = std::uint64_t{1} << 16;
  if (::fstat(guard.fd, &st) == 0 && S_ISREG(st.st_mode))
    room = static_cast<std::uint64_t>(st.st_size) + 1;  // + 1 to see the end in the same read
  std::string text(static_cast<std::size_t>(std::min(room, cap)), '\0');
  std::uint64_t size = 0;
  while (size < cap) {
    if (size == text.size())
      text.resize(static_cast<std::size_t>(std::min<std::uint64_t>(cap, 2 * text.size())));
    const ssize_t n = ::read(guard.fd, text.data() + size, text.size() - size);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return io_error(cannot_read(limits, path, errno_message(errno)));
    if (n == 0) break;
    size += static_cast<std::uint64_t>(n);
  }
  if (size > limits.max_bytes && limits.what.empty()) {
    return invalid_argument(cannot_read(
        limits, path, "it is larger than " + byte_limit_text(limits.max_bytes) + ", the limit"));
  }
  if (size > limits.max_bytes) {
    std::string message(limits.what);
    message.append(" '").append(excerpt(path.string())).append("' is larger than ");
    const bool vowel = !limits.what.empty() &&
                       std::string_view("aeiou").find(limits.what[0]) != std::string_view::npos;
    message.append(byte_limit_text(limits.max_bytes))
        .append(vowel ? ", the most an " : ", the most a ");
    return invalid_argument(message.append(limits.what).append(" may hold"));
  }
  text.resize(static_cast<std::size_t>(size));
  return text;
}

}  // namespace

std::string byte_limit_text(std::uint64_t bytes) {
  constexpr std::uint64_t kKiB = 1024;
  std::string text = std::to_string(bytes) + " bytes";
  const char* unit = nullptr;
  std::uint64_t scaled = 0;
  for (const auto& [size, name] : {std::pair{kKiB * kKiB * kKiB, "GiB"},
                                   std::pair{kKiB * kKiB, "MiB"}, std::pair{kKiB, "KiB"}}) {
    if (bytes >= size && bytes % size == 0) {
      unit = name;
      scaled = bytes / size;
      break;
    }
  }
  if (unit != nullptr)
    text.append(" (").append(std::to_string(scaled)).append(" ").append(unit).append(")");
  return text;
}

Result<std::string> read_bounded(const std::filesystem::path& path, const ReadLimits& limits) {
  try {
    return read_opened(path, limits);
  } catch (const std::exception& e) {  // out of memory building the text or a message
    return Status{ErrorCode::io_error, std::string("cannot read a file: ") + e.what()};
  }
}

}  // namespace ocean::io
