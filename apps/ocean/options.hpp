// The ocean tool's number flags: the typed parameters of ocean/parameters.hpp (declared once,
// parsed and checked by the library, so Python and the C API give the same messages) and their
// registration on CLI11 commands.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "ocean/parameters.hpp"

namespace ocean::cli {

using params::Accept;
using params::check;
using params::Echo;
using params::NumberOption;
using params::parse;
using params::parse_list;
using params::parse_number;
using params::parse_number_list;
using params::parse_triple;

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

}  // namespace ocean::cli
