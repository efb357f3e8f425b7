// The picture flags shared by `ocean render` and `ocean view` (see view_flags.hpp).
#include "view_flags.hpp"

#include <cmath>
#include <numbers>

#include "cli_common.hpp"

namespace ocean::cli {

void add_view_flags(CLI::App& command, ViewFlags& f, const std::string& what) {
  command.add_option("--width", f.width, what + " width, pixels (default " + f.width + ")");
  command.add_option("--height", f.height, what + " height, pixels (default " + f.height + ")");
  command.add_option("--camera", f.camera, "eye X,Y,Z in metres, Y up (default " + f.camera + ")");
  command.add_option("--target", f.target,
                     "a point the camera looks at (default " + f.target + ")");
  command.add_option("--fov", f.fov, "vertical field of view, degrees (default " + f.fov + ")");
  command.add_option("--quality", f.quality,
                     "LOD quality: low, medium, high, ultra (default " + f.quality + ")");
  command.add_option(
      "--ocean-size", f.ocean_size,
      "side of the LOD square around the camera, m (256..8192, default " + f.ocean_size + ")");
  command.add_option("--view", f.view, "shaded, lod (colours by level) or wireframe");
  command.add_option("--backend", f.backend,
                     "simulation backend: cpu, or vulkan (its images are rendered with no copy)");
  command.add_flag("--validation", f.validation,
                   "enable the Khronos validation layer; fail if it reports anything");
}

Result<double> number_in(std::string_view flag, const std::string& text, double lo, double hi) {
  Result<double> v = parse_number(flag, text);
  if (!v.ok()) return v.status();
  if (Status s = require_in_range(flag, v.value(), lo, hi); !s.ok()) return s;
  return v.value();
}

Status parse_view_flags(const ViewFlags& f, int min_size, render::SceneParams& scene,
                        render::View& v) {
  if (f.backend != "cpu" && f.backend != "vulkan")
    return invalid_argument("--backend = " + f.backend + " cannot render: must be cpu or vulkan");
  scene.backend = f.backend;
  scene.validation = f.validation;
  Result<double> w = number_in("--width", f.width, min_size, 16384);
  if (!w.ok()) return w.status();
  Result<double> h = number_in("--height", f.height, min_size, 16384);
  if (!h.ok()) return h.status();
  if (w.value() != std::floor(w.value()) || h.value() != std::floor(h.value()))
    return invalid_argument("--width and --height must be whole numbers of pixels");
  scene.width = static_cast<int>(w.value());
  scene.height = static_cast<int>(h.value());
  Result<std::array<double, 3>> eye = parse_triple("--camera", f.camera);
  if (!eye.ok()) return eye.status();
  Result<std::array<double, 3>> target = parse_triple("--target", f.target);
  if (!target.ok()) return target.status();
  Result<double> fov = number_in("--fov", f.fov, 1.0, 170.0);
  if (!fov.ok()) return fov.status();
  v.camera = {.position_m = {eye.value()[0], eye.value()[1], eye.value()[2]},
              .target_m = {target.value()[0], target.value()[1], target.value()[2]},
              .fov_y_rad = fov.value() * std::numbers::pi / 180.0,
              .aspect = w.value() / h.value(),
              .near_m = 0.2,
              .far_m = 2.0e5};
  if (eye.value()[1] <= 0.0)
    return invalid_argument("--camera = " + f.camera +
                            ": the camera must be above the sea (Y > 0)");
  if (Status s = lod::validate(v.camera); !s.ok())
    return invalid_argument("--camera/--target: " + s.message());
  Result<lod::QualityPreset> preset = lod::parse_preset(f.quality);
  if (!preset.ok())
    return invalid_argument("--quality = " + f.quality +
                            " is not a quality: must be low, medium, high or ultra");
  v.quality = lod::quality_preset(preset.value());
  Result<double> size =
      number_in("--ocean-size", f.ocean_size, lod::kMinOceanSize_m, lod::kMaxOceanSize_m);
  if (!size.ok()) return size.status();
  v.ocean_size_m = size.value();
  Result<render::DebugView> debug = render::parse_debug_view(f.view);
  if (!debug.ok())
    return invalid_argument("--view = " + f.view +
                            " is not a view: must be shaded, lod or wireframe");
  v.debug = debug.value();
  return {};
}

}  // namespace ocean::cli
