// Output file names typed by a user, read as data: the frame-number field of an image sequence's
// name (`ocean render --out shot_%05d.png`) and the length limits every output flag shares. A
// name is never handed to printf or to a shell; the only `%` it may hold is the one field and
// `%%`. Free of the command line, so that a fuzz target can call it.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "ocean/core.hpp"

namespace ocean::cli {

/// Longest output name accepted, and longest component of it: Linux's PATH_MAX - 1 and NAME_MAX,
/// beyond which the kernel refuses a name anyway. Checked first, so that a huge name is refused
/// in a short message before any library echoes it.
inline constexpr std::size_t kMaxOutputNameBytes = 4095;
inline constexpr std::size_t kMaxOutputComponentBytes = 255;
/// Widest zero-padded frame-number field, N of %0Nd: 18 digits hold any long long frame count.
inline constexpr int kMaxFrameDigits = 18;

/// Ok, or a one-line invalid_argument naming `flag` and the name (ocean::excerpt) when the name is
/// empty, longer than kMaxOutputNameBytes, or has a component longer than
/// kMaxOutputComponentBytes. For every flag that names a file or directory to write.
Status check_output_name(std::string_view flag, std::string_view name);

/// An image sequence's name, split around its frame-number field.
struct OutputPattern {
  std::string head;       ///< text before the field (the whole name if none), `%%` read as `%`
  std::string tail;       ///< text after the field
  bool numbered = false;  ///< the name holds a field
  int digits = 0;         ///< N of %0Nd: the number is zero-padded to N digits; 0 for %d

  /// The name of a lone file (one frame, or a video): the name, its field (if any) filled with 0.
  [[nodiscard]] std::string name() const;
  /// Frame `frame` (>= 0) of a sequence: the field filled with the number, zero-padded to
  /// `digits` (a longer number is written whole); without a field, `_` and the number padded to
  /// five digits go before the extension: seq.png gives seq_00000.png, seq_00001.png, ...
  [[nodiscard]] std::string name_for(long long frame) const;
};

/// Reads a user's output name by the rule: at most one frame-number field, `%d` or `%0Nd` with N
/// from 1 to kMaxFrameDigits; `%%` is a percent sign; any other `%` is refused, as is a second
/// field; check_output_name's limits apply. Any other byte (quotes, `$`, spaces, newlines, bytes
/// that are not UTF-8) is part of the name. Errors: one line, invalid_argument,
/// "<flag> = '<name>' ..." with the name as ocean::excerpt writes it and the rule stated.
Result<OutputPattern> parse_output_pattern(std::string_view name, std::string_view flag = "--out");

}  // namespace ocean::cli
