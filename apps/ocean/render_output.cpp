// The rendered picture's PNG and the validation verdict (see render_output.hpp).
#include "render_output.hpp"

#include <string>

#include "ocean/io.hpp"
#include "ocean/memory_budget.hpp"
#include "ocean/render.hpp"

namespace ocean::cli {

Status check_picture_memory(int width, int height, std::uint64_t bytes_per_pixel,
                            std::string_view what) {
  const std::uint64_t pixels =
      static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  std::string asked = "--width " + std::to_string(width) + " --height " + std::to_string(height);
  asked.append(": rendering ").append(what);
  return require_memory(asked, pixels * (render::kReadbackBytesPerPixel + bytes_per_pixel));
}

Status write_srgb_png(const std::filesystem::path& path, int width, int height,
                      const std::vector<std::uint8_t>& rgba) {
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::vector<std::uint8_t> rgb(n * 3);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t c = 0; c < 3; ++c) rgb[3 * i + c] = rgba[4 * i + c];
  return io::write_png8(path, width, height, 3, rgb.data());
}

Status validation_status(const vk::Context& context) {
  const std::uint32_t messages = context.validation_messages.load();
  if (!context.validation || messages == 0) return {};
  return {ErrorCode::internal,
          "Vulkan validation reported " + std::to_string(messages) +
              " messages; last: " + excerpt(context.last_validation_message, 300)};
}

}  // namespace ocean::cli
