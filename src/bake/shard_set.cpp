// src/bake/shard_set.cpp — the shards of one bake checked against each other (every entry that
// changes the frames the same, each shard once, none missing) and every file they list read and
// checked against its size and CRC-32: the last checks before a merge writes anything.
#include <algorithm>
#include <optional>
#include <string>

#include "ocean/io.hpp"
#include "shard_manifest.hpp"

namespace ocean::bake::detail {
namespace {

// "shard 1 of 4".
std::string set_shard_name(const Shard& s) {
  std::string text("shard ");
  text.append(std::to_string(s.index)).append(" of ").append(std::to_string(s.count));
  return text;
}

// A manifest value as a refusal quotes it: numbers in their shortest exact form, the rest as
// JSON, cut to one short line.
std::string value_text(const Json& v) {
  if (v.is_number_float()) return format_number(v.get<double>());
  return excerpt(v.dump(), 60);
}

// Where `b` first differs from `a`, depth first in a's order: the entry's path ("config.seed",
// "cascades[0].resolution") and both values ("absent" for a missing entry).
struct Difference {
  std::string path, b_value, a_value;
};

std::string member_path(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

std::optional<Difference> first_difference(const Json& b, const Json& a, const std::string& path) {
  if (a.is_object() && b.is_object()) {
    for (const auto& [key, value] : a.items()) {
      const auto it = b.find(key);
      if (it == b.end()) return Difference{member_path(path, key), "absent", value_text(value)};
      if (auto d = first_difference(*it, value, member_path(path, key))) return d;
    }
    for (const auto& [key, value] : b.items()) {
      if (!a.contains(key)) return Difference{member_path(path, key), value_text(value), "absent"};
    }
    return std::nullopt;
  }
  if (a.is_array() && b.is_array() && a.size() == b.size()) {
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (auto d = first_difference(b[i], a[i], path + "[" + std::to_string(i) + "]")) return d;
    }
    return std::nullopt;
  }
  if (a == b) return std::nullopt;
  return Difference{path, value_text(b), value_text(a)};
}

// The entries of a shard's manifest that are its own: which shard, which frames. Every other
// entry describes the bake (its configuration, backend, frame count, fps, start time, formats,
// layout, cascades, local layer; generator too, which the merged manifest repeats) and must be
// the same in every shard.
bool own_entry(const std::string& key) {
  return key == "shard" || key == "frames" || key == "frames_written";
}

// Where shard b's manifest differs from a's in an entry of the bake.
std::optional<Difference> bake_difference(const Json& b, const Json& a) {
  Json b_bake = Json::object(), a_bake = Json::object();
  for (const auto& [key, value] : a.items()) {
    if (!own_entry(key)) a_bake[key] = value;
  }
  for (const auto& [key, value] : b.items()) {
    if (!own_entry(key)) b_bake[key] = value;
  }
  return first_difference(b_bake, a_bake, "");
}

std::string missing_message(const Shard& missing, long long frame_count, long long others) {
  const FrameRange r = shard_frames(frame_count, missing);
  std::string message = set_shard_name(missing);
  message.append(r.end - r.first == 1 ? " is missing (frame " : " is missing (frames ")
      .append(std::to_string(r.first));
  if (r.end - r.first > 1) message.append(" to ").append(std::to_string(r.end - 1));
  message.append("; bake it with --shard ")
      .append(std::to_string(missing.index))
      .append("/")
      .append(std::to_string(missing.count))
      .append(")");
  if (others > 0) message.append(", and ").append(std::to_string(others)).append(" more");
  return message;
}

}  // namespace

Status check_shards(std::vector<ShardManifest>& shards) noexcept {
  try {
    if (shards.empty()) return invalid_argument("merge needs at least one shard folder");
    const ShardManifest& a = shards.front();
    for (const ShardManifest& b : shards) {
      if (b.shard.count != a.shard.count) {
        return invalid_argument(io::quoted(b.dir) + " is " + set_shard_name(b.shard) + " but " +
                                io::quoted(a.dir) + " is " + set_shard_name(a.shard) +
                                ": they are not shards of one bake");
      }
      const auto refuse = [&](const std::string& what) {
        return invalid_argument("cannot merge: shard " + io::quoted(b.dir) +
                                " differs from shard " + io::quoted(a.dir) + " in " + what);
      };
      if (const std::optional<Difference> d = bake_difference(b.manifest, a.manifest))
        return refuse(d->path + " (" + d->b_value + " vs " + d->a_value + ")");
      if (b.file_pattern != a.file_pattern) {  // only a hand-edited manifest gets here
        return refuse("the files of each frame (" + excerpt(Json(b.file_pattern).dump(), 60) +
                      " vs " + excerpt(Json(a.file_pattern).dump(), 60) + ")");
      }
    }
    std::sort(shards.begin(), shards.end(), [](const ShardManifest& x, const ShardManifest& y) {
      return x.shard.index < y.shard.index;
    });
    for (std::size_t i = 1; i < shards.size(); ++i) {
      if (shards[i].shard.index == shards[i - 1].shard.index) {
        return invalid_argument(set_shard_name(shards[i].shard) +
                                " is given twice: " + io::quoted(shards[i - 1].dir) + " and " +
                                io::quoted(shards[i].dir));
      }
    }
    const long long frame_count = shards.front().manifest["frame_count"].get<long long>();
    const long long count = shards.front().shard.count;
    for (long long i = 0; i < count; ++i) {
      const auto at = static_cast<std::size_t>(i);
      if (at < shards.size() && shards[at].shard.index == i) continue;
      const long long others = count - static_cast<long long>(shards.size()) - 1;
      return invalid_argument(missing_message({i, count}, frame_count, others));
    }
    return {};
  } catch (const std::exception& e) {
    return io_error(std::string("cannot check the shards: ") + e.what());
  }
}

Status check_files(const std::vector<ShardManifest>& shards,
                   const std::atomic<bool>* cancel) noexcept {
  try {
    for (const ShardManifest& s : shards) {
      for (const Json& frame : s.manifest["frames"]) {
        const Json& files = frame["files"];
        for (std::size_t i = 0; i < files.size(); ++i) {
          if (cancel != nullptr && cancel->load(std::memory_order_relaxed))
            return {ErrorCode::cancelled,
                    "merge cancelled before its first frame; nothing written"};
          const std::string& file = files[i].get_ref<const std::string&>();
          const Result<FileSum> got = read_plain_file(s.dir / file, {});
          if (!got.ok()) {
            return {got.status().code(),
                    shard_prefix(s) + io::quoted(file) + " " + got.status().message()};
          }
          if (std::string why = sum_mismatch(file, got.value(), listed_sum(frame, i)); !why.empty())
            return invalid_argument(shard_prefix(s) + why);
        }
      }
    }
    return {};
  } catch (const std::exception& e) {
    return io_error(std::string("cannot check the shards' files: ") + e.what());
  }
}

}  // namespace ocean::bake::detail
