// The ocean tool's subcommands, registered together (see commands.hpp).
#include "commands.hpp"

namespace ocean::cli {

std::vector<Command> add_commands(CLI::App& app) {
  return {
      add_spectrum_command(app), add_dispersion_command(app), add_spreading_command(app),
      add_stats_command(app),    add_bake_command(app),       add_bench_command(app),
      add_info_command(app),     add_validate_command(app),   add_lod_command(app),
      add_query_command(app),
#ifdef OCEAN_HAS_VULKAN
      add_render_command(app),
#endif
#ifdef OCEAN_HAS_VIEW
      add_view_command(app),
#endif
#ifdef OCEAN_HAS_XR
      add_xr_command(app),
#endif
  };
}

}  // namespace ocean::cli
