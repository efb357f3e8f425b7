// src/bake/checksum.hpp — the CRC-32 a manifest records for every file, and a file read only when
// it is a regular file reached without a symbolic link (private to the bake module).
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>

#include "ocean/core.hpp"

namespace ocean::bake::detail {

/// `crc` (the CRC-32 of the bytes before, 0 for none) extended over `bytes`: CRC-32 as zlib,
/// PNG, gzip and Python's zlib.crc32 compute it (reflected polynomial 0xEDB88320, initial value
/// and final XOR 0xFFFFFFFF; "123456789" gives 0xCBF43926). Pure; never allocates.
std::uint32_t crc32_update(std::uint32_t crc, std::span<const std::byte> bytes) noexcept;

/// `crc` as the manifest writes it: eight lower-case hexadecimal digits.
std::string crc32_hex(std::uint32_t crc);

/// What a manifest records of a file.
struct FileSum {
  std::uint64_t bytes = 0;  ///< size
  std::uint32_t crc32 = 0;  ///< CRC-32 of its bytes
};

/// Called with each block of a file's bytes in order; a non-ok Status stops the read.
using BlockSink = std::function<Status(std::span<const std::byte>)>;

/// What `mode` is, for a message: "a symbolic link", "a FIFO, not a regular file", "a
/// directory, not a regular file"...; empty for a regular file.
std::string not_regular(mode_t mode);

/// The size of the file at `path` (lstat: a symbolic link is not followed), or the reason it is
/// not a plain file, worded to follow its quoted name: invalid_argument "is a symbolic link",
/// "is a FIFO, not a regular file"...; io_error "is missing" or "cannot be read: <strerror>".
/// Never opens the file. Never throws.
Result<std::uint64_t> plain_file_size(const std::filesystem::path& path) noexcept;

/// Reads the regular file at `path` whole, never through a symbolic link (O_NOFOLLOW) and never
/// opening anything but what lstat found a regular file (checked again with fstat on the open
/// file, same device and inode), passing each block to `sink` (when set); returns its size and
/// CRC-32. Errors as plain_file_size, or `sink`'s Status. Blocking; allocates a buffer of the
/// file's size, at most 1 MiB. Never throws.
Result<FileSum> read_plain_file(const std::filesystem::path& path, const BlockSink& sink) noexcept;

}  // namespace ocean::bake::detail
