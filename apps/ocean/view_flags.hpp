// The picture flags `ocean render` and `ocean view` share: image size, camera, LOD quality,
// ocean size, debug view, backend and validation, parsed into the Scene and View they drive.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "ocean/far_field.hpp"
#include "ocean/render.hpp"
#include "ocean/scene.hpp"
#include "simulation_flags.hpp"
#include "sphere_flags.hpp"

namespace ocean::cli {

struct ViewFlags {
  std::string width = "1280", height = "720";
  std::string camera = "0,6,0", target = "300,-2,60", fov = "55";
  std::string quality = "high", ocean_size = "4096", view = "shaded";
  std::string backend = "cpu";
  // D_min,D_max of the far field (R.13), m; empty: the preset's far_field_range, else 1000,2500.
  std::string far_field_range;
  std::optional<render::FarFieldRange> preset_far_field;  // the preset's far_field_range
  // Texels per side of the far field's per-frame noise map (R.13b); 0: none, the analytic noise.
  std::string far_noise_resolution = std::to_string(render::kFarNoiseDefaultResolution);
  std::string planet_radius = "6371000";  // R of the sea's curvature (R.15), m; inf: flat
  std::string environment;                // equirectangular HDR OpenEXR sky (R.17); empty: none
  std::string mesh = "quadtree";          // quadtree or tessellation (R.40–R.42)
  // The water's scattering b, 1/m (R.51, R.66); empty: the preset's, else clear open ocean's.
  std::string scattering;
  std::optional<double> preset_scattering;  // the preset's underwater.scattering_per_m
  bool validation = false;
  SphereFlags sphere;  // --sphere, --latitude, --longitude, --altitude
};
/// Registers the flags; `what` names the image ("image" or "window") in the help.
void add_view_flags(CLI::App& command, ViewFlags& flags, const std::string& what);

/// Size, backend and validation into `scene`; camera, quality, ocean size, far-field range
/// (--far-field-range, else flags.preset_far_field, else render::FarFieldRange's default), the
/// water's scattering (--scattering, else flags.preset_scattering, else render::Underwater's) and
/// debug view into `view` (its shading is left alone); the far field's noise map
/// (--far-noise-resolution) into scene.config.far_noise, its window around the camera and sized
/// for the range (render::far_noise_window; off on a sphere, which draws no far field). `min_size`
/// is the smallest width/height accepted.
Status parse_view_flags(const ViewFlags& flags, int min_size, render::SceneParams& scene,
                        render::View& view);
/// The same under the picture settings of the preset `sim` names (resolve_picture): its
/// far_field_range where --far-field-range is not given, its underwater.scattering_per_m where
/// --scattering is not.
Status parse_view_flags(const ViewFlags& flags, const SimulationFlags& sim, int min_size,
                        render::SceneParams& scene, render::View& view);

/// `unsupported` naming the device when `view` asks for the tessellated mesh (--mesh
/// tessellation) and the device lacks tessellation shaders; checked before any work is done.
Status check_mesh_support(const render::View& view, const vk::Context& ctx);

/// invalid_argument naming the flag when temporal anti-aliasing (--taa, R.61) cannot follow the
/// motion vectors: --backend vulkan (its images are sampled in place, not uploaded), --sphere or
/// --mesh tessellation (no motion vectors drawn).
Status check_taa_support(const render::SceneParams& scene, const render::View& view);

}  // namespace ocean::cli
