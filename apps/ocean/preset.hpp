// Simulation presets: SimulationConfig ⇄ JSON, preset files, `--set key=value` overrides and
// the sea-state flags shared with `ocean spectrum`.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "ocean/sim.hpp"

namespace ocean::cli {

/// The JSON form of a configuration (every key, units in the names; unset numbers are null).
nlohmann::ordered_json to_json(const SimulationConfig& config);
/// Reads a configuration; unknown keys and wrong types are invalid_argument naming the key path
/// ("sea.wind_sea.fetch_m: expected a number, got a string").
Result<SimulationConfig> from_json(const nlohmann::ordered_json& document);

/// Flags every simulating subcommand shares: a preset, overrides, the sea-state flags of
/// `ocean spectrum`, and the grid.
struct SimulationFlags {
  std::string preset_path;
  std::vector<std::string> set;  ///< key=value, dotted keys, JSON values (strings may be bare)
  SpectrumFlags sea;
  std::string resolution, seed, choppiness, cascades, normals, loop_period;
};
void add_simulation_flags(CLI::App& command, SimulationFlags& flags);
/// Default config ← preset file ← --set overrides ← explicit flags; then validated.
Result<SimulationConfig> resolve_config(const SimulationFlags& flags);

}  // namespace ocean::cli
