// src/bake/output_folder.hpp — the output folder of one bake, held as a transaction from the
// checks before the first frame to the manifest (private to the bake module).
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "folder_lock.hpp"
#include "ocean/core.hpp"

namespace ocean::bake::detail {

/// Checks, before any work, that a file could be written at `path` by io::write_atomically:
/// its folder exists and is writable, and `path` is absent, a regular file or a symbolic link
/// (which is replaced, not followed). io_error "cannot write '<path>': <reason>" ("No such file
/// or directory", "Permission denied", "it is a directory", "it is not a regular file").
/// Never throws.
Status check_output_file(const std::filesystem::path& path);

/// One bake's hold on its folder. open() creates it and locks it; begin() marks the start of
/// writing; until then the destructor undoes open() (a failed start leaves no folder it made),
/// afterwards it only releases the lock. Neither copyable nor movable.
class OutputFolder {
 public:
  OutputFolder() = default;
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;
  ~OutputFolder();

  /// Creates `dir` and its missing parents (remembering which), takes its FolderLock and checks
  /// `other_outputs` with check_output_file. On failure the folders it created are removed again
  /// and the error is returned: ensure_directory's, FolderLock::take's or the check's. Call once.
  Status open(const std::filesystem::path& dir,
              std::span<const std::filesystem::path> other_outputs);

  /// The start of writing, after open(): removes the temporaries of dead bakes (names of bake
  /// files in io::write_atomically's ".<name>.tmp-<pid>-<n>" form whose pid is no live process),
  /// then removes the old manifest.json and syncs the folder, so that no manifest describes the
  /// files about to be written even after a crash. io_error "cannot remove the old manifest
  /// '<path>': <reason>" (e.g. a directory in its place); the start has then failed.
  Status begin();

  /// Removes files of this bake by name (the unfinished frame's), best effort. Never throws.
  void remove(const std::vector<std::string>& names) const noexcept;

  [[nodiscard]] const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_;
  std::vector<std::filesystem::path> created_;  // folders open() made, deepest first
  FolderLock lock_;
  bool begun_ = false;

  void undo_open() noexcept;
};

}  // namespace ocean::bake::detail
