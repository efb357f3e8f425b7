// `ocean render` in a build without Vulkan: not registered (commands.hpp).
#include "commands.hpp"

namespace ocean::cli {

Command add_render_command(CLI::App& /*app*/) { return {.app = nullptr, .run = {}}; }

}  // namespace ocean::cli
