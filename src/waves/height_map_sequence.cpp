// src/waves/height_map_sequence.cpp — a numbered sequence of height maps (W.16): the pattern's
// "{frame}" or "{frame:W}" placeholder matched against the names in its folder, the numbers
// checked to run without a gap, every frame read with load_height_map and checked to be of one
// size. Everything is read before anything is returned, so a bad sequence is refused whole.
#include <algorithm>
#include <cctype>
#include <map>
#include <string>
#include <system_error>

#include "ocean/waves.hpp"

namespace ocean::waves {
namespace {

// The pattern's file name split at its placeholder: prefix, digits (0: any count), suffix.
struct NamePattern {
  std::string prefix;
  std::string suffix;
  int width = 0;
};

Status bad(const std::filesystem::path& pattern, const std::string& why) {
  return invalid_argument("height map sequence '" + excerpt(pattern.string()) + "': " + why);
}

Result<NamePattern> split(const std::filesystem::path& pattern) {
  const std::string name = pattern.filename().string();
  const std::size_t at = name.find(kFramePlaceholder);
  if (at == std::string::npos) {
    return bad(pattern, "the file name must hold {frame} or {frame:W}" +
                            std::string(pattern.parent_path().string().find(kFramePlaceholder) !=
                                                std::string::npos
                                            ? " (not the folder's)"
                                            : ""));
  }
  const std::size_t close = name.find('}', at);
  if (close == std::string::npos) return bad(pattern, "the placeholder is not closed by '}'");
  NamePattern p{.prefix = name.substr(0, at), .suffix = name.substr(close + 1)};
  const std::string inside =
      name.substr(at + kFramePlaceholder.size(), close - at - kFramePlaceholder.size());
  if (!inside.empty()) {
    if (inside.size() != 2 || inside[0] != ':' || inside[1] < '1' || inside[1] > '9')
      return bad(pattern, "the placeholder must be {frame} or {frame:W} with W in 1..9");
    p.width = inside[1] - '0';
  }
  if (p.suffix.find(kFramePlaceholder) != std::string::npos)
    return bad(pattern, "the file name holds more than one placeholder");
  return p;
}

// The frame number of `name` under the pattern, or −1 when the name does not match.
long long number_of(const NamePattern& p, const std::string& name) {
  if (name.size() <= p.prefix.size() + p.suffix.size()) return -1;
  if (name.compare(0, p.prefix.size(), p.prefix) != 0) return -1;
  if (name.compare(name.size() - p.suffix.size(), p.suffix.size(), p.suffix) != 0) return -1;
  const std::string digits =
      name.substr(p.prefix.size(), name.size() - p.prefix.size() - p.suffix.size());
  if (digits.size() > 9 || (p.width > 0 && digits.size() != static_cast<std::size_t>(p.width)))
    return -1;
  for (char c : digits)
    if (!std::isdigit(static_cast<unsigned char>(c))) return -1;
  return std::stoll(digits);
}

}  // namespace

bool is_sequence_pattern(std::string_view pattern) {
  return pattern.find(kFramePlaceholder) != std::string_view::npos;
}

Result<std::vector<std::shared_ptr<const HeightMap>>> load_height_map_sequence(
    const std::filesystem::path& pattern) {
  Result<NamePattern> p = split(pattern);
  if (!p.ok()) return p.status();
  const std::filesystem::path folder =
      pattern.has_parent_path() ? pattern.parent_path() : std::filesystem::path(".");
  // Number → file name; a second name of one number ("7" and "007") is refused.
  std::map<long long, std::string> found;
  std::error_code ec;
  std::filesystem::directory_iterator it(folder, ec);
  if (ec) return bad(pattern, "cannot list its folder: " + ec.message());
  for (; it != std::filesystem::directory_iterator(); it.increment(ec)) {
    if (ec) return bad(pattern, "cannot list its folder: " + ec.message());
    const std::string name = it->path().filename().string();
    const long long n = number_of(p.value(), name);
    if (n < 0) continue;
    const auto [slot, inserted] = found.emplace(n, name);
    if (!inserted) {
      return bad(pattern, "two files are frame " + std::to_string(n) + ": '" +
                              excerpt(slot->second) + "' and '" + excerpt(name) + "'");
    }
    if (found.size() > static_cast<std::size_t>(kMaxSequenceFrames))
      return bad(pattern, "more than " + std::to_string(kMaxSequenceFrames) + " frames");
  }
  if (found.empty()) return bad(pattern, "no file matches");
  long long expected = found.begin()->first;
  for (const auto& [n, name] : found) {
    if (n != expected) {
      return bad(pattern, "frame " + std::to_string(expected) + " missing between " +
                              std::to_string(expected - 1) + " and " + std::to_string(n));
    }
    ++expected;
  }
  std::vector<std::shared_ptr<const HeightMap>> frames;
  frames.reserve(found.size());
  std::size_t samples = 0;
  for (const auto& [n, name] : found) {
    Result<HeightMap> map = load_height_map(folder / name);
    if (!map.ok()) return map.status();
    const HeightMap& first = frames.empty() ? map.value() : *frames.front();
    if (map.value().rows != first.rows || map.value().cols != first.cols) {
      return bad(pattern, "frame " + std::to_string(n) + " is " + std::to_string(map.value().rows) +
                              "x" + std::to_string(map.value().cols) + ", frame " +
                              std::to_string(found.begin()->first) + " " +
                              std::to_string(first.rows) + "x" + std::to_string(first.cols) +
                              ": every frame must be of one size");
    }
    samples += map.value().values.size();
    if (samples > kMaxSequenceSamples) {
      return bad(pattern, "its frames hold more than " + std::to_string(kMaxSequenceSamples) +
                              " samples together");
    }
    frames.push_back(std::make_shared<const HeightMap>(std::move(map).value()));
  }
  return frames;
}

}  // namespace ocean::waves
