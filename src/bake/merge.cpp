// src/bake/merge.cpp — the shards of a bake joined into one folder: every manifest and every
// file checked first (shard_manifest.hpp), then the output folder held as a bake holds it, the
// files copied frame by frame (each checked again as it is copied), and the manifest of the
// one-machine bake written last.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>
#include <utility>

#include "checksum.hpp"
#include "io/format_detail.hpp"
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

// Writes all of `bytes` to `fd`, retrying short writes and EINTR.
Status write_all(int fd, std::span<const std::byte> bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return io_error(io::errno_message(errno));
    bytes = bytes.subspan(static_cast<std::size_t>(n));
  }
  return {};
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

// Copies file `i` of `frame` from the shard's folder into the output folder, atomically, reading
// it as check_files did (never through a link, a regular file only) and checking the bytes
// copied against the manifest's size and CRC-32 once more: a file changed since the check never
// reaches the output.
Status copy_checked(const detail::ShardManifest& shard, const Json& frame, std::size_t i,
                    const fs::path& to) {
  const std::string& file = frame["files"][i].get_ref<const std::string&>();
  return io::write_atomically(to / file, [&](const fs::path& temporary) -> Status {
    io::detail::FdGuard out;
    out.fd = ::open(temporary.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC | O_NOFOLLOW);
    if (out.fd < 0) return io_error(io::errno_message(errno));
    Status written;
    const Result<detail::FileSum> sum =
        detail::read_plain_file(shard.dir / file, [&](std::span<const std::byte> block) {
          written = write_all(out.fd, block);
          return written;
        });
    if (!written.ok()) return written;  // the output's failure ("No space left on device")
    // The reason write_atomically reports after "cannot write '<output file>': ".
    const std::string from = detail::shard_place(shard) + ": ";
    if (!sum.ok())
      return {sum.status().code(), from + io::quoted(file) + " " + sum.status().message()};
    if (std::string why = detail::sum_mismatch(file, sum.value(), detail::listed_sum(frame, i));
        !why.empty())
      return invalid_argument(from + why);
    const int fd = std::exchange(out.fd, -1);
    if (::close(fd) != 0 && errno != EINTR) return io_error(io::errno_message(errno));
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
      for (std::size_t i = 0; i < frame["files"].size(); ++i) {
        if (cancelled(p)) {
          folder.remove(names);
          return {ErrorCode::cancelled, "cancelled"};
        }
        if (Status s = copy_checked(shard, frame, i, folder.dir()); !s.ok()) {
          folder.remove(names);
          return s;
        }
        names.push_back(frame["files"][i].get<std::string>());
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
    // Every byte checked before the output folder is touched.
    if (Status s = detail::check_files(shards, params.cancel); !s.ok()) return s;
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
