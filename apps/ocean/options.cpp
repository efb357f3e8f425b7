// Registration of the tool's number flags on CLI11 commands (see options.hpp).
#include "options.hpp"

namespace ocean::cli {

Status refuse_empty_values(const CLI::App& command) {
  for (const CLI::Option* option : command.get_options()) {
    if (option->get_items_expected_min() == 0) continue;  // a switch: no value
    for (const std::string& value : option->results()) {
      if (value.empty())
        return invalid_argument(option->get_name() +
                                " is empty: give a value or leave the flag out");
    }
  }
  for (const CLI::App* sub : command.get_subcommands()) {
    if (Status s = refuse_empty_values(*sub); !s.ok()) return s;
  }
  return {};
}

}  // namespace ocean::cli
