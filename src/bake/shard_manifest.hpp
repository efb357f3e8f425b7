// src/bake/shard_manifest.hpp — the manifests of a sharded bake read and checked before a merge
// touches anything (private to the bake module).
#pragma once

#include <filesystem>
#include <vector>

#include "manifest.hpp"
#include "ocean/bake.hpp"

namespace ocean::bake::detail {

/// One shard's folder and its manifest.
struct ShardManifest {
  std::filesystem::path dir;
  Json manifest;  ///< the whole document, keys in their written order
  Shard shard;
  FrameRange frames;
};

/// Reads <dir>/manifest.json and checks that it is a complete shard's: a "shard" entry agreeing
/// with shard_frames(), "complete": true, its frames listed in order, each file a plain name
/// present in `dir`. Errors name the folder (see merge() in ocean/bake.hpp). Never throws.
Result<ShardManifest> read_shard_manifest(const std::filesystem::path& dir) noexcept;

/// Checks that `shards` are the shards of one bake, each once and none missing, and sorts them
/// by index. Errors name the folders and the missing shard. Never throws.
Status check_shards(std::vector<ShardManifest>& shards) noexcept;

}  // namespace ocean::bake::detail
