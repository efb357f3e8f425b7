// `--object` and `--float` of `ocean render` (object_flags.hpp): parsing, the built-in shapes'
// and glTF files' meshes, and the floating-body simulation that places them on the waves.
#include "object_flags.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "ocean/backends.hpp"
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

// The built-in shapes: hull, material, density (docs/bodies.md B.6; metacentrically stable).
struct Shape {
  bodies::Hull hull;
  render::Material material;
  double density = 0.0;
};
Result<Shape> built_in(const std::string& kind) {
  Result<bodies::Hull> hull = bodies::Hull{};
  Shape s;
  if (kind == "box") {
    hull = bodies::box_hull({2.0, 1.0, 2.0});
    s.material = {.base_colour = {0.8, 0.3, 0.04}, .roughness = 0.5};
    s.density = kBoxDensity;
  } else if (kind == "buoy") {
    hull = bodies::buoy_hull(0.8, 1.0);
    s.material = {.base_colour = {0.75, 0.04, 0.03}, .roughness = 0.45};
    s.density = kBuoyDensity;
  } else {
    hull = bodies::boat_hull(8.0, 3.0, 1.2);
    s.material = {.base_colour = {0.85, 0.85, 0.82}, .roughness = 0.35};
    s.density = kBoatDensity;
  }
  if (!hull.ok()) return hull.status();
  s.hull = std::move(hull).value();
  return s;
}

// The file's meshes as one hull: positions merged where they are equal (glTF splits vertices
// at normal and texture seams), degenerate triangles dropped.
bodies::Hull welded(const std::vector<render::Mesh>& meshes, std::size_t first) {
  bodies::Hull hull;
  std::map<std::array<double, 3>, std::uint32_t> index;
  for (std::size_t m = first; m < meshes.size(); ++m) {
    const render::Mesh& mesh = meshes[m];
    std::vector<std::uint32_t> map(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const std::array<double, 3> p{mesh.positions[v][0], mesh.positions[v][1],
                                    mesh.positions[v][2]};
      auto [it, inserted] = index.try_emplace(p, static_cast<std::uint32_t>(hull.vertices.size()));
      if (inserted) hull.vertices.push_back(p);
      map[v] = it->second;
    }
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const std::array<std::uint32_t, 3> tri{map[mesh.indices[t]], map[mesh.indices[t + 1]],
                                             map[mesh.indices[t + 2]]};
      if (tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2]) hull.triangles.push_back(tri);
    }
  }
  return hull;
}

}  // namespace

bodies::PropulsionParams propulsion_for(const bodies::BodyParams& body, double gravity_mps2) {
  double x_min = 0.0, y_min = 0.0;
  for (const auto& v : body.hull.vertices) {
    x_min = std::min(x_min, v[0]);
    y_min = std::min(y_min, v[1]);
  }
  // The yaw inertia of the level body: about its vertical (body y) axis.
  const double i_yaw = body.inertia_kgm2[4];
  return {.max_thrust_n = 0.5 * body.mass_kg * gravity_mps2,
          .thrust_point_m = {0.9 * x_min, 0.0, 0.0},
          .speed_time_s = 2.5,
          .max_yaw_moment_nm = 0.5 * i_yaw,
          .heading_time_s = 2.0};
}

waves::WakeTrackParams wake_track_for(const bodies::Hull& hull) {
  double x_min = 0.0, x_max = 0.0;
  for (const auto& v : hull.vertices) {
    x_min = std::min(x_min, v[0]);
    x_max = std::max(x_max, v[0]);
  }
  const double length = std::clamp(x_max - x_min, 0.01, 1000.0);
  return {.hull_length_m = length, .peak_height_m = kWakePeakPerLength * length};
}

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

Result<std::unique_ptr<SceneObjects>> SceneObjects::make(const std::vector<ObjectSpec>& specs,
                                                         bool floating,
                                                         const SimulationConfig& config) {
  auto objects = std::unique_ptr<SceneObjects>(new SceneObjects());
  for (const ObjectSpec& spec : specs) {
    Object o;
    o.position_m = spec.position_m;
    o.orientation = bodies::orientation_from_heading(spec.heading_deg);
    const std::size_t first = objects->meshes_.size();
    bodies::Hull hull;
    double density = kMeshDensity;
    if (is_mesh_file(spec.kind)) {
      Result<std::vector<render::Mesh>> loaded = render::load_gltf(spec.kind);
      if (!loaded.ok()) return loaded.status();
      for (render::Mesh& m : loaded.value()) objects->meshes_.push_back(std::move(m));
      if (floating) hull = welded(objects->meshes_, first);
    } else {
      Result<Shape> shape = built_in(spec.kind);
      if (!shape.ok()) return shape.status();
      objects->meshes_.push_back(render::flat_mesh(
          shape.value().hull.vertices, shape.value().hull.triangles, shape.value().material));
      hull = std::move(shape.value().hull);
      density = shape.value().density;
    }
    for (std::size_t m = first; m < objects->meshes_.size(); ++m)
      o.meshes.push_back(static_cast<std::uint32_t>(m));
    if (floating) {
      Result<bodies::BodyParams> params = bodies::solid_body(hull, density);
      if (!params.ok())
        return invalid_argument("--object " + excerpt(spec.kind) +
                                " cannot float: " + params.status().message());
      o.centre_m = bodies::mass_properties(hull).centroid_m;
      const std::array<double, 3> c = bodies::rotate(o.orientation, o.centre_m);
      const bodies::BodyState start{
          .position_m = {o.position_m[0] + c[0], o.position_m[1] + c[1], o.position_m[2] + c[2]},
          .orientation = o.orientation};
      Result<bodies::FloatingBody> body = bodies::FloatingBody::make(params.value(), start);
      if (!body.ok()) return body.status();
      o.body = std::make_unique<bodies::FloatingBody>(std::move(body).value());
      if (spec.speed_mps > 0.0) {
        Result<bodies::Propulsion> propulsion = bodies::Propulsion::make(
            propulsion_for(params.value(), config.sea.dispersion.gravity_mps2));
        if (!propulsion.ok()) return propulsion.status();
        o.propulsion = propulsion.value();
        o.helm = {.speed_mps = spec.speed_mps, .heading_deg = spec.heading_deg};
        Result<waves::WakeTrack> track =
            waves::WakeTrack::make(wake_track_for(params.value().hull));
        if (!track.ok()) return track.status();
        o.track = std::move(track).value();
      }
    } else if (spec.speed_mps > 0.0) {
      return invalid_argument("--object " + excerpt(spec.kind) +
                              ": a speed drives a floating object; add --float");
    }
    objects->objects_.push_back(std::move(o));
  }
  if (floating && !specs.empty()) {
    SimulationConfig surface = config;
    // The displacement is all the queries read: no float maps, and no far-field noise map (the
    // picture's, 512² by default, would cost each step of the bodies' sea about seven times its
    // cascades: 30 ms against 4 ms of CPU for the moderate preset).
    surface.outputs = FrameOutputs::textures();
    surface.far_noise.resolution = 0;
    Result<std::unique_ptr<Simulator>> sim = make_simulator(surface);
    if (!sim.ok()) return sim.status();
    objects->surface_ = std::move(sim).value();
    objects->surface_->step(0.0);
  }
  return objects;
}

Status SceneObjects::place(double time_s, std::vector<render::ObjectInstance>& out,
                           const std::atomic<bool>* cancel) {
  constexpr double kDt = 1.0 / 60;  // body step; the surface is simulated every second one
  if (surface_ != nullptr) {
    const bodies::SurfaceQuery surface = bodies::surface_of(*surface_);
    // The steps to take, counted with the same sums as the loop below takes them.
    long long steps = 0;
    for (double t = time_s_; t + 0.5 * kDt < time_s; t += kDt) ++steps;
    std::optional<Progress> progress;
    if (time_s - time_s_ >= kFloatProgressSpan_s)
      progress.emplace("floating bodies (1/60 s steps)", steps);
    for (long long i = 0; i < steps; ++i) {
      if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) {
        if (progress) progress->end_line();
        return {ErrorCode::cancelled, "stopped at t = " + format_number(time_s_) + " s"};
      }
      if (i % 2 == 0) surface_->step(time_s_);
      for (Object& o : objects_) {
        bodies::Wrench thrust;
        if (o.propulsion) {
          Result<bodies::Wrench> w = o.propulsion->control(*o.body, o.helm, kDt);
          if (!w.ok()) return w.status();
          thrust = w.value();
        }
        if (Status s = o.body->step(surface, kDt, thrust); !s.ok()) return s;
        if (o.track) {
          const auto& x = o.body->state().position_m;
          o.track->record(time_s_ + kDt, x[0], x[2]);
        }
      }
      time_s_ += kDt;
      if (progress) progress->update(i + 1);
    }
    if (progress) progress->finish();
  }
  out.clear();
  for (const Object& o : objects_) {
    std::array<double, 3> position = o.position_m;
    std::array<double, 4> orientation = o.orientation;
    if (o.body != nullptr) {
      // The body's centre is the mesh frame's point centre_m: origin = x − R·c.
      orientation = o.body->state().orientation;
      const std::array<double, 3> c = bodies::rotate(orientation, o.centre_m);
      const auto& x = o.body->state().position_m;
      position = {x[0] - c[0], x[1] - c[1], x[2] - c[2]};
    }
    for (std::uint32_t m : o.meshes)
      out.push_back({.mesh = m, .model = render::model_matrix(position, orientation)});
  }
  return {};
}

void SceneObjects::wakes(std::vector<waves::KelvinWake>& out) const {
  for (const Object& o : objects_) {
    if (!o.track) continue;
    waves::KelvinWake wake;
    if (o.track->wake(wake)) out.push_back(std::move(wake));
  }
}

std::optional<std::array<double, 3>> SceneObjects::first_driven() const {
  for (const Object& o : objects_) {
    if (!o.propulsion) continue;
    const auto& x = o.body->state().position_m;
    return std::array<double, 3>{x[0], x[2], bodies::heading_deg(o.body->state())};
  }
  return std::nullopt;
}

}  // namespace ocean::cli
