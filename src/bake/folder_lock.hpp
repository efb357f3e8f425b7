// src/bake/folder_lock.hpp — one bake at a time per output folder (private to the bake module).
#pragma once

#include <filesystem>

#include "ocean/core.hpp"

namespace ocean::bake::detail {

/// An exclusive flock(2) on <dir>/.ocean-bake.lock (kLockFileName), which holds the holder's pid
/// as text. The kernel drops the lock when its holder dies, so a lock file left by a killed
/// process blocks nothing. Move-only; the destructor releases.
class FolderLock {
 public:
  FolderLock() = default;
  FolderLock(FolderLock&& other) noexcept;
  FolderLock& operator=(FolderLock&& other) noexcept;
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  ~FolderLock() { release(); }

  /// Takes the lock of the existing folder `dir` without waiting. io_error "'<dir>' is being
  /// baked by process <pid> (it holds '<lock file>')" if another process (or another FolderLock
  /// in this one) holds it; io_error "cannot write '<lock file>': <reason>" if the file cannot be
  /// created (an unwritable folder, a directory in its place). Never throws.
  static Result<FolderLock> take(const std::filesystem::path& dir);

  /// Removes the lock file, then drops the lock; nothing when not held. Never throws.
  void release() noexcept;

 private:
  int fd_ = -1;
  std::filesystem::path file_;
};

}  // namespace ocean::bake::detail
