// The picture flags shared by `ocean render` and `ocean view` (see view_flags.hpp).
#include "view_flags.hpp"

#include <cmath>
#include <numbers>

#include "options.hpp"

namespace ocean::cli {

namespace {
// How deep --camera may dive, m: far below, the water is the same dark fog everywhere.
constexpr double kDeepestCamera_m = 1000.0;
constexpr NumberOption<double> kFov{
    .flag = "--fov", .accept = Accept::in_range, .lo = 1.0, .hi = 170.0};
constexpr NumberOption<double> kFarFieldRange{.flag = "--far-field-range",
                                              .accept = Accept::non_negative};
// A planet smaller than a kilometre would bend the ocean square itself by more than its waves.
constexpr NumberOption<double> kPlanetRadius{.flag = "--planet-radius",
                                             .accept = Accept::in_range,
                                             .lo = 1000.0,
                                             .says = "a radius >= 1000 m, or inf for a flat sea"};
constexpr NumberOption<double> kScattering{
    .flag = "--scattering", .accept = Accept::in_range, .lo = 0.0, .hi = 10.0};
constexpr NumberOption<int> kFarNoiseResolution{
    .flag = "--far-noise-resolution", .accept = Accept::integer_in_range, .lo = 0, .hi = 4096};
constexpr NumberOption<double> kOceanSize{.flag = "--ocean-size",
                                          .accept = Accept::in_range,
                                          .lo = lod::kMinOceanSize_m,
                                          .hi = lod::kMaxOceanSize_m};
}  // namespace

void add_view_flags(CLI::App& command, ViewFlags& f, const std::string& what) {
  command.add_option("--width", f.width, what + " width, pixels (default " + f.width + ")");
  command.add_option("--height", f.height, what + " height, pixels (default " + f.height + ")");
  command.add_option("--camera", f.camera, "eye X,Y,Z in metres, Y up (default " + f.camera + ")");
  command.add_option("--target", f.target,
                     "a point the camera looks at (default " + f.target + ")");
  add_option(command, kFov, f.fov, "vertical field of view, degrees (default " + f.fov + ")");
  command.add_option("--quality", f.quality,
                     "LOD quality: " + name_list(lod::kQualityPresetNames, ", ", ", ") +
                         " (default " + f.quality + ")");
  add_option(
      command, kOceanSize, f.ocean_size,
      "side of the LOD square around the camera, m (256..8192, default " + f.ocean_size + ")");
  command.add_option("--far-field-range", f.far_field_range,
                     "DMIN,DMAX: distances, m, over which the simulated sea blends into the "
                     "far field's noise and hex-tiled cascades (default: the preset's "
                     "far_field_range, else 1000,2500)");
  add_option(command, kFarNoiseResolution, f.far_noise_resolution,
             "texels per side of the far field's per-frame noise map around the camera, drawn "
             "beyond DMIN (0: none, the noise evaluated per pixel; else " +
                 std::to_string(render::kFarNoiseMinResolution) + "..4096, default " +
                 f.far_noise_resolution + ")");
  add_option(command, kScattering, f.scattering,
             "the water's scattering coefficient b, 1/m (0..10): its turbidity, which sets the "
             "fog, the light shafts and the visibility 4.8/(a + b) under water (default: the "
             "preset's underwater.scattering_per_m, else 0.072, clear open ocean; coastal water "
             "about 0.3-1)");
  add_option(command, kPlanetRadius, f.planet_radius,
             "radius of the planet whose curvature bends the sea and sets the horizon, m; inf: "
             "a flat sea (default " +
                 f.planet_radius + ", Earth's)");
  command.add_option("--environment", f.environment,
                     "equirectangular HDR OpenEXR (R, G, B; twice as wide as high) for the sky, "
                     "its reflections and the fog, scaled by the sky's brightness");
  command.add_option(
      "--view", f.view,
      "shaded, lod (colours by level), wireframe or normals (the shading normal as colour)");
  command.add_option("--mesh", f.mesh,
                     "the sea's mesh: quadtree, or tessellation (a base grid subdivided by the "
                     "GPU's tessellation shaders; default " +
                         f.mesh + ")");
  command.add_option("--backend", f.backend,
                     "simulation backend: cpu, vulkan (its images are rendered with no copy) or "
                     "cuda (its frames written into the renderer's memory on the same GPU)");
  command.add_flag("--validation", f.validation,
                   "enable the Khronos validation layer; fail if it reports anything");
  add_sphere_flags(command, f.sphere);
}

Status parse_view_flags(const ViewFlags& f, int min_size, render::SceneParams& scene,
                        render::View& v) {
  if (f.backend != "cpu" && f.backend != "vulkan" && f.backend != "cuda")
    return invalid_argument("--backend = " + excerpt(f.backend) +
                            " cannot render: must be cpu, vulkan or cuda");
  scene.backend = f.backend;
  scene.validation = f.validation;
  const auto side = [min_size](std::string_view flag) {
    return NumberOption<double>{
        .flag = flag, .accept = Accept::in_range, .lo = static_cast<double>(min_size), .hi = 16384};
  };
  Result<double> w = parse(side("--width"), f.width);
  if (!w.ok()) return w.status();
  Result<double> h = parse(side("--height"), f.height);
  if (!h.ok()) return h.status();
  if (w.value() != std::floor(w.value()) || h.value() != std::floor(h.value()))
    return invalid_argument("--width and --height must be whole numbers of pixels");
  scene.width = static_cast<int>(w.value());
  scene.height = static_cast<int>(h.value());
  Result<std::array<double, 3>> eye = parse_triple("--camera", f.camera);
  if (!eye.ok()) return eye.status();
  Result<std::array<double, 3>> target = parse_triple("--target", f.target);
  if (!target.ok()) return target.status();
  Result<double> fov = parse(kFov, f.fov);
  if (!fov.ok()) return fov.status();
  Result<double> radius = parse(kPlanetRadius, f.planet_radius);
  if (!radius.ok()) return radius.status();
  v.planet_radius_m = radius.value();
  // The far plane reaches past the horizon √(2R·h) of a high eye (R.15); the near plane keeps
  // the depth buffer's precision for it.
  const double altitude = std::max(eye.value()[1], 0.0);
  const double horizon =
      std::isinf(v.planet_radius_m) ? 0.0 : std::sqrt(2.0 * v.planet_radius_m * (altitude + 20.0));
  v.camera = {.position_m = {eye.value()[0], eye.value()[1], eye.value()[2]},
              .target_m = {target.value()[0], target.value()[1], target.value()[2]},
              .fov_y_rad = fov.value() * std::numbers::pi / 180.0,
              .aspect = w.value() / h.value(),
              .near_m = std::max(0.2, 0.005 * altitude),
              .far_m = std::max(2.0e5, 1.5 * horizon)};
  // Below the surface the camera sees the underside of the waves (docs/rendering.md R.50); on a
  // sphere parse_sphere_flags checks the camera.
  if (eye.value()[1] < -kDeepestCamera_m && !f.sphere.enabled)
    return invalid_argument("--camera = " + excerpt(f.camera) +
                            ": the camera must be at most 1000 m below the sea (Y >= -1000)");
  if (Status s = lod::validate(v.camera); !s.ok())
    return invalid_argument("--camera/--target: " + s.message());
  Result<lod::QualityPreset> preset = lod::parse_preset(f.quality);
  if (!preset.ok())
    return invalid_argument("--quality = " + excerpt(f.quality) + " is not a quality: must be " +
                            name_list(lod::kQualityPresetNames, ", ", " or "));
  v.quality = lod::quality_preset(preset.value());
  Result<double> size = parse(kOceanSize, f.ocean_size);
  if (!size.ok()) return size.status();
  v.ocean_size_m = size.value();
  if (f.far_field_range.empty()) {
    v.far_field = f.preset_far_field.value_or(render::FarFieldRange{});
  } else {
    Result<std::vector<double>> range = parse_list(kFarFieldRange, f.far_field_range);
    if (!range.ok()) return range.status();
    if (range.value().size() != 2)
      return invalid_argument("--far-field-range = " + excerpt(f.far_field_range) +
                              " must be two distances DMIN,DMAX in metres");
    v.far_field = {.near_m = range.value()[0], .far_m = range.value()[1]};
    if (range.value()[0] >= range.value()[1])
      return invalid_argument("--far-field-range = " + excerpt(f.far_field_range) +
                              ": DMIN must be below DMAX");
  }
  if (!f.scattering.empty()) {
    Result<double> b = parse(kScattering, f.scattering);
    if (!b.ok()) return b.status();
    v.underwater.scattering_per_m = b.value();
  } else if (f.preset_scattering) {
    v.underwater.scattering_per_m = *f.preset_scattering;
  }
  Result<render::DebugView> debug = render::parse_debug_view(f.view);
  if (!debug.ok())
    return invalid_argument("--view = " + excerpt(f.view) + " is not a view: must be " +
                            name_list(render::kDebugViewNames, ", ", " or "));
  v.debug = debug.value();
  Result<render::MeshMode> mesh = render::parse_mesh_mode(f.mesh);
  if (!mesh.ok())
    return invalid_argument("--mesh = " + excerpt(f.mesh) + " is not a mesh: must be " +
                            name_list(render::kMeshModeNames, ", ", " or "));
  v.tessellation.mesh = mesh.value();
  if (!f.environment.empty()) {
    Result<render::Environment> env = render::load_environment(f.environment);
    if (!env.ok()) return invalid_argument("--environment: " + env.status().message());
    scene.environment = std::make_shared<const render::Environment>(std::move(env).value());
  }
  if (Status s = parse_sphere_flags(f.sphere, v); !s.ok()) return s;
  Result<int> far_noise = parse(kFarNoiseResolution, f.far_noise_resolution);
  if (!far_noise.ok()) return far_noise.status();
  scene.config.far_noise.resolution = 0;
  if (far_noise.value() == 0 || v.sphere.enabled) return {};
  Result<FarNoiseConfig> window = render::far_noise_window(
      v.far_field, far_noise.value(), v.camera.position_m.x, v.camera.position_m.z);
  if (!window.ok()) return invalid_argument("--far-noise-resolution: " + window.status().message());
  scene.config.far_noise = window.value();
  return {};
}

Status parse_view_flags(const ViewFlags& flags, const SimulationFlags& sim, int min_size,
                        render::SceneParams& scene, render::View& view) {
  Result<preset::PictureSettings> picture = resolve_picture(sim);
  if (!picture.ok()) return picture.status();
  ViewFlags with_preset = flags;
  if (const auto& range = picture.value().far_field_range_m)
    with_preset.preset_far_field =
        render::FarFieldRange{.near_m = (*range)[0], .far_m = (*range)[1]};
  with_preset.preset_scattering = picture.value().scattering_per_m;
  return parse_view_flags(with_preset, min_size, scene, view);
}

Status check_mesh_support(const render::View& view, const vk::Context& ctx) {
  if (view.tessellation.mesh == render::MeshMode::tessellation && !ctx.tessellation)
    return unsupported("--mesh tessellation: Vulkan device '" + ctx.info.name +
                       "' lacks tessellation shaders; use --mesh quadtree");
  return {};
}

Status check_taa_support(const render::SceneParams& scene, const render::View& view) {
  const char* why = scene.backend == "vulkan"
                        ? "--backend vulkan, whose images the renderer samples in place (the "
                          "motion vectors keep a copy of uploaded frames)"
                    : view.sphere.enabled ? "--sphere, which draws no motion vectors"
                    : view.tessellation.mesh == render::MeshMode::tessellation
                        ? "--mesh tessellation, which draws no motion vectors"
                        : nullptr;
  if (why == nullptr) return {};
  return invalid_argument(std::string("--taa: not with ") + why);
}

}  // namespace ocean::cli
