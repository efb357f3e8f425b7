// The subcommands of the ocean tool. Each add_* registers its flags on the parent and returns
// the subcommand with the function that runs it.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <vector>

namespace ocean::cli {

struct Command {
  CLI::App* app;             ///< the registered subcommand
  std::function<int()> run;  ///< runs it after parsing; returns the process exit code
};

Command add_spectrum_command(CLI::App& app);
Command add_dispersion_command(CLI::App& app);
Command add_spreading_command(CLI::App& app);
Command add_stats_command(CLI::App& app);
Command add_bake_command(CLI::App& app);
Command add_info_command(CLI::App& app);
Command add_validate_command(CLI::App& app);
Command add_bench_command(CLI::App& app);
Command add_lod_command(CLI::App& app);
Command add_query_command(CLI::App& app);
// The optional subcommands: CMake compiles commands/<name>.cpp where the build has what the command
// needs, else commands/absent/<name>.cpp, whose add_* registers nothing and returns a Command with
// app = nullptr.
Command add_render_command(CLI::App& app);  // Vulkan builds only
Command add_view_command(CLI::App& app);    // builds with GLFW and Dear ImGui only
Command add_xr_command(CLI::App& app);      // builds with the OpenXR loader only

/// Registers every subcommand this build has (the optional ones above where it was built with
/// them), in the order `ocean --help` lists them.
std::vector<Command> add_commands(CLI::App& app);

}  // namespace ocean::cli
