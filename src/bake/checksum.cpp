// src/bake/checksum.cpp — CRC-32 and the plain-file read behind a manifest's sizes and CRC-32s.
//
// This work is based on:
//  - W3C, "Portable Network Graphics (PNG) Specification (Second Edition)", 2003, Annex D
//    "Sample Cyclic Redundancy Code implementation": the CRC-32 of ISO/IEC 3309 and ITU-T V.42
//    (reflected polynomial 0xEDB88320, register preset to and result inverted with 0xFFFFFFFF),
//    computed a byte at a time from a 256-entry table. zlib, gzip and Python's zlib.crc32 give
//    the same values.
//  - M. E. Kounavis and F. L. Berry, "A Systematic Approach to Building High Performance
//    Software-Based CRC Generators", ISCC 2005: "slicing-by-8", eight tables so that one step
//    takes eight bytes (about 1 byte per cycle instead of 1 per 6–8), exactly the same CRC.
// Why CRC-32 rather than a cryptographic hash: the manifest's sums catch files changed, truncated
// or swapped by accident or carelessness between the bake and the merge; whoever can write a
// shard's folder can rewrite its manifest too, so no hash would make a shard trustworthy, and
// CRC-32 needs no library and is one call away in every language (zlib.crc32).
#include "checksum.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>

#include "io/format_detail.hpp"
#include "ocean/io.hpp"

namespace ocean::bake::detail {
namespace {

using CrcTables = std::array<std::array<std::uint32_t, 256>, 8>;

// Table 0 is the PNG specification's (the CRC of each byte value); table s is the CRC of a byte
// followed by s zero bytes (Kounavis & Berry, §3).
constexpr CrcTables make_crc_tables() {
  CrcTables t{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int k = 0; k < 8; ++k) c = (c & 1U) != 0 ? 0xEDB88320U ^ (c >> 1U) : c >> 1U;
    t[0][i] = c;
  }
  for (std::size_t s = 1; s < 8; ++s) {
    for (std::size_t i = 0; i < 256; ++i) t[s][i] = (t[s - 1][i] >> 8U) ^ t[0][t[s - 1][i] & 0xFFU];
  }
  return t;
}

constexpr CrcTables kCrcTables = make_crc_tables();

// The standard check value (Williams, "A Painless Guide to CRC Error Detection Algorithms",
// CRC-32: check = 0xCBF43926 for the nine ASCII digits "123456789"), byte-at-a-time form.
constexpr bool crc_tables_check() {
  std::uint32_t c = 0xFFFFFFFFU;
  for (const char digit : {'1', '2', '3', '4', '5', '6', '7', '8', '9'})
    c = kCrcTables[0][(c ^ static_cast<std::uint32_t>(digit)) & 0xFFU] ^ (c >> 8U);
  return ~c == 0xCBF43926U;
}
static_assert(crc_tables_check());

Status cannot_read(int err) {
  return io_error(err == ENOENT ? std::string("is missing")
                                : "cannot be read: " + io::errno_message(err));
}

// lstat of `path`: a regular file's status, or the reason it is none.
Result<struct stat> plain_stat(const std::filesystem::path& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) return cannot_read(errno);
  if (std::string why = not_regular(st.st_mode); !why.empty()) return invalid_argument("is " + why);
  return st;
}

Result<FileSum> read_checked(const std::filesystem::path& path, const BlockSink& sink) {
  Result<struct stat> seen = plain_stat(path);
  if (!seen.ok()) return seen.status();
  io::detail::FdGuard file;
  // O_NONBLOCK: should a FIFO take the file's place after the lstat, its open does not wait for
  // a writer (the fstat below refuses it).
  do {
    file.fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
  } while (file.fd < 0 && errno == EINTR);
  if (file.fd < 0) {
    return errno == ELOOP ? invalid_argument("is a symbolic link") : cannot_read(errno);
  }
  struct stat st {};
  if (::fstat(file.fd, &st) != 0) return cannot_read(errno);
  if (std::string why = not_regular(st.st_mode); !why.empty()) return invalid_argument("is " + why);
  if (st.st_dev != seen.value().st_dev || st.st_ino != seen.value().st_ino)
    return invalid_argument("was replaced while it was read");
  // Blocks of the file's size up to 1 MiB: a bake's files are mostly smaller, and a buffer
  // larger than the file would be paged in for nothing.
  const std::size_t size = std::clamp<std::size_t>(static_cast<std::size_t>(st.st_size) + 1,
                                                   std::size_t{4096}, std::size_t{1} << 20);
  const std::unique_ptr<std::byte[]> block = std::make_unique_for_overwrite<std::byte[]>(size);
  FileSum sum;
  for (;;) {
    const ssize_t n = ::read(file.fd, block.get(), size);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return cannot_read(errno);
    if (n == 0) break;
    const std::span<const std::byte> got(block.get(), static_cast<std::size_t>(n));
    sum.crc32 = crc32_update(sum.crc32, got);
    sum.bytes += static_cast<std::uint64_t>(n);
    if (sink) {
      if (Status s = sink(got); !s.ok()) return s;
    }
  }
  return sum;
}

}  // namespace

std::uint32_t crc32_update(std::uint32_t crc, std::span<const std::byte> bytes) noexcept {
  const CrcTables& t = kCrcTables;
  const std::byte* p = bytes.data();
  std::size_t n = bytes.size();
  // Eight bytes as two little-endian words, whatever the machine's byte order.
  const auto word = [](const std::byte* at) {
    std::uint32_t w = 0;
    std::memcpy(&w, at, sizeof w);
    if constexpr (std::endian::native == std::endian::big)
      w = (w >> 24U) | ((w >> 8U) & 0xFF00U) | ((w << 8U) & 0xFF0000U) | (w << 24U);
    return w;
  };
  std::uint32_t c = ~crc;
  for (; n >= 8; p += 8, n -= 8) {
    const std::uint32_t lo = c ^ word(p);
    const std::uint32_t hi = word(p + 4);
    c = t[7][lo & 0xFFU] ^ t[6][(lo >> 8U) & 0xFFU] ^ t[5][(lo >> 16U) & 0xFFU] ^ t[4][lo >> 24U] ^
        t[3][hi & 0xFFU] ^ t[2][(hi >> 8U) & 0xFFU] ^ t[1][(hi >> 16U) & 0xFFU] ^ t[0][hi >> 24U];
  }
  for (; n > 0; ++p, --n) c = t[0][(c ^ static_cast<std::uint32_t>(*p)) & 0xFFU] ^ (c >> 8U);
  return ~c;
}

std::string crc32_hex(std::uint32_t crc) {
  char text[9];
  std::snprintf(text, sizeof text, "%08x", static_cast<unsigned>(crc));
  return text;
}

std::string not_regular(mode_t mode) {
  if (S_ISREG(mode)) return {};
  if (S_ISLNK(mode)) return "a symbolic link";
  return std::string(io::detail::file_kind(mode)) + ", not a regular file";
}

Result<std::uint64_t> plain_file_size(const std::filesystem::path& path) noexcept {
  try {
    Result<struct stat> st = plain_stat(path);
    if (!st.ok()) return st.status();
    return static_cast<std::uint64_t>(st.value().st_size);
  } catch (const std::exception& e) {  // out of memory for a message
    return io_error(std::string("cannot be read: ") + e.what());
  }
}

Result<FileSum> read_plain_file(const std::filesystem::path& path, const BlockSink& sink) noexcept {
  try {
    return read_checked(path, sink);
  } catch (const std::exception& e) {  // out of memory for the buffer or a message
    return io_error(std::string("cannot be read: ") + e.what());
  }
}

}  // namespace ocean::bake::detail
