// `--object FILE.glb|box|buoy|boat,X,Y,Z[,HEADING_DEG]` (repeatable) and `--float` of
// `ocean render`: the objects' meshes for the renderer, their placement, and with --float the
// floating-body simulation (ocean/bodies.hpp) on a CPU simulator of the same sea from t = 0, so
// that each object sits on the waves at the time of each frame.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ocean/bodies.hpp"
#include "ocean/render.hpp"

namespace ocean::cli {

/// One parsed --object.
struct ObjectSpec {
  std::string kind;  ///< box, buoy, boat or a .glb/.gltf path
  std::array<double, 3> position_m{};
  double heading_deg = 0.0;
};
/// "KIND,X,Y,Z[,HEADING_DEG]": X, Z in [-1e5, 1e5] m, Y in [-1e4, 1e4] m, heading in
/// [-360, 360]; a file name ends in .glb or .gltf and holds no comma. invalid_argument naming
/// --object and the part at fault (ocean::excerpt of the text).
Result<ObjectSpec> parse_object_spec(const std::string& text);

/// Densities of the built-in objects and of glTF meshes when they float, kg/m³.
inline constexpr double kBoxDensity = 500.0, kBuoyDensity = 400.0, kBoatDensity = 350.0,
                        kMeshDensity = 500.0;

/// The objects of a render: meshes for Renderer::set_meshes and, per object, its instances.
class SceneObjects {
 public:
  /// Builds the meshes (loading glTF files) and, with `floating`, a body per object and a CPU
  /// simulator of `config` for the surface. Errors: the file's (load_gltf), a glTF that is not
  /// a closed mesh with --float, a bad configuration.
  static Result<std::unique_ptr<SceneObjects>> make(const std::vector<ObjectSpec>& specs,
                                                    bool floating, const SimulationConfig& config);
  [[nodiscard]] const std::vector<render::Mesh>& meshes() const { return meshes_; }
  /// Advances the bodies (with --float) to time_s from where they are (from t = 0 on the first
  /// call) at a fixed step of 1/60 s, the surface simulated every second step, then writes the
  /// instances of every object at their poses into `out`.
  Status place(double time_s, std::vector<render::ObjectInstance>& out);

 private:
  struct Object {
    std::vector<std::uint32_t> meshes;
    std::array<double, 3> position_m{};
    std::array<double, 4> orientation{1, 0, 0, 0};
    std::array<double, 3> centre_m{};  // the mesh frame's point that is the body's centre
    std::unique_ptr<bodies::FloatingBody> body;
  };
  std::vector<render::Mesh> meshes_;
  std::vector<Object> objects_;
  std::unique_ptr<Simulator> surface_;  // with --float
  double time_s_ = 0.0;
};

}  // namespace ocean::cli
