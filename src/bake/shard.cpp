// src/bake/shard.cpp — which frames a shard of a bake holds, and the "I/N" text that names one.
#include <charconv>
#include <string>

#include "ocean/bake.hpp"

namespace ocean::bake {

FrameRange shard_frames(long long frame_count, const Shard& shard) {
  // index·F ≤ kMaxFrames² = 1e12: exact in 64 bits.
  return {shard.index * frame_count / shard.count, (shard.index + 1) * frame_count / shard.count};
}

Result<Shard> parse_shard(std::string_view text, std::string_view label) {
  const auto number = [](std::string_view digits, long long& value) {
    if (digits.empty() || digits.size() > 7) return false;  // kMaxFrames has 7 digits
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    return error == std::errc{} && end == digits.data() + digits.size();
  };
  const std::size_t slash = text.find('/');
  Shard shard;
  if (slash != std::string_view::npos && number(text.substr(0, slash), shard.index) &&
      number(text.substr(slash + 1), shard.count) && shard.count >= 1 &&
      shard.count <= kMaxFrames && shard.index >= 0 && shard.index < shard.count) {
    return shard;
  }
  std::string message(label);
  message.append(" = '")
      .append(excerpt(text))
      .append("' is not I/N: must be a shard index 0 to N-1, a slash and a count 1 to 1000000");
  return invalid_argument(std::move(message));
}

}  // namespace ocean::bake
