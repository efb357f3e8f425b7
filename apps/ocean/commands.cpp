// The ocean tool's subcommands, registered together (see commands.hpp).
#include "commands.hpp"

#include <vector>

namespace ocean::cli {

std::vector<Command> add_commands(CLI::App& app) {
  std::vector<Command> all = {
      add_spectrum_command(app), add_dispersion_command(app), add_spreading_command(app),
      add_stats_command(app),    add_bake_command(app),       add_bench_command(app),
      add_info_command(app),     add_validate_command(app),   add_lod_command(app),
      add_query_command(app),    add_render_command(app),     add_view_command(app),
      add_xr_command(app),
  };
  std::erase_if(all, [](const Command& c) { return c.app == nullptr; });  // not in this build
  return all;
}

}  // namespace ocean::cli
