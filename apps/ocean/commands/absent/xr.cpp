// `ocean xr` in a build without the OpenXR loader: not registered (commands.hpp).
#include "commands.hpp"

namespace ocean::cli {

Command add_xr_command(CLI::App& /*app*/) { return {.app = nullptr, .run = {}}; }

}  // namespace ocean::cli
