// `ocean bench`'s list flags: comma-separated integers, each checked by its NumberOption, with
// the messages the tool has always printed.
#pragma once

#include <string>
#include <vector>

#include "ocean/core.hpp"
#include "options.hpp"

namespace ocean::cli::bench {

/// Integers separated by commas, each accepted by `item` (an integer_in_range option); with
/// allow_all, "all" is accepted and given as 0, and the range message adds " or 'all'". An
/// empty text is "<flag> is empty"; a trailing comma is ignored.
Result<std::vector<int>> parse_ints(const NumberOption<int>& item, const std::string& text,
                                    bool allow_all);

}  // namespace ocean::cli::bench
