// ocean/objects.hpp — things drawn with the water: triangle meshes with a simple metallic-
// roughness material (the glTF 2.0 model), loaded from glTF files or built from positions and
// triangles (the hulls of ocean/bodies.hpp), placed in the world by a transform per instance.
// The renderer (ocean/render.hpp: Renderer::set_meshes, View::objects) shades them under the same
// sky and sun as the water and depth-tests them with it (docs/rendering.md R.20–R.21).
//
// Conventions: metres, world Y up (glTF's own convention, so glTF files need no conversion);
// matrices are 4×4 column-major (as glTF and GLSL), mapping the mesh's frame to the world.
// Threading: plain data and free functions; load_gltf may be called from any thread.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "ocean/core.hpp"

namespace ocean::render {

/// glTF 2.0's metallic-roughness material, constant over a mesh (textures are not read).
struct Material {
  std::array<double, 3> base_colour{0.8, 0.8, 0.8};  ///< linear RGB albedo, [0, 1]
  double metallic = 0.0;                             ///< [0, 1]
  double roughness = 0.6;                            ///< perceptual roughness, [0.02, 1]
};

/// An indexed triangle list with per-vertex normals, in its own frame.
struct Mesh {
  std::vector<std::array<float, 3>> positions;  ///< m
  std::vector<std::array<float, 3>> normals;    ///< unit, one per position
  std::vector<std::uint32_t> indices;           ///< 3 per triangle, counter-clockwise outside
  Material material;
};
/// Largest mesh the renderer takes: vertices and indices each.
inline constexpr std::size_t kMaxMeshElements = 1u << 24;
/// invalid_argument for an empty mesh, sizes that disagree, an index out of range, more than
/// kMaxMeshElements, non-finite positions or normals, or material values outside their ranges.
Status validate(const Mesh& mesh);

/// A flat-shaded mesh (one vertex per triangle corner, the face normal) of a triangle list.
Mesh flat_mesh(std::span<const std::array<double, 3>> vertices,
               std::span<const std::array<std::uint32_t, 3>> triangles, const Material& material);

/// The most bytes load_gltf reads from a glTF file, and from each buffer file it names: 512 MiB,
/// room for kMaxMeshElements vertices with normals and indices.
inline constexpr std::uint64_t kMaxGltfFileBytes = std::uint64_t{512} << 20;

/// Reads a glTF 2.0 file (.glb, or .gltf with embedded or neighbouring .bin buffers): the
/// triangle primitives of every node of the default scene (or of the first scene), node
/// transforms applied, one Mesh per primitive with its material's base colour, metallic and
/// roughness factors; missing normals are computed per face. io_error "cannot read '<path>':
/// ..." for a missing or unreadable file; invalid_argument "glTF file '<path>' is larger than
/// ..." past kMaxGltfFileBytes (a buffer file likewise); invalid_argument "cannot read '<path>':
/// ..." for a malformed file, no triangles, non-finite values or more than kMaxMeshElements. The
/// path is echoed through ocean::excerpt. Never throws.
Result<std::vector<Mesh>> load_gltf(const std::filesystem::path& path);

/// What the seabed looks like.
enum class SeabedPattern : std::uint8_t {
  sand,     ///< albedo modulated by low ripples (±30 %)
  checker,  ///< squares of side period/2, albedo and a quarter of it (tests, calibration)
};

/// A flat seabed seen through the water (docs/rendering.md R.22–R.23): the view ray refracted at
/// the surface (Snell, n = 1.333), attenuated along its path in the water and the light along
/// its way down by Beer–Lambert with the absorption of pure water, mixed with the water body's
/// colour as shallow-water reflectance (Maritorena, Morel & Gentili 1994).
struct Seabed {
  bool enabled = false;
  double depth_m = 5.0;                          ///< below the mean sea level, (0, 1e4]
  std::array<double, 3> albedo{0.6, 0.55, 0.4};  ///< linear RGB, [0, 1]: pale sand
  SeabedPattern pattern = SeabedPattern::sand;
  double period_m = 2.0;  ///< of the pattern, (0, 1e4]
  /// Absorption coefficient per channel, 1/m, [0, 100]: pure water at 650, 550 and 450 nm
  /// (Pope & Fry 1997, Table 3: 0.340, 0.0565, 0.00922 m⁻¹) — the clearest water there is.
  std::array<double, 3> absorption_per_m{0.340, 0.0565, 0.00922};
};
/// invalid_argument naming the field for values outside the ranges above or not finite.
Status validate(const Seabed& seabed);

/// One placed mesh: the index into the meshes given to Renderer::set_meshes and its transform.
struct ObjectInstance {
  std::uint32_t mesh = 0;
  std::array<double, 16> model{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  ///< column-major
};
/// The rigid transform of a position (m) and a unit quaternion (w, x, y, z), column-major.
std::array<double, 16> model_matrix(const std::array<double, 3>& position_m,
                                    const std::array<double, 4>& orientation);

}  // namespace ocean::render
