// Typed number options of the ocean command-line tool: each number flag is declared once with
// its name, the values it accepts and the type it yields, and one parser turns the flag's text
// into that value or into the tool's error message for it. Every subcommand parses its numbers
// here, so the messages ("--width = -3 is out of range: must be in [1, 16384]") read alike.
#pragma once

#include <CLI/CLI.hpp>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "ocean/core.hpp"

namespace ocean::cli {

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

/// Registers the option's flag on `command`, its text into `text` (parsed later with parse()).
template <class T>
CLI::Option* add_option(CLI::App& command, const NumberOption<T>& option, std::string& text,
                        const std::string& help) {
  return command.add_option(std::string(option.flag), text, help);
}

/// Refuses an empty value given to any option of `command` (and of its subcommands) that takes
/// one: `--shard ""` is invalid_argument "--shard is empty: give a value or leave the flag out",
/// never the flag left out. The flags keep their text empty for "not given", so this one check,
/// made after parsing and before the command runs, holds for every flag.
Status refuse_empty_values(const CLI::App& command);

/// A comma-separated list (parse_number_list), every item then checked against the option.
Result<std::vector<double>> parse_list(const NumberOption<double>& option, const std::string& text);

}  // namespace ocean::cli
