// ocean/parameters.hpp — typed number parameters: each number a front end takes (a flag of the
// `ocean` tool, a Python keyword, a C API field) is declared once with its name, the values it
// accepts and the type it yields, and one parser and one checker turn its text or value into
// that value or into the one error message for it, so every front end's messages read alike
// ("--width = -3 is out of range: must be in [1, 16384]"). Also the table of sea-state
// parameters: library field, flag, Python keyword and doc line of each.
//
// Contract: pure functions, thread-safe; nothing here allocates beyond the returned values.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ocean/core.hpp"

namespace ocean::params {

/// What a number flag accepts. NaN is never accepted; the messages are those of
/// ocean::require_finite, require_positive, require_non_negative and require_in_range.
enum class Accept {
  any_number,        ///< everything but NaN (±inf included): the library checks the value
  finite,            ///< "must be a finite number"
  positive,          ///< "must be > 0 and finite"
  non_negative,      ///< "must be >= 0 and finite"
  in_range,          ///< [lo, hi]: "must be in [lo, hi]" (shortest round-trip bounds)
  whole_in_range,    ///< [lo, hi] as in_range, then "<flag> = <text> must be a whole number"
  integer_in_range,  ///< "must be an integer in [lo, hi]" (bounds written as integers)
};

/// How a rejected value is shown in the message: the parsed value (shortest round-trip form),
/// the text as typed, or the text as typed in single quotes. Typed text is always shown as
/// ocean::excerpt writes it (at most 80 bytes, escaped), here and in every message below.
enum class Echo { value, text, quoted_text };

/// A number flag. `T` is the type the value is converted to once accepted (double, or an integer
/// type for the integer and whole rules). Declare one per flag, next to its registration.
template <class T>
struct NumberOption {
  std::string_view flag;  ///< "--width"
  Accept accept = Accept::any_number;
  double lo = -std::numeric_limits<double>::infinity();  ///< closed range, for the *_in_range rules
  double hi = std::numeric_limits<double>::infinity();
  Echo echo = Echo::value;
  std::string_view unit = {};  ///< written after the range, e.g. "ms": "must be in [0, 1000] ms"
  /// What the message says the value must be, where that is not the range itself (a bound the
  /// library checks later, or a sanity cap the user need not see); empty: from `accept`.
  std::string_view says = {};
};

/// Parses a scalar flag value ("3.5", "inf"); NaN is refused. The error names the flag:
/// "<flag> = '<text>' is not a number".
Result<double> parse_number(std::string_view flag, const std::string& text);
/// Parses a comma-separated list of numbers; empty lists and empty items are errors.
Result<std::vector<double>> parse_number_list(std::string_view flag, const std::string& text);
/// Parses "X,Y,Z": exactly three finite numbers. The error names the flag.
Result<std::array<double, 3>> parse_triple(std::string_view flag, const std::string& text);

/// Checks a parsed value against the option's rule; `text` is what the user typed (for the
/// messages that echo it). The one place the tool's range messages are written.
Status check(const NumberOption<double>& option, double value, const std::string& text);

/// The flag's text as a number that passed the option's rule, converted to T.
template <class T>
Result<T> parse(const NumberOption<T>& option, const std::string& text) {
  const NumberOption<double> spec{option.flag, option.accept, option.lo,  option.hi,
                                  option.echo, option.unit,   option.says};
  Result<double> v = parse_number(option.flag, text);
  if (!v.ok()) return v.status();
  if (Status s = check(spec, v.value(), text); !s.ok()) return s;
  return static_cast<T>(v.value());
}

/// A comma-separated list (parse_number_list), every item then checked against the option.
Result<std::vector<double>> parse_list(const NumberOption<double>& option, const std::string& text);

/// One parameter as every front end names it: the library's field (in messages and presets), the
/// `ocean` tool's flag, the Python keyword, the closed range of its valid values (the library's
/// own check reads it), its unit and a doc line (the flag's help and the keyword's doc).
struct ParameterDoc {
  std::string_view field;    ///< "significant_wave_height_m"
  std::string_view flag;     ///< "--hs"
  std::string_view keyword;  ///< "hs"
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  std::string_view unit;  ///< "m"; empty: dimensionless
  std::string_view doc;   ///< "significant wave height Hs, m (with --tp)"
};

/// The parameter of `table` whose field is `field`; a compile-time error when used in a constant
/// expression with a field the table lacks.
template <std::size_t N>
constexpr const ParameterDoc& parameter(const std::array<ParameterDoc, N>& table,
                                        std::string_view field) {
  for (const ParameterDoc& p : table)
    if (p.field == field) return p;
  throw "no such parameter";  // not a constant expression: a compile error where constexpr
}

/// `message` with every whole-word field name of `table` replaced by its flag ("--hs = -1 is out
/// of range: ..."), fields in table order; a name already written as a flag stays.
std::string with_flag_names(std::string message, std::span<const ParameterDoc> table);
/// `message` with every whole-word field name of `table` replaced by its keyword ("hs = -1 is
/// out of range: ..."), and every flag ("--wind-speed") by the keyword of the same name, hyphens
/// as underscores ("wind_speed"); a flag followed by a placeholder in capitals ("--fetch M")
/// becomes an assignment ("fetch=M"). The names a Python caller wrote.
std::string with_keyword_names(std::string message, std::span<const ParameterDoc> table);

}  // namespace ocean::params
