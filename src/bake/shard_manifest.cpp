// src/bake/shard_manifest.cpp — one shard's manifest read under its size limit and checked:
// its shard entry, its frames in order and at their times, each frame's files its own, a plain
// name, a regular file of the size listed. What shard_set.cpp checks across the shards builds on
// it.
#include "shard_manifest.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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

bool is_number(const Json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() && std::isfinite(it->get<double>());
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

// Eight lower-case hexadecimal digits, as crc32_hex writes them.
bool crc_text(const Json& j) {
  if (!j.is_string() || j.get_ref<const std::string&>().size() != 8) return false;
  const std::string& text = j.get_ref<const std::string&>();
  return std::all_of(text.begin(), text.end(),
                     [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

// `name` with frame f's "_f<fffff>" (followed by '.' or '_', found once) written "_f#"; empty
// when the name is not one of frame f's.
std::string pattern_of(const std::string& name, long long f) {
  char tag[32];
  std::snprintf(tag, sizeof tag, "_f%05lld", f);
  const std::string_view t(tag);
  const std::size_t at = name.find(t);
  const std::size_t after = at + t.size();
  if (at == std::string::npos || after >= name.size() ||
      (name[after] != '.' && name[after] != '_') || name.find(t, at + 1) != std::string::npos) {
    return {};
  }
  return name.substr(0, at) + "_f#" + name.substr(after);
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
  if (!is_number(m, "fps") || !(m["fps"].get<double>() > 0)) return "\"fps\" is not a number > 0";
  if (m.contains("start_time_s") && !is_number(m, "start_time_s"))
    return "\"start_time_s\" is not a finite number";
  return {};
}

// Whether the manifest predates the start time and the files' sizes and CRC-32s.
bool older_format(const ShardManifest& s) {
  if (!s.manifest.contains("start_time_s")) return true;
  const auto frames = s.manifest.find("frames");
  if (frames == s.manifest.end() || !frames->is_array()) return false;
  return std::any_of(frames->begin(), frames->end(), [](const Json& frame) {
    return frame.is_object() && !frame.contains("bytes") && !frame.contains("crc32");
  });
}

// Checks frame f's file i: a plain name of frame f's, a regular file of the size listed.
std::string file_error(const ShardManifest& s, const Json& frame, std::size_t i, long long f,
                       std::vector<std::string>& pattern) {
  const Json& name = frame["files"][i];
  const std::string at = "frame " + std::to_string(f) + " lists ";
  if (!plain_name(name)) return at + excerpt(name.dump()) + ", which is not a plain file name";
  const std::string& file = name.get_ref<const std::string&>();
  pattern.push_back(pattern_of(file, f));
  if (pattern.back().empty())
    return at + io::quoted(file) + ", which is not a file of frame " + std::to_string(f);
  if (!frame["bytes"][i].is_number_unsigned() || !crc_text(frame["crc32"][i]))
    return at + io::quoted(file) + " without a size in bytes and an eight-digit CRC-32";
  std::error_code ec;
  if (fs::symlink_status(s.dir / file, ec).type() == fs::file_type::not_found)
    return "the folder lacks " + io::quoted(file) + ", which its manifest lists";
  const Result<std::uint64_t> size = plain_file_size(s.dir / file);
  if (!size.ok()) return io::quoted(file) + " " + size.status().message();
  return sum_mismatch(file, {.bytes = size.value()}, {.bytes = listed_sum(frame, i).bytes});
}

// The frame and file checks of a complete shard; an empty string when they pass.
std::string frames_error(ShardManifest& s) {
  static const Json kNone;
  const auto listed = s.manifest.find("frames");
  const Json& frames = listed == s.manifest.end() ? kNone : *listed;
  const long long count = s.frames.end - s.frames.first;
  if (!frames.is_array() || static_cast<long long>(frames.size()) != count ||
      !is_integer(s.manifest, "frames_written", count, count))
    return "it lists " + std::to_string(frames.is_array() ? frames.size() : 0) + " frames of " +
           std::to_string(count);
  const double start_s = s.manifest["start_time_s"].get<double>();
  const double fps = s.manifest["fps"].get<double>();
  std::vector<std::string> pattern;
  for (long long k = 0; k < count; ++k) {
    const Json& frame = frames[static_cast<std::size_t>(k)];
    const long long f = s.frames.first + k;
    const std::string at = "frame " + std::to_string(f);
    if (!frame.is_object() || !is_integer(frame, "index", f, f) || !frame.contains("files") ||
        !frame["files"].is_array())
      return at + " is not listed in order with its files";
    // The time bake() gives frame f, computed the same way (so equal to the last bit).
    const double t = start_s + static_cast<double>(f) / fps;
    if (!is_number(frame, "time_s") || frame["time_s"].get<double>() != t) {
      const std::string was = !frame.contains("time_s") ? std::string("(none)")
                              : is_number(frame, "time_s")
                                  ? format_number(frame["time_s"].get<double>())
                                  : excerpt(frame["time_s"].dump());
      return at + " is at time_s " + was + ", not start_time_s + " + std::to_string(f) +
             "/fps = " + format_number(t);
    }
    const std::size_t files = frame["files"].size();
    for (const char* key : {"bytes", "crc32"}) {
      if (!frame.contains(key) || !frame[key].is_array() || frame[key].size() != files)
        return at + "'s \"" + key + "\" does not list one entry per file";
    }
    pattern.clear();
    for (std::size_t i = 0; i < files; ++i) {
      if (std::string why = file_error(s, frame, i, f, pattern); !why.empty()) return why;
    }
    std::vector<std::string> sorted = pattern;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      return at + " lists a file twice";
    if (k == 0) {
      s.file_pattern = pattern;
    } else if (pattern != s.file_pattern) {
      return at + " lists other files than frame " + std::to_string(s.frames.first);
    }
  }
  return {};
}

}  // namespace

std::string shard_place(const ShardManifest& s) {
  return shard_name(s.shard) + " in " + io::quoted(s.dir);
}

std::string shard_prefix(const ShardManifest& s) {
  return "cannot merge: " + shard_place(s) + ": ";
}

FileSum listed_sum(const Json& frame, std::size_t i) {
  const std::string& crc = frame["crc32"][i].get_ref<const std::string&>();
  return {.bytes = frame["bytes"][i].get<std::uint64_t>(),
          .crc32 = static_cast<std::uint32_t>(std::stoul(crc, nullptr, 16))};
}

std::string sum_mismatch(const std::string& file, const FileSum& got, const FileSum& listed) {
  std::string why = io::quoted(file);
  if (got.bytes != listed.bytes) {
    why.append(" holds ").append(std::to_string(got.bytes)).append(" bytes, its manifest says ");
    why.append(std::to_string(listed.bytes));
  } else if (got.crc32 != listed.crc32) {
    why.append(" has CRC-32 ").append(crc32_hex(got.crc32)).append(", its manifest says ");
    why.append(crc32_hex(listed.crc32));
  } else {
    return {};
  }
  return why.append(": the file changed after the bake; bake the shard again");
}

Result<ShardManifest> read_shard_manifest(const fs::path& dir) noexcept {
  try {
    ShardManifest out{.dir = dir};
    const fs::path path = dir / kManifestName;
    Result<std::string> text = io::read_bounded(path, {.max_bytes = kMaxManifestBytes,
                                                       .what = "manifest",
                                                       .regular_only = true,
                                                       .no_follow = true});
    if (!text.ok()) return text.status();
    out.manifest = Json::parse(text.value(), nullptr, false);
    if (out.manifest.is_discarded())
      return invalid_argument(io::quoted(path) + " is not a shard's manifest: not valid JSON");
    if (std::string why = shape_error(out.manifest, out); !why.empty())
      return invalid_argument(io::quoted(path) + " is not a shard's manifest: " + why);
    if (!out.manifest["complete"].get<bool>()) {
      return invalid_argument(shard_name(out.shard) + " in " + io::quoted(dir) +
                              " is incomplete (its manifest says \"complete\": false): bake it "
                              "again");
    }
    if (older_format(out)) {
      return invalid_argument(shard_prefix(out) +
                              "its manifest records no start time, file sizes or CRC-32s (an "
                              "older ocean wrote it): bake the shard again");
    }
    if (std::string why = frames_error(out); !why.empty())
      return invalid_argument(shard_prefix(out) + why);
    return out;
  } catch (const std::exception& e) {  // out of memory for a large manifest
    return io_error("cannot read the manifest in " + io::quoted(dir) + ": " + e.what());
  }
}

}  // namespace ocean::bake::detail
