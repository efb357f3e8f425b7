// io/atomic_file.hpp — crash-safe file replacement (temporary beside the target, fsync, rename).
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <span>
#include <string>

#include "ocean/core.hpp"

namespace ocean::io {

/// Produces the new contents of a file by writing them to `temporary`, which already exists
/// (empty) when the callback runs. Returns ok, or a Status whose message is the reason for the
/// failure (e.g. "No space left on device"); the message ends up in the final error unchanged.
using WriteCallback = std::function<ocean::Status(const std::filesystem::path& temporary)>;

/// Replaces (or creates) `path` with the file produced by `write`, so that at every moment `path`
/// either holds its old contents or the complete new ones — never a partial file.
///
/// Contract:
///  - Creates a new, uniquely named temporary ".<name>.tmp-<pid>-<counter>" in the directory of
///    `path` (permissions 0666 minus the umask), calls `write(temporary)`, fsyncs the temporary,
///    renames it over `path` and fsyncs the directory (best effort: a failing directory fsync
///    does not fail the call, the data are already complete).
///  - The directory of `path` must exist; it is not created (see ensure_directory).
///  - If `path` is a symbolic link, the link itself is replaced, not its target.
///  - On any failure the temporary is removed, `path` is untouched and the result is io_error
///    "cannot write '<path>': <reason>", the reason coming from errno (strerror text, e.g.
///    "No such file or directory") or from the message of the Status returned by `write`.
///    Exceptions thrown by `write` are caught and reported the same way.
///  - A `path` that is empty or does not end in a file name ("dir/", ".", "..") or an empty
///    callback is invalid_argument, and nothing is created.
///  - Never throws. Safe to call from several threads at once (distinct temporaries).
ocean::Status write_atomically(const std::filesystem::path& path, const WriteCallback& write);

/// Atomically replaces `path` with the concatenation of `parts` (write_atomically with a callback
/// that writes the bytes, retrying short writes and EINTR). Same contract as write_atomically.
/// Empty parts are allowed; no part is copied.
ocean::Status write_bytes_atomically(const std::filesystem::path& path,
                                     std::initializer_list<std::span<const std::byte>> parts);

/// Makes sure `dir` exists as a directory, creating it and any missing parents.
///
/// Contract: ok if `dir` is (or now is) a directory, including when it already existed or was
/// created concurrently by someone else; an empty `dir` means the current directory and is ok.
/// Otherwise io_error "cannot create directory '<dir>': <reason>", e.g. "'<component>' exists
/// and is not a directory" or "Permission denied". Never throws.
ocean::Status ensure_directory(const std::filesystem::path& dir);

/// Checks, before long work, that a file could be created at `path`: its directory (the
/// current one when `path` has none) exists and is writable. io_error "cannot write '<path>':
/// No such file or directory" or "...: Permission denied" otherwise. Never throws.
ocean::Status check_parent_writable(const std::filesystem::path& path);

/// The strerror text for an errno value, e.g. "No such file or directory". Never throws (returns
/// an empty string if even building the message fails).
std::string errno_message(int err) noexcept;

}  // namespace ocean::io
