// `ocean bench`'s list flags (see parse.hpp).
#include "bench/parse.hpp"

#include <sstream>

namespace ocean::cli::bench {

Result<std::vector<int>> parse_ints(const NumberOption<int>& item, const std::string& text,
                                    bool allow_all) {
  std::string says = "an integer in [" + std::to_string(static_cast<int>(item.lo)) + ", " +
                     std::to_string(static_cast<int>(item.hi)) + "]" +
                     (allow_all ? " or 'all'" : "");
  NumberOption<int> option = item;
  option.echo = Echo::quoted_text;
  option.says = says;
  std::vector<int> out;
  std::stringstream stream(text);
  std::string word;
  while (std::getline(stream, word, ',')) {
    if (allow_all && word == "all") {
      out.push_back(0);
      continue;
    }
    Result<int> v = parse(option, word);
    if (!v.ok()) return v.status();
    out.push_back(v.value());
  }
  if (out.empty()) return invalid_argument(std::string(item.flag) + " is empty");
  return out;
}

Result<std::vector<std::string>> parse_runners(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream stream(text);
  std::string word;
  while (std::getline(stream, word, ',')) {
    if (word != "tbb" && word != "ready")
      return invalid_argument("--runner = '" + excerpt(word) +
                              "' is unknown: must be one of tbb, ready");
    out.push_back(word);
  }
  if (out.empty()) return invalid_argument("--runner is empty");
  return out;
}

}  // namespace ocean::cli::bench
