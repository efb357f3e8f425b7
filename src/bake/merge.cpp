// src/bake/merge.cpp — the shards of a bake joined into one folder: every manifest checked first
// (shard_manifest.hpp), then the output folder held as a bake holds it, the files copied frame by
// frame, and the manifest of the one-machine bake written last.
#include <system_error>

#include "manifest.hpp"
#include "ocean/bake.hpp"
#include "ocean/io.hpp"
#include "output_folder.hpp"
#include "shard_manifest.hpp"

namespace ocean::bake {
namespace {

namespace fs = std::filesystem;
using detail::Json;

bool cancelled(const MergeParams& p) {
  return p.cancel != nullptr && p.cancel->load(std::memory_order_relaxed);
}

// The manifest a one-machine bake writes, from a shard's: its entries in their order without
// "shard", "stopped" where bake() puts it, no frames yet.
Json merged_head(const Json& shard) {
  Json head = Json::object();
  for (const auto& [key, value] : shard.items()) {
    if (key == "shard") continue;
    head[key] = key == "frames" ? Json::array() : key == "frames_written" ? Json(0) : value;
    if (key == "frames_written") head["stopped"] = nullptr;
  }
  return head;
}

// Copies `from` to `to`, atomically.
Status copy_atomically(const fs::path& from, const fs::path& to) {
  return io::write_atomically(to, [&](const fs::path& temporary) -> Status {
    std::error_code ec;
    fs::copy_file(from, temporary, fs::copy_options::overwrite_existing, ec);
    if (ec) return io_error("copying from " + io::quoted(from) + ": " + ec.message());
    return {};
  });
}

// Copies every frame of every shard, in frame order, into the folder, listing in `manifest` the
// frames copied whole; returns what stopped the copy (ok when all were copied).
Status copy_frames(const std::vector<detail::ShardManifest>& shards, const MergeParams& p,
                   const detail::OutputFolder& folder, Json& manifest) {
  std::vector<std::string> names;
  long long copied = 0;
  for (const detail::ShardManifest& shard : shards) {
    for (const Json& frame : shard.manifest["frames"]) {
      names.clear();
      for (const Json& name : frame["files"]) {
        if (cancelled(p)) {
          folder.remove(names);
          return {ErrorCode::cancelled, "cancelled"};
        }
        const std::string& file = name.get_ref<const std::string&>();
        if (Status s = copy_atomically(shard.dir / file, folder.dir() / file); !s.ok()) {
          folder.remove(names);
          return s;
        }
        names.push_back(file);
      }
      manifest["frames"].push_back(frame);
      manifest["frames_written"] = ++copied;
    }
  }
  return {};
}

// Whether `dir` is the folder of one of the shards (merging into it would overwrite its manifest).
const detail::ShardManifest* same_folder(const fs::path& dir,
                                         const std::vector<detail::ShardManifest>& shards) {
  for (const detail::ShardManifest& s : shards) {
    std::error_code ec;
    if (fs::equivalent(dir, s.dir, ec)) return &s;
  }
  return nullptr;
}

}  // namespace

Status merge(std::span<const fs::path> shard_dirs, const MergeParams& params) {
  try {
    if (params.output_dir.empty()) return invalid_argument("merge needs an output directory");
    std::vector<detail::ShardManifest> shards;
    for (const fs::path& dir : shard_dirs) {
      Result<detail::ShardManifest> shard = detail::read_shard_manifest(dir);
      if (!shard.ok()) return shard.status();
      shards.push_back(std::move(shard).value());
    }
    if (Status s = detail::check_shards(shards); !s.ok()) return s;
    if (const detail::ShardManifest* s = same_folder(params.output_dir, shards)) {
      return invalid_argument("merge output " + io::quoted(params.output_dir) +
                              " is the folder of a shard (" + io::quoted(s->dir) +
                              "): merge into another folder");
    }
    detail::OutputFolder folder;
    if (Status s = folder.open(params.output_dir, {}); !s.ok()) return s;
    if (cancelled(params)) {
      return {ErrorCode::cancelled, "merge cancelled before its first frame; nothing written"};
    }
    if (Status s = folder.begin(); !s.ok()) return s;
    Json manifest = merged_head(shards.front().manifest);
    const Status stop = copy_frames(shards, params, folder, manifest);
    return detail::finish_manifest(folder.dir(), manifest, stop,
                                   manifest["frame_count"].get<long long>(), "merge");
  } catch (const std::exception& e) {  // out of memory
    return io_error(std::string("merge failed: ") + e.what());
  }
}

}  // namespace ocean::bake
