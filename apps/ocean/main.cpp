// The ocean command-line tool: one subcommand per file (cmd_*.cpp).
#include <CLI/CLI.hpp>
#include <iostream>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"ocean — spectral ocean surface simulation: spectra, dispersion, spreading"};
  app.name("ocean");
  app.require_subcommand(1);
  const std::vector<ocean::cli::Command> commands = {
      ocean::cli::add_spectrum_command(app), ocean::cli::add_dispersion_command(app),
      ocean::cli::add_spreading_command(app), ocean::cli::add_stats_command(app),
      ocean::cli::add_bake_command(app), ocean::cli::add_bench_command(app),
      ocean::cli::add_info_command(app), ocean::cli::add_validate_command(app),
      ocean::cli::add_lod_command(app),
#ifdef OCEAN_HAS_VULKAN
      ocean::cli::add_render_command(app),
#endif
#ifdef OCEAN_HAS_VIEW
      ocean::cli::add_view_command(app),
#endif
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help: printed on stdout, exit 0
    std::cerr << "ocean: error: " << e.what() << " (see ocean --help)\n";
    return ocean::cli::kExitUsage;
  }
  for (const ocean::cli::Command& command : commands) {
    if (command.app->parsed()) return command.run();
  }
  return ocean::cli::kExitUsage;
}
