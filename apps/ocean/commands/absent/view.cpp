// `ocean view` in a build without Vulkan, GLFW 3.3 and Dear ImGui: not registered (commands.hpp).
#include "commands.hpp"

namespace ocean::cli {

Command add_view_command(CLI::App& /*app*/) { return {.app = nullptr, .run = {}}; }

}  // namespace ocean::cli
