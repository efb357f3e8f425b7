// src/bake/shard_manifest.hpp — the manifests of a sharded bake read and checked before a merge
// touches anything (private to the bake module).
#pragma once

#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

#include "checksum.hpp"
#include "manifest.hpp"
#include "ocean/bake.hpp"

namespace ocean::bake::detail {

/// One shard's folder and its manifest.
struct ShardManifest {
  std::filesystem::path dir;
  Json manifest;  ///< the whole document, keys in their written order
  Shard shard;
  FrameRange frames;
  /// The files of each of its frames, the frame's "_f<fffff>" written "_f#" (the same list for
  /// every frame of a shard, and of every shard of one bake).
  std::vector<std::string> file_pattern;
};

/// Reads <dir>/manifest.json (io::read_bounded: at most kMaxManifestBytes, a regular file, not
/// through a symbolic link) and checks that it is a complete shard's: a "shard" entry agreeing
/// with shard_frames(), "complete": true, a start time, its frames listed in order at
/// start_time_s + f/fps, each listing the files of its frame only with a size and a CRC-32 per
/// file, each file a plain name, in `dir` a regular file (lstat: never a link, never opened) of
/// the size listed. Errors name the folder (see merge() in ocean/bake.hpp). Never throws.
Result<ShardManifest> read_shard_manifest(const std::filesystem::path& dir) noexcept;

/// Checks that `shards` are the shards of one bake (every entry but the shard's own the same,
/// else "cannot merge: shard '<b>' differs from shard '<a>' in <entry> (<b's> vs <a's>)"), each
/// once and none missing, and sorts them by index. Errors name the folders and the missing
/// shard. Never throws.
Status check_shards(std::vector<ShardManifest>& shards) noexcept;

/// Reads every file the shards list (never through a link, nothing but a regular file) and
/// checks its size and CRC-32 against the manifest's; invalid_argument "cannot merge: shard <i>
/// of <n> in '<dir>': '<file>' has CRC-32 <x>, its manifest says <y>: ..." otherwise. Checks
/// `cancel` before each file (ErrorCode::cancelled). Blocking; reads every byte once. Never
/// throws.
Status check_files(const std::vector<ShardManifest>& shards,
                   const std::atomic<bool>* cancel) noexcept;

/// "shard <i> of <n> in '<dir>'".
std::string shard_place(const ShardManifest& s);

/// "cannot merge: shard <i> of <n> in '<dir>': " — how a refusal about one shard's folder
/// begins.
std::string shard_prefix(const ShardManifest& s);

/// The size and CRC-32 the manifest lists for file `i` of `frame` (a frame entry that
/// read_shard_manifest accepted).
FileSum listed_sum(const Json& frame, std::size_t i);

/// The refusal of a file whose size or CRC-32 is not its manifest's: "'<file>' holds 10 bytes,
/// its manifest says 12: the file changed after the bake; bake the shard again" (or "has CRC-32
/// <x>, its manifest says <y>: ..."); empty when `got` is `listed`.
std::string sum_mismatch(const std::string& file, const FileSum& got, const FileSum& listed);

}  // namespace ocean::bake::detail
