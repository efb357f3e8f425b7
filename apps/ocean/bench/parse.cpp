// `ocean bench`'s flag parsers.
#include "bench/parse.hpp"

#include <cmath>
#include <sstream>

#include "cli_common.hpp"

namespace ocean::cli::bench {

Result<std::vector<int>> parse_ints(std::string_view flag, const std::string& text, int lo, int hi,
                                    bool allow_all) {
  std::vector<int> out;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    if (allow_all && item == "all") {
      out.push_back(0);
      continue;
    }
    Result<double> v = parse_number(flag, item);
    if (!v.ok()) return v.status();
    if (v.value() != std::floor(v.value()) || v.value() < lo || v.value() > hi) {
      return invalid_argument(std::string(flag) + " = '" + item +
                              "' is out of range: must be an integer in [" + std::to_string(lo) +
                              ", " + std::to_string(hi) + "]" + (allow_all ? " or 'all'" : ""));
    }
    out.push_back(static_cast<int>(v.value()));
  }
  if (out.empty()) return invalid_argument(std::string(flag) + " is empty");
  return out;
}

Result<double> parse_in_range(std::string_view flag, const std::string& text, double lo, double hi,
                              std::string_view unit) {
  Result<double> v = parse_number(flag, text);
  if (!v.ok()) return v;
  if (!(v.value() >= lo && v.value() <= hi)) {
    return invalid_argument(std::string(flag) + " = " + text + " is out of range: must be in [" +
                            std::to_string(static_cast<long long>(lo)) + ", " +
                            std::to_string(static_cast<long long>(hi)) + "] " + std::string(unit));
  }
  return v;
}

}  // namespace ocean::cli::bench
