// The flags every simulating subcommand shares: a preset, `--set key=value` overrides, the
// sea-state flags of `ocean spectrum`, and the grid. The preset format itself is the library's
// (ocean/preset.hpp).
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "ocean/preset.hpp"
#include "ocean/sim.hpp"

namespace ocean::cli {

/// The preset document of a configuration as a JSON value (ocean::preset::to_json), for
/// embedding in the tool's JSON outputs.
nlohmann::ordered_json to_json(const SimulationConfig& config);

struct SimulationFlags {
  std::string preset_path;
  std::vector<std::string> set;  ///< key=value, dotted keys, JSON values (strings may be bare)
  SpectrumFlags sea;
  std::string resolution, seed, choppiness, cascades, normals, loop_period, band_roles;
};
void add_simulation_flags(CLI::App& command, SimulationFlags& flags);
/// Default config ← preset file ← --set overrides ← explicit flags; then validated.
Result<SimulationConfig> resolve_config(const SimulationFlags& flags);
/// The picture settings of the preset file and the --set overrides (ocean/preset.hpp), for
/// `ocean render` and `ocean view`; their flags override them.
Result<preset::PictureSettings> resolve_picture(const SimulationFlags& flags);

}  // namespace ocean::cli
