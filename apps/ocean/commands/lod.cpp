// `ocean lod`: the quadtree LOD selection for one camera (Aebi, VR Ocean, §5): patch counts per
// level and per stitching configuration, the selected mesh as OBJ (world space, undisplaced,
// skirt excluded) and optionally a top-down PNG of the layout.
#include "ocean/lod.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "ocean/io.hpp"
#include "output_name.hpp"
#include "plot/plot.hpp"

namespace ocean::cli {

namespace {

constexpr NumberOption<double> kLodOceanSize{.flag = "--ocean-size",
                                          .accept = Accept::in_range,
                                          .lo = lod::kMinOceanSize_m,
                                          .hi = lod::kMaxOceanSize_m};
constexpr NumberOption<double> kLodFov{
    .flag = "--fov", .accept = Accept::in_range, .lo = 1.0, .hi = 170.0};
constexpr NumberOption<double> kAspect{
    .flag = "--aspect", .accept = Accept::in_range, .lo = 0.05, .hi = 20.0};
constexpr NumberOption<double> kCentre{.flag = "--center"};  // two finite numbers, checked below

struct LodOptions {
  std::string camera, target, centre;
  std::string preset = "medium", ocean_size = "1024", fov = "60", aspect = "1.7778";
  std::string out, png;
  bool no_cull = false, json = false;
};

Result<lod::Vec3> parse_vec3(std::string_view flag, const std::string& text) {
  Result<std::array<double, 3>> v = parse_triple(flag, text);
  if (!v.ok()) return v.status();
  return lod::Vec3{v.value()[0], v.value()[1], v.value()[2]};
}

struct LodInputs {
  lod::Camera camera;
  lod::LodParams params;
  lod::QualityPreset preset = lod::QualityPreset::medium;
};

Result<LodInputs> parse_inputs(const LodOptions& o) {
  LodInputs in;
  Result<lod::Vec3> eye = parse_vec3("--camera", o.camera);
  if (!eye.ok()) return eye.status();
  Result<lod::Vec3> target = parse_vec3("--target", o.target);
  if (!target.ok()) return target.status();
  Result<lod::QualityPreset> preset = lod::parse_preset(o.preset);
  if (!preset.ok())
    return invalid_argument("--preset = " + excerpt(o.preset) + " is not a preset: must be " +
                            name_list(lod::kQualityPresetNames, ", ", " or "));
  in.preset = preset.value();
  Result<double> size = parse(kLodOceanSize, o.ocean_size);
  if (!size.ok()) return size.status();
  Result<double> fov = parse(kLodFov, o.fov);
  if (!fov.ok()) return fov.status();
  Result<double> aspect = parse(kAspect, o.aspect);
  if (!aspect.ok()) return aspect.status();
  in.camera = {.position_m = eye.value(),
               .target_m = target.value(),
               .fov_y_rad = fov.value() * std::numbers::pi / 180.0,
               .aspect = aspect.value()};
  if (Status s = lod::validate(in.camera); !s.ok()) {
    if (s.message().find("equals") != std::string::npos) {
      return invalid_argument("--target equals --camera: the view direction is undefined");
    }
    return s;
  }
  in.params = {.ocean_size_m = size.value(),
               .quality = lod::quality_preset(in.preset),
               .camera_position_m = eye.value(),
               .frustum = lod::camera_frustum(in.camera),
               .cull = !o.no_cull};
  if (!o.centre.empty()) {
    Result<std::vector<double>> c = parse_list(kCentre, o.centre);
    if (!c.ok()) return c.status();
    if (c.value().size() != 2 || !std::isfinite(c.value()[0]) || !std::isfinite(c.value()[1])) {
      return invalid_argument("--center = " + excerpt(o.centre) +
                              " must be two finite numbers X,Z");
    }
    in.params.follow_camera = false;
    in.params.fixed_centre_x_m = c.value()[0];
    in.params.fixed_centre_z_m = c.value()[1];
  }
  for (const auto& [flag, name] : {std::pair{"--out", &o.out}, std::pair{"--png", &o.png}}) {
    if (name->empty()) continue;
    if (Status s = check_output_name(flag, *name); !s.ok()) return s;
  }
  return in;
}

std::string config_name(int c) {
  std::string s;
  if (c & lod::kEast) s += 'E';
  if (c & lod::kNorth) s += 'N';
  if (c & lod::kWest) s += 'W';
  if (c & lod::kSouth) s += 'S';
  return s.empty() ? "-" : s;
}

// Welded OBJ: vertices are keyed on the finest lattice, so patches share their edge vertices.
std::string obj_text(const lod::LodSelection& sel, const lod::PatchMeshes& meshes, double size,
                     const std::string& header) {
  const int v = meshes.vertices;
  const std::int64_t m = (std::int64_t{1} << sel.max_level) * v;
  const double unit = size / static_cast<double>(m);
  const double x0 = sel.grid_centre_x_m - 0.5 * size, z0 = sel.grid_centre_z_m - 0.5 * size;
  std::unordered_map<std::int64_t, std::uint32_t> index;
  std::ostringstream verts, faces;
  verts << std::setprecision(12);
  for (const lod::PatchInstance& pi : sel.instances) {
    const std::int64_t delta = std::int64_t{1} << (sel.max_level - pi.level);
    const std::int64_t ox = pi.grid_x * delta * v, oz = pi.grid_y * delta * v;
    const auto& idx = meshes.indices[pi.config];
    for (std::size_t t = 0; t < idx.size(); t += 3) {
      faces << 'f';
      for (std::size_t k = 0; k < 3; ++k) {
        const std::int64_t i = ox + (idx[t + k] % (v + 1)) * delta;
        const std::int64_t j = oz + (idx[t + k] / (v + 1)) * delta;
        const auto [it, added] =
            index.try_emplace(i * (m + 1) + j, static_cast<std::uint32_t>(index.size() + 1));
        if (added) {
          verts << "v " << x0 + static_cast<double>(i) * unit << " 0 "
                << z0 + static_cast<double>(j) * unit << "\n";
        }
        faces << ' ' << it->second;
      }
      faces << '\n';
    }
  }
  return header + verts.str() + faces.str();
}

// ---- top-down PNG ------------------------------------------------------------------------------

// Patch colours by level, coarse (dark blue) to fine (red).
constexpr std::array<plot::Rgb, 9> kLevel = {{{49, 54, 149},
                                              {69, 117, 180},
                                              {116, 173, 209},
                                              {171, 217, 233},
                                              {254, 224, 144},
                                              {253, 174, 97},
                                              {244, 109, 67},
                                              {215, 48, 39},
                                              {165, 0, 38}}};
constexpr plot::Rgb kCulled{225, 225, 225};
constexpr plot::Rgb kEdge{40, 40, 40};
constexpr plot::Rgb kEye{220, 0, 0};
constexpr plot::Rgb kInk{25, 25, 25};
constexpr int kMapPx = 900;  // the square of the map
constexpr int kKeyPx = 250;  // the key to its right

// The key: one swatch per level, culled patches, the camera and its field of view.
void draw_key(plot::Canvas& canvas, const lod::LodSelection& sel, double ocean_size_m) {
  const plot::Font font{.size_px = 15.0}, bold{.size_px = 16.0, .bold = true};
  const double x = kMapPx + 20.0;
  double y = 34.0;
  canvas.text({x, y}, "patch level (side)", bold, kInk);
  const auto swatch = [&](plot::Rgb fill, const std::string& label) {
    y += 26.0;
    canvas.fill({x, y - 14.0, x + 22.0, y + 2.0}, fill);
    canvas.outline({x, y - 14.0, x + 22.0, y + 2.0}, kEdge, 1.0);
    canvas.text({x + 32.0, y}, label, font, kInk);
  };
  for (int l = 0; l <= sel.max_level; ++l) {
    std::ostringstream label;
    label << l << " (" << ocean_size_m / (1 << l) << " m)";
    swatch(kLevel[static_cast<std::size_t>(l)], label.str());
  }
  swatch(kCulled, "culled");
  y += 30.0;
  canvas.disc({x + 11.0, y - 6.0}, 5.0, kEye);
  canvas.text({x + 32.0, y}, "camera", font, kInk);
  y += 26.0;
  const plot::Point fov[] = {{x, y - 6.0}, {x + 22.0, y - 6.0}};
  canvas.polyline(fov, {.color = {0, 0, 0}, .width_px = 2.0});
  canvas.text({x + 32.0, y}, "field of view", font, kInk);
}

Status write_layout_png(const std::string& path, const LodInputs& in, const lod::LodSelection& sel) {
  // All leaves (grey when culled) from a second, unculled selection.
  lod::LodSelection all;
  lod::LodParams p = in.params;
  p.cull = false;
  if (Status s = lod::select_patches(p, all); !s.ok()) return s;
  const double half = 0.5 * p.ocean_size_m;
  const lod::Vec3 eye = in.camera.position_m;
  const double x_lo = std::min(sel.grid_centre_x_m - half, eye.x) - 0.05 * half;
  const double x_hi = std::max(sel.grid_centre_x_m + half, eye.x) + 0.05 * half;
  const double z_lo = std::min(sel.grid_centre_z_m - half, eye.z) - 0.05 * half;
  const double z_hi = std::max(sel.grid_centre_z_m + half, eye.z) + 0.05 * half;
  const double scale = kMapPx / std::max(x_hi - x_lo, z_hi - z_lo);
  // World (x, z) to pixels: east to the right, north up.
  const auto px = [&](double x) { return std::floor((x - x_lo) * scale); };
  const auto py = [&](double z) { return std::floor((z_hi - z) * scale); };
  Result<plot::Canvas> made = plot::Canvas::make(kMapPx + kKeyPx, kMapPx, {255, 255, 255});
  if (!made.ok()) return made.status();
  plot::Canvas& canvas = made.value();
  auto drawn = [&](const lod::PatchInstance& q) {
    return std::any_of(sel.instances.begin(), sel.instances.end(), [&](const auto& s) {
      return s.level == q.level && s.grid_x == q.grid_x && s.grid_y == q.grid_y;
    });
  };
  for (const lod::PatchInstance& q : all.instances) {
    const double h = 0.5 * q.size_m;
    const plot::Box box{px(q.centre_x_m - h), py(q.centre_z_m + h), px(q.centre_x_m + h) + 1.0,
                        py(q.centre_z_m - h) + 1.0};
    canvas.fill(box, drawn(q) ? kLevel[q.level] : kCulled);
    // The top and left edges: neighbours draw the others, so every edge is one pixel wide.
    canvas.fill({box.x0, box.y0, box.x1, box.y0 + 1.0}, kEdge);
    canvas.fill({box.x0, box.y0, box.x0 + 1.0, box.y1}, kEdge);
  }
  // The square's right and bottom edges, which no patch draws.
  const double east = px(sel.grid_centre_x_m + half), south = py(sel.grid_centre_z_m - half);
  canvas.fill({px(sel.grid_centre_x_m - half), south, east + 1.0, south + 1.0}, kEdge);
  canvas.fill({east, py(sel.grid_centre_z_m + half), east + 1.0, south + 1.0}, kEdge);
  const plot::Box map{0.0, 0.0, static_cast<double>(kMapPx), static_cast<double>(kMapPx)};
  // The horizontal field of view: the view direction ± half the horizontal angle.
  const double yaw = std::atan2(in.camera.target_m.z - eye.z, in.camera.target_m.x - eye.x);
  const double half_h = std::atan(std::tan(0.5 * in.camera.fov_y_rad) * in.camera.aspect);
  const double reach = 2.0 * p.ocean_size_m;
  const bool vertical = std::hypot(in.camera.target_m.x - eye.x, in.camera.target_m.z - eye.z) <
                        1e-9 * std::abs(in.camera.target_m.y - eye.y);
  const plot::Point eye_px{px(eye.x) + 0.5, py(eye.z) + 0.5};
  if (!vertical) {
    for (double a : {yaw - half_h, yaw + half_h}) {
      const plot::Point ray[] = {
          eye_px, {px(eye.x + reach * std::cos(a)) + 0.5, py(eye.z + reach * std::sin(a)) + 0.5}};
      canvas.polyline(ray, {.color = {0, 0, 0}, .width_px = 2.0}, map);
    }
  }
  canvas.disc(eye_px, 5.0, kEye);
  draw_key(canvas, sel, p.ocean_size_m);
  return canvas.write_png(path);
}

int run_lod(const LodOptions& o) {
  Result<LodInputs> inputs = parse_inputs(o);
  if (!inputs.ok()) return report(inputs.status());
  const LodInputs& in = inputs.value();
  lod::LodSelection sel;
  if (Status s = lod::reserve_selection(sel, in.params.ocean_size_m); !s.ok()) return report(s);
  if (Status s = lod::select_patches(in.params, sel); !s.ok()) return report(s);
  Result<lod::PatchMeshes> meshes = lod::build_patch_meshes(in.params.quality.vertices);
  if (!meshes.ok()) return report(meshes.status());
  std::size_t triangles = 0;
  for (const lod::Batch& b : sel.batches) {
    triangles += b.count * meshes.value().indices[b.config].size() / 3;
  }
  if (!o.out.empty()) {
    std::ostringstream header;
    header << "# ocean lod: camera " << o.camera << ", target " << o.target << ", preset "
           << o.preset << ", ocean size " << in.params.ocean_size_m << " m, "
           << sel.instances.size() << " patches; world metres, y up, undisplaced\n";
    const std::string text = obj_text(sel, meshes.value(), in.params.ocean_size_m, header.str());
    const auto* bytes = reinterpret_cast<const std::byte*>(text.data());
    if (Status s = io::write_bytes_atomically(o.out, {{bytes, text.size()}}); !s.ok()) {
      return report(s);
    }
  }
  if (!o.png.empty()) {
    if (Status s = write_layout_png(o.png, in, sel); !s.ok()) return report(s);
  }
  const lod::Quality& q = in.params.quality;
  if (o.json) {
    nlohmann::ordered_json j;
    j["ocean_size_m"] = in.params.ocean_size_m;
    j["preset"] = std::string(lod::preset_name(in.preset));
    j["vertices"] = q.vertices;
    j["lod_scale"] = q.lod_scale;
    j["cull_scale"] = q.cull_scale;
    j["max_level"] = sel.max_level;
    j["grid_centre_m"] = {sel.grid_centre_x_m, sel.grid_centre_z_m};
    j["cull"] = in.params.cull;
    j["patches"] = sel.instances.size();
    j["triangles"] = triangles;
    j["draws"] = sel.batches.size();
    j["patches_per_level"] = std::vector<std::uint32_t>(
        sel.patches_per_level.begin(), sel.patches_per_level.begin() + sel.max_level + 1);
    j["patches_per_config"] = sel.patches_per_config;
    nlohmann::ordered_json batches = nlohmann::ordered_json::array();
    for (const lod::Batch& b : sel.batches) {
      batches.push_back({{"config", b.config}, {"first", b.first}, {"count", b.count}});
    }
    j["batches"] = batches;
    if (!o.out.empty()) j["obj"] = o.out;
    if (!o.png.empty()) j["png"] = o.png;
    print_json(j);
    return kExitOk;
  }
  std::cout << "ocean " << in.params.ocean_size_m << " m, preset " << lod::preset_name(in.preset)
            << " (V " << q.vertices << ", tau " << q.lod_scale << ", beta " << q.cull_scale
            << "), L_max " << sel.max_level << ", grid centre (" << sel.grid_centre_x_m << ", "
            << sel.grid_centre_z_m << ") m\n"
            << sel.instances.size() << " patches, " << triangles << " triangles, "
            << sel.batches.size() << " instanced draws" << (in.params.cull ? "" : " (no culling)")
            << "\n\nlevel  size_m      patches\n";
  for (int l = 0; l <= sel.max_level; ++l) {
    std::cout << std::left << std::setw(7) << l << std::setw(12)
              << in.params.ocean_size_m / (1 << l)
              << sel.patches_per_level[static_cast<std::size_t>(l)] << "\n";
  }
  std::cout << "\nconfig  coarser_edges  patches\n";
  for (int c = 0; c < lod::kConfigurations; ++c) {
    std::cout << std::setw(8) << c << std::setw(15) << config_name(c)
              << sel.patches_per_config[static_cast<std::size_t>(c)] << "\n";
  }
  return kExitOk;
}

}  // namespace

Command add_lod_command(CLI::App& app) {
  auto options = std::make_shared<LodOptions>();
  CLI::App* command = app.add_subcommand(
      "lod",
      "Quadtree LOD patches for one camera: counts per level and stitching configuration, "
      "the mesh as OBJ");
  command->add_option("--camera", options->camera, "camera position X,Y,Z, m (Y up)")->required();
  command->add_option("--target", options->target, "point the camera looks at X,Y,Z, m")
      ->required();
  command
      ->add_option("--preset", options->preset,
                   "quality: " + name_list(lod::kQualityPresetNames, ", ", " or "))
      ->capture_default_str();
  add_option(*command, kLodOceanSize, options->ocean_size, "side S of the ocean square, m")
      ->capture_default_str();
  add_option(*command, kCentre, options->centre,
             "fix the grid centre at X,Z, m (default: the camera, snapped)");
  add_option(*command, kLodFov, options->fov, "vertical field of view, degrees")
      ->capture_default_str();
  add_option(*command, kAspect, options->aspect, "width/height")->capture_default_str();
  command->add_flag("--no-cull", options->no_cull,
                    "keep patches outside the view frustum (the whole square)");
  command->add_option("--out", options->out,
                      "write the selected mesh as OBJ (world m, undisplaced, no skirt)");
  command->add_option("--png", options->png, "write a top-down PNG of the patch layout");
  command->add_flag("--json", options->json, "print JSON instead of tables");
  return {command, [options] { return run_lod(*options); }};
}

}  // namespace ocean::cli
