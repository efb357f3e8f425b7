// Shared pieces of the ocean command-line tool: error reporting, the spectrum flags that several
// subcommands accept, and JSON output. Number flags are parsed by options.hpp.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ocean/spectrum.hpp"
#include "options.hpp"

namespace ocean::cli {

/// Exit codes: 0 success, 1 a runtime failure (I/O), 2 a usage error (bad flag or value).
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

/// Prints "ocean: error: <message>" on stderr (with library field names rewritten to the flags
/// that set them) and returns the exit code for the status (2 for invalid arguments, else 1).
int report(const Status& status);
/// The message report() prints after "ocean: error: ": the status's message with library field
/// names rewritten to the flags that set them ("--hs = -1 is out of range: ...").
std::string flag_message(const Status& status);

/// The sea-state flags of `ocean spectrum`, reused by later subcommands.
struct SpectrumFlags {
  std::string model = "jonswap";
  std::string hs, tp, wind_speed, fetch, gamma, depth, gravity;
  std::string depth_factor = "exact";
  std::string fetch_law = "hasselmann";
  std::string normalization = "dnv";
  std::string phillips_amplitude, cutoff_length;
};
void add_spectrum_flags(CLI::App& command, SpectrumFlags& flags);
/// Turns the flags into validated-later parameters; parse errors name the flag. With no sea
/// state given at all, the default sea is U10 = 10 m/s over a 100 km fetch (the README's plot).
Result<FrequencySpectrumParams> to_params(const SpectrumFlags& flags);

/// Writes JSON to stdout, keys in insertion order (two-space indent, round-trip numbers).
void print_json(const nlohmann::ordered_json& value);

}  // namespace ocean::cli
