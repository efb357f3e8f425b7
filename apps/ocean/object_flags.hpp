// `--object FILE.glb|box|buoy|boat,X,Y,Z[,HEADING_DEG[,SPEED_MPS]]` (repeatable) and `--float`
// of `ocean render`: the flags turned into the world's objects (ocean/world.hpp), which floats
// them with --float on a CPU simulator of the same sea from t = 0 and drives those given a speed
// (B.8–B.10) leaving Kelvin wakes (W.17); here the objects' meshes for the renderer and their
// instances at the world's poses.
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ocean/render.hpp"
#include "ocean/world.hpp"

namespace ocean::cli {

/// One parsed --object.
struct ObjectSpec {
  std::string kind;  ///< box, buoy, boat or a .glb/.gltf path
  std::array<double, 3> position_m{};
  double heading_deg = 0.0;
  double speed_mps = 0.0;  ///< commanded speed with --float; 0: drifts
};
/// "KIND,X,Y,Z[,HEADING_DEG[,SPEED_MPS]]": X, Z in [-1e5, 1e5] m, Y in [-1e4, 1e4] m, heading in
/// [-360, 360], speed in [0, 30] m/s; a file name ends in .glb or .gltf and holds no comma.
/// invalid_argument naming --object and the part at fault (ocean::excerpt of the text).
Result<ObjectSpec> parse_object_spec(const std::string& text);

/// The latest time `ocean render --float` integrates the objects to, s: --time of the last
/// frame (--time + (--frames − 1)/--fps) beyond it is a usage error. The bodies start at t = 0
/// and step 1/60 s, the sea under them simulated every second step: 600 s is 36 000 body steps
/// and 18 000 steps of the sea, whose cost dominates. Measured with a box on the moderate
/// preset's four 256² cascades: about 4 ms of CPU per step of the sea, so the longest span is
/// about 80 s of CPU (a minute or two on two cores), and four times that on 512² grids; beyond
/// it a picture would be a wait of many minutes. The same bound as --warmup's.
inline constexpr double kMaxFloatTime_s = 600.0;
/// The shortest integration that shows its progress (a bar on a terminal, a summary line in a
/// log), s of simulated time: a minute, about 8 s of CPU on the moderate preset. Shorter spans,
/// the default --time 20 among them, print nothing.
inline constexpr double kFloatProgressSpan_s = 60.0;

/// The objects of a render: the renderer's meshes and the world's descriptions of them.
struct RenderObjects {
  std::vector<render::Mesh> meshes;                      ///< for Renderer::set_meshes
  std::vector<std::vector<std::uint32_t>> mesh_indices;  ///< per object, its meshes
  std::vector<world::ObjectDesc> objects;                ///< for world::WorldParams
};
/// Builds the meshes (loading glTF files) and, with `floating`, each object's hull (a glTF
/// file's meshes welded). Errors: the file's (load_gltf).
Result<RenderObjects> load_objects(const std::vector<ObjectSpec>& specs, bool floating);
/// The meshes of a built-in object ("box", "buoy" or "boat": its hull, then for the boat its
/// deck, bulwark, cabin and windows), in the hull's frame.
Result<std::vector<render::Mesh>> built_in_meshes(const std::string& kind);

/// Advances the world to time_s (World::advance_to, handing `sea` its layer); a span of
/// kFloatProgressSpan_s or more of floating bodies shows a progress bar on stderr ("floating
/// bodies (1/60 s steps)"). Returns whether `sea` was handed a new layer.
Result<bool> advance_world(world::World& world, double time_s, Simulator& sea,
                           const std::atomic<bool>* cancel = nullptr);
/// Writes the instances of every object's meshes at its pose in the world into `out`.
void place_objects(const RenderObjects& objects, const world::World& world,
                   std::vector<render::ObjectInstance>& out);

}  // namespace ocean::cli
