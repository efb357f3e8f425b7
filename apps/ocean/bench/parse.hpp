// `ocean bench`'s list flags: comma-separated integers, each checked by its NumberOption, with
// the messages the tool has always printed.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "ocean/core.hpp"
#include "options.hpp"

namespace ocean::cli::bench {

/// Integers separated by commas, each accepted by `item` (an integer_in_range option); with
/// allow_all, "all" is accepted and given as 0, and the range message adds " or 'all'". An
/// empty text is "<flag> is empty"; a trailing comma is ignored.
Result<std::vector<int>> parse_ints(const NumberOption<int>& item, const std::string& text,
                                    bool allow_all);

/// Runner names separated by commas, each one of tbb, ready: "--runner = '<name>' is unknown:
/// must be one of tbb, ready" otherwise; an empty list is "--runner is empty".
Result<std::vector<std::string>> parse_runners(const std::string& text);

/// Every (a, b) pair, a in the outer loop.
template <typename A, typename B>
std::vector<std::pair<A, B>> product(const std::vector<A>& as, const std::vector<B>& bs) {
  std::vector<std::pair<A, B>> out;
  for (const A& a : as)
    for (const B& b : bs) out.emplace_back(a, b);
  return out;
}

}  // namespace ocean::cli::bench
