// `--object` and `--float` of `ocean render` (object_flags.hpp): parsing, the built-in shapes'
// and glTF files' meshes, and the objects' instances at the world's poses.
#include "object_flags.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "options.hpp"
#include "progress.hpp"

namespace ocean::cli {

namespace {

constexpr NumberOption<double> kObjectX{
    .flag = "--object x", .accept = Accept::in_range, .lo = -1e5, .hi = 1e5, .unit = "m"};
constexpr NumberOption<double> kObjectY{
    .flag = "--object y", .accept = Accept::in_range, .lo = -1e4, .hi = 1e4, .unit = "m"};
constexpr NumberOption<double> kObjectZ{
    .flag = "--object z", .accept = Accept::in_range, .lo = -1e5, .hi = 1e5, .unit = "m"};
constexpr NumberOption<double> kObjectHeading{
    .flag = "--object heading", .accept = Accept::in_range, .lo = -360.0, .hi = 360.0};
constexpr NumberOption<double> kObjectSpeed{
    .flag = "--object speed", .accept = Accept::in_range, .lo = 0.0, .hi = 30.0, .unit = "m/s"};

bool is_mesh_file(const std::string& kind) {
  const auto ends = [&](const std::string& ext) {
    return kind.size() > ext.size() && kind.compare(kind.size() - ext.size(), ext.size(), ext) == 0;
  };
  return ends(".glb") || ends(".gltf");
}

// The built-in objects: the world's shape and the mesh's material.
struct BuiltIn {
  world::Shape shape;
  render::Material material;
};
BuiltIn built_in(const std::string& kind) {
  if (kind == "box")
    return {world::Shape::box, {.base_colour = {0.8, 0.3, 0.04}, .roughness = 0.5}};
  if (kind == "buoy")
    return {world::Shape::buoy, {.base_colour = {0.75, 0.04, 0.03}, .roughness = 0.45}};
  return {world::Shape::boat, {.base_colour = {0.85, 0.85, 0.82}, .roughness = 0.35}};
}

}  // namespace

Result<ObjectSpec> parse_object_spec(const std::string& text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t comma; (comma = text.find(',', start)) != std::string::npos; start = comma + 1)
    parts.push_back(text.substr(start, comma - start));
  parts.push_back(text.substr(start));
  if (parts.size() < 4 || parts.size() > 6)
    return invalid_argument("--object = '" + excerpt(text) +
                            "' must be KIND,X,Y,Z, KIND,X,Y,Z,HEADING_DEG or "
                            "KIND,X,Y,Z,HEADING_DEG,SPEED_MPS (KIND: box, buoy, boat or a "
                            ".glb/.gltf file)");
  ObjectSpec spec;
  spec.kind = parts[0];
  if (spec.kind != "box" && spec.kind != "buoy" && spec.kind != "boat" && !is_mesh_file(spec.kind))
    return invalid_argument("--object = '" + excerpt(text) + "': '" + excerpt(spec.kind) +
                            "' is not box, buoy, boat or a .glb/.gltf file");
  const NumberOption<double>* options[] = {&kObjectX, &kObjectY, &kObjectZ, &kObjectHeading,
                                           &kObjectSpeed};
  double* values[] = {&spec.position_m[0], &spec.position_m[1], &spec.position_m[2],
                      &spec.heading_deg, &spec.speed_mps};
  for (std::size_t i = 1; i < parts.size(); ++i) {
    Result<double> v = parse(*options[i - 1], parts[i]);
    if (!v.ok()) return v.status();
    *values[i - 1] = v.value();
  }
  return spec;
}

Result<std::vector<render::Mesh>> built_in_meshes(const std::string& kind) {
  const BuiltIn b = built_in(kind);
  Result<bodies::Hull> hull = world::shape_hull(b.shape);
  if (!hull.ok()) return hull.status();
  std::vector<render::Mesh> out;
  if (b.shape != world::Shape::boat) {
    out.push_back(render::flat_mesh(hull.value().vertices, hull.value().triangles, b.material));
    return out;
  }
  // The boat: a dark blue hull (the foam along its waterline shows against it), teak deck, white
  // bulwark and cabin, dark glass (bodies::boat_topside, of the world's boat's size).
  Result<bodies::BoatTopside> top = world::boat_topside();
  if (!top.ok()) return top.status();
  const auto add = [&](const bodies::Hull& h, const render::Material& m) {
    out.push_back(render::flat_mesh(h.vertices, h.triangles, m));
  };
  add(hull.value(), {.base_colour = {0.05, 0.09, 0.2}, .roughness = 0.3});
  add(top.value().deck, {.base_colour = {0.45, 0.3, 0.16}, .roughness = 0.6});
  add(top.value().bulwark, b.material);
  add(top.value().cabin, b.material);
  add(top.value().windows, {.base_colour = {0.02, 0.03, 0.04}, .roughness = 0.08});
  return out;
}

Result<RenderObjects> load_objects(const std::vector<ObjectSpec>& specs, bool floating) {
  RenderObjects out;
  for (const ObjectSpec& spec : specs) {
    world::ObjectDesc desc{.name = "--object " + excerpt(spec.kind),
                           .position_m = spec.position_m,
                           .heading_deg = spec.heading_deg,
                           .speed_mps = spec.speed_mps};
    const std::size_t first = out.meshes.size();
    if (is_mesh_file(spec.kind)) {
      Result<std::vector<render::Mesh>> loaded = render::load_gltf(spec.kind);
      if (!loaded.ok()) return loaded.status();
      for (render::Mesh& m : loaded.value()) out.meshes.push_back(std::move(m));
      if (floating) {
        std::vector<world::MeshView> views;
        for (std::size_t m = first; m < out.meshes.size(); ++m)
          views.push_back({out.meshes[m].positions, out.meshes[m].indices});
        desc.hull = world::welded_hull(views);
      }
    } else {
      const BuiltIn b = built_in(spec.kind);
      Result<bodies::Hull> hull = world::shape_hull(b.shape);
      if (!hull.ok()) return hull.status();
      Result<std::vector<render::Mesh>> meshes = built_in_meshes(spec.kind);
      if (!meshes.ok()) return meshes.status();
      for (render::Mesh& m : meshes.value()) out.meshes.push_back(std::move(m));
      desc.hull = std::move(hull).value();
      desc.density_kgpm3 = world::shape_density_kgpm3(b.shape);
    }
    std::vector<std::uint32_t>& indices = out.mesh_indices.emplace_back();
    for (std::size_t m = first; m < out.meshes.size(); ++m)
      indices.push_back(static_cast<std::uint32_t>(m));
    out.objects.push_back(std::move(desc));
  }
  return out;
}

Result<bool> advance_world(world::World& world, double time_s, Simulator& sea,
                           const std::atomic<bool>* cancel) {
  std::optional<Progress> progress;
  if (world.floating() && time_s - world.time_s() >= kFloatProgressSpan_s)
    progress.emplace("floating bodies (1/60 s steps)", world.steps_until(time_s));
  world::AdvanceHooks hooks{.cancel = cancel};
  if (progress) hooks.on_step = [&](long long steps) { progress->update(steps); };
  Result<bool> advanced = world.advance_to(time_s, sea, hooks);
  if (progress && advanced.ok()) progress->finish();
  if (progress && advanced.status().code() == ErrorCode::cancelled) progress->end_line();
  return advanced;
}

void place_objects(const RenderObjects& objects, const world::World& world,
                   std::vector<render::ObjectInstance>& out) {
  out.clear();
  for (std::size_t i = 0; i < objects.mesh_indices.size(); ++i) {
    const world::Pose pose = world.pose(i);
    for (std::uint32_t m : objects.mesh_indices[i])
      out.push_back({.mesh = m, .model = render::model_matrix(pose.position_m, pose.orientation)});
  }
}

}  // namespace ocean::cli
