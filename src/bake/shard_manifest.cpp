// src/bake/shard_manifest.cpp — a shard's manifest read and checked, and the shards of one bake
// checked against each other: everything a merge verifies before it writes a file.
#include "shard_manifest.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>

#include "ocean/io.hpp"

namespace ocean::bake::detail {
namespace {

namespace fs = std::filesystem;

// "shard 1 of 4".
std::string shard_name(const Shard& s) {
  std::string text("shard ");
  text.append(std::to_string(s.index)).append(" of ").append(std::to_string(s.count));
  return text;
}

bool is_integer(const Json& j, const char* key, long long lo, long long hi) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number_integer() && it->get<long long>() >= lo &&
         it->get<long long>() <= hi;
}

// A file name a manifest may list: one plain, visible name inside the folder (never a path that
// would lead a merge to read or write outside the folders it was given).
bool plain_name(const Json& name) {
  if (!name.is_string()) return false;
  const std::string& text = name.get_ref<const std::string&>();
  return !text.empty() && text.size() <= 255 && text[0] != '.' &&
         text.find('/') == std::string::npos && text.find('\0') == std::string::npos &&
         text != kManifestName;
}

// The checks of read_shard_manifest on a parsed document; an empty string when it passes.
std::string shape_error(const Json& m, ShardManifest& out) {
  if (!m.is_object()) return "not a JSON object";
  const auto shard = m.find("shard");
  if (shard == m.end() || !shard->is_object())
    return "it has no \"shard\" entry (a bake made without --shard)";
  if (!is_integer(*shard, "count", 1, kMaxFrames) ||
      !is_integer(*shard, "index", 0, (*shard)["count"].get<long long>() - 1))
    return "\"shard\" needs an index 0 to count-1 and a count 1 to 1000000";
  if (!is_integer(m, "frame_count", 1, kMaxFrames)) return "\"frame_count\" is not 1 to 1000000";
  out.shard = {(*shard)["index"].get<long long>(), (*shard)["count"].get<long long>()};
  const long long frame_count = m["frame_count"].get<long long>();
  if (out.shard.count > frame_count) return "it has more shards than frames";
  out.frames = shard_frames(frame_count, out.shard);
  if (!is_integer(*shard, "first_frame", out.frames.first, out.frames.first) ||
      !is_integer(*shard, "last_frame", out.frames.end - 1, out.frames.end - 1))
    return "its first and last frames are not those of " + shard_name(out.shard);
  if (!m.contains("complete") || !m["complete"].is_boolean())
    return "\"complete\" is not true or false";
  return {};
}

// The frame and file checks of a complete shard; an empty string when they pass.
std::string frames_error(const ShardManifest& s) {
  static const Json kNone;
  const auto listed = s.manifest.find("frames");
  const Json& frames = listed == s.manifest.end() ? kNone : *listed;
  const long long count = s.frames.end - s.frames.first;
  if (!frames.is_array() || static_cast<long long>(frames.size()) != count ||
      !is_integer(s.manifest, "frames_written", count, count))
    return "it lists " + std::to_string(frames.is_array() ? frames.size() : 0) + " frames of " +
           std::to_string(count);
  for (long long k = 0; k < count; ++k) {
    const Json& frame = frames[static_cast<std::size_t>(k)];
    const long long f = s.frames.first + k;
    if (!frame.is_object() || !is_integer(frame, "index", f, f) || !frame.contains("files") ||
        !frame["files"].is_array())
      return "frame " + std::to_string(f) + " is not listed in order with its files";
    for (const Json& name : frame["files"]) {
      if (!plain_name(name))
        return "frame " + std::to_string(f) + " lists " + excerpt(name.dump()) +
               ", which is not a plain file name";
      std::error_code ec;
      if (!fs::is_regular_file(s.dir / name.get<std::string>(), ec))
        return "the folder lacks '" + name.get<std::string>() + "', which its manifest lists";
    }
  }
  return {};
}

}  // namespace

Result<ShardManifest> read_shard_manifest(const fs::path& dir) noexcept {
  try {
    ShardManifest out{.dir = dir};
    const fs::path path = dir / kManifestName;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      const int err = errno;
      return io_error("cannot read " + io::quoted(path) + ": " + io::errno_message(err));
    }
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    out.manifest = Json::parse(text, nullptr, false);
    if (out.manifest.is_discarded())
      return invalid_argument(io::quoted(path) + " is not a shard's manifest: not valid JSON");
    if (std::string why = shape_error(out.manifest, out); !why.empty())
      return invalid_argument(io::quoted(path) + " is not a shard's manifest: " + why);
    if (!out.manifest["complete"].get<bool>()) {
      return invalid_argument(shard_name(out.shard) + " in " + io::quoted(dir) +
                              " is incomplete (its manifest says \"complete\": false): bake it "
                              "again");
    }
    if (std::string why = frames_error(out); !why.empty())
      return invalid_argument(shard_name(out.shard) + " in " + io::quoted(dir) + ": " + why);
    return out;
  } catch (const std::exception& e) {  // out of memory for a huge manifest
    return io_error("cannot read the manifest in " + io::quoted(dir) + ": " + e.what());
  }
}

Status check_shards(std::vector<ShardManifest>& shards) noexcept {
  try {
    if (shards.empty()) return invalid_argument("merge needs at least one shard folder");
    const ShardManifest& a = shards.front();
    // Everything but the shard's own entries must be the same bake's.
    const auto own = [](const std::string& key) {
      return key == "shard" || key == "frames" || key == "frames_written";
    };
    for (const ShardManifest& b : shards) {
      if (b.shard.count != a.shard.count) {
        return invalid_argument(io::quoted(b.dir) + " is " + shard_name(b.shard) + " but " +
                                io::quoted(a.dir) + " is " + shard_name(a.shard) +
                                ": they are not shards of one bake");
      }
      for (const auto& [key, value] : a.manifest.items()) {
        if (own(key) || (b.manifest.contains(key) && b.manifest[key] == value)) continue;
        return invalid_argument(io::quoted(b.dir) + " is not a shard of the same bake as " +
                                io::quoted(a.dir) + ": \"" + key + "\" differs");
      }
      if (b.manifest.size() != a.manifest.size()) {
        return invalid_argument(io::quoted(b.dir) + " is not a shard of the same bake as " +
                                io::quoted(a.dir) + ": their manifests hold other entries");
      }
    }
    std::sort(shards.begin(), shards.end(), [](const ShardManifest& x, const ShardManifest& y) {
      return x.shard.index < y.shard.index;
    });
    for (std::size_t i = 1; i < shards.size(); ++i) {
      if (shards[i].shard.index == shards[i - 1].shard.index) {
        return invalid_argument(shard_name(shards[i].shard) +
                                " is given twice: " + io::quoted(shards[i - 1].dir) + " and " +
                                io::quoted(shards[i].dir));
      }
    }
    const long long frame_count = a.manifest["frame_count"].get<long long>();
    for (long long i = 0; i < a.shard.count; ++i) {
      const auto at = static_cast<std::size_t>(i);
      if (at < shards.size() && shards[at].shard.index == i) continue;
      const Shard missing{i, a.shard.count};
      const FrameRange r = shard_frames(frame_count, missing);
      const long long others = a.shard.count - static_cast<long long>(shards.size()) - 1;
      std::string message = shard_name(missing);
      message.append(r.end - r.first == 1 ? " is missing (frame " : " is missing (frames ")
          .append(std::to_string(r.first));
      if (r.end - r.first > 1) message.append(" to ").append(std::to_string(r.end - 1));
      message.append("; bake it with --shard ")
          .append(std::to_string(i))
          .append("/")
          .append(std::to_string(a.shard.count))
          .append(")");
      if (others > 0) message.append(", and ").append(std::to_string(others)).append(" more");
      return invalid_argument(std::move(message));
    }
    return {};
  } catch (const std::exception& e) {
    return io_error(std::string("cannot check the shards: ") + e.what());
  }
}

}  // namespace ocean::bake::detail
