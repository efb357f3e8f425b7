// `ocean bench`'s flag parsers: comma-separated integer lists and range-checked scalars, with
// the messages the tool has always printed.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "ocean/core.hpp"

namespace ocean::cli::bench {

/// Integers in [lo, hi] separated by commas; with allow_all, "all" is accepted and given as 0.
Result<std::vector<int>> parse_ints(std::string_view flag, const std::string& text, int lo, int hi,
                                    bool allow_all);
/// A scalar flag value in [lo, hi] (bounds written as integers in the error, with their unit).
Result<double> parse_in_range(std::string_view flag, const std::string& text, double lo, double hi,
                              std::string_view unit);

}  // namespace ocean::cli::bench
