// src/io/format_detail.hpp — small helpers the file-format writers share with the test readers
// (tests/support), which reach this private header through the source tree: error messages that
// name the path, a closing file-descriptor guard, the .npy prelude, element count and byte swap.
#pragma once

#include <sys/stat.h>
#include <unistd.h>

#include <bit>
#include <cerrno>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <span>
#include <string>

#include "ocean/core.hpp"
#include "ocean/io.hpp"

namespace ocean::io::detail {

/// "cannot <verb> '<path>': <why>".
inline std::string with_path(const char* verb, const std::filesystem::path& path,
                             const std::string& why) {
  std::string message = "cannot ";
  message.append(verb).append(" ").append(quoted(path)).append(": ").append(why);
  return message;
}

/// An io_error naming the path; never throws (drops the message if even that cannot be built).
inline Status failure(const char* verb, const std::filesystem::path& path,
                      const char* why) noexcept {
  try {
    return io_error(with_path(verb, path, why));
  } catch (...) {
    return {ErrorCode::io_error, std::string()};
  }
}

/// The kind of file `mode` describes, for a message: "a directory", "a FIFO", "a symbolic link"
/// (an lstat's mode)... (for a mode that is not a regular file's).
inline const char* file_kind(mode_t mode) {
  if (S_ISLNK(mode)) return "a symbolic link";
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  return "something else";
}

/// Closes the descriptor it holds when it goes out of scope.
struct FdGuard {
  int fd = -1;
  FdGuard() = default;
  FdGuard(const FdGuard&) = delete;
  FdGuard& operator=(const FdGuard&) = delete;
  ~FdGuard() {
    if (fd >= 0) ::close(fd);
  }
  /// Closes now and returns 0 or the errno of a failing close.
  int close_now() {
    const int result = ::close(fd) == 0 || errno == EINTR ? 0 : errno;
    fd = -1;
    return result;
  }
};

/// The .npy 1.0 prelude: the magic string, then major and minor version and the uint16 length
/// of the header that follows.
inline constexpr char kNpyMagic[] = "\x93NUMPY";
inline constexpr std::size_t kNpyMagicLen = 6;
inline constexpr std::size_t kNpyPreludeLen = 10;

/// Product of the dimensions, or nullopt when the element count or its byte size overflows.
inline std::optional<std::size_t> element_count(std::span<const std::size_t> shape) {
  std::size_t n = 1;
  for (const std::size_t d : shape) {
    if (d != 0 && n > std::numeric_limits<std::size_t>::max() / d) return std::nullopt;
    n *= d;
  }
  if (n > static_cast<std::size_t>(std::numeric_limits<std::ptrdiff_t>::max()) / sizeof(float)) {
    return std::nullopt;
  }
  return n;
}

/// Only used on big-endian hosts: .npy '<f4' data are little-endian.
inline void byte_swap(std::span<float> values) {
  for (float& v : values) {
    const auto u = std::bit_cast<std::uint32_t>(v);
    v = std::bit_cast<float>((u >> 24U) | ((u >> 8U) & 0xFF00U) | ((u << 8U) & 0xFF0000U) |
                             (u << 24U));
  }
}

}  // namespace ocean::io::detail
