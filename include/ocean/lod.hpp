// ocean/lod.hpp — the adaptive quadtree level of detail of the ocean mesh (Aebi, VR Ocean, §5).
//
// CPU only, no GPU headers: the core produces plain data (patch instances grouped by stitching
// configuration, 16 index buffers, a skirt mesh) and a renderer consumes it.
//
// Conventions: Y up, the undisplaced sea is the x–z plane at y = 0, metres. The quadtree covers
// an ocean square of side S centred on the grid centre (the camera snapped to the grid, eq. L.9,
// or a fixed point). Level l has 2^l × 2^l nodes of side s_l = S/2^l; node (x, y) spans
// [x·s_l, (x+1)·s_l] along +x and [y·s_l, (y+1)·s_l] along +z from the square's corner
// (centre − S/2). "East" is +x, "north" is +z. Every triangle faces +y: for its corners a, b, c,
// ((b − a) × (c − a)).y > 0. The math, with equation numbers L.1…, is docs/lod.md.
//
// Errors: functions that take user input return Status/Result (never throw); preconditions on
// already-validated data are asserts.
#pragma once

#include <array>
#include <cstdint>
#include <numbers>
#include <optional>
#include <string_view>
#include <vector>

#include "ocean/core.hpp"
#include "ocean/names.hpp"

namespace ocean::lod {

// ---- quality presets (quality.cpp) --------------------------------------------------------------

/// Aebi, VR Ocean, Table 2.
enum class QualityPreset : std::uint8_t { low, medium, high, ultra };

/// Mesh density and LOD distances.
struct Quality {
  int vertices = 32;       ///< V: quads per patch side, even, in [2, 254] ((V+1)² vertices)
  double lod_scale = 1.5;  ///< τ > 0: a node subdivides while its centre is closer than τ·s (L.3)
  double cull_scale = 1.5;  ///< β ≥ 1: the culling box is β times the node (L.5)
};

/// Table 2: low {16, 2.0, 1.2}, medium {32, 1.5, 1.5}, high {64, 1.2, 1.8}, ultra {64, 1.0, 2.0}.
constexpr Quality quality_preset(QualityPreset preset) {
  switch (preset) {
    case QualityPreset::low: return {.vertices = 16, .lod_scale = 2.0, .cull_scale = 1.2};
    case QualityPreset::medium: return {.vertices = 32, .lod_scale = 1.5, .cull_scale = 1.5};
    case QualityPreset::high: return {.vertices = 64, .lod_scale = 1.2, .cull_scale = 1.8};
    case QualityPreset::ultra: return {.vertices = 64, .lod_scale = 1.0, .cull_scale = 2.0};
  }
  return {};
}
/// The names of the quality presets in flags, panels and messages.
inline constexpr std::array<EnumName<QualityPreset>, 4> kQualityPresetNames{{
    {QualityPreset::low, "low"},
    {QualityPreset::medium, "medium"},
    {QualityPreset::high, "high"},
    {QualityPreset::ultra, "ultra"},
}};
/// The preset's name in kQualityPresetNames: "low", "medium", "high", "ultra".
std::string_view preset_name(QualityPreset preset);
/// The preset of a name in kQualityPresetNames; invalid_argument naming `name` otherwise.
Result<QualityPreset> parse_preset(std::string_view name);

/// Valid ocean sizes S, metres (Aebi, VR Ocean, §5.1).
inline constexpr double kMinOceanSize_m = 256.0;
inline constexpr double kMaxOceanSize_m = 8192.0;
/// The deepest level L_max can be (eq. L.1); instances store grid coordinates in 8 bits.
inline constexpr int kMaxLevels = 8;

/// L_max = clamp(⌊log2(S/64) + 0.5⌋, 2, 8) (Aebi, VR Ocean, eq. 56, L.1). Precondition: S > 0,
/// finite.
int max_level(double ocean_size_m);

/// invalid_argument naming the field unless V is even in [2, 254], τ > 0 and β ≥ 1 (all finite).
Status validate(const Quality& quality);

// ---- camera and frustum (frustum.cpp) -----------------------------------------------------------

struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;
};

/// 4×4 matrix, column-major like GLSL: element (row r, column c) is m[c*4 + r]; transforms
/// column vectors, p' = M·p.
struct Mat4 {
  std::array<double, 16> m{};
};
Mat4 operator*(const Mat4& a, const Mat4& b);

/// Right-handed view matrix: the camera at `eye` looks along −z of view space towards `target`,
/// view +y towards `up`. When the view direction is parallel to `up` (looking straight down or
/// up) view +y is taken along world −z instead. Precondition: eye ≠ target.
Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up = {0.0, 1.0, 0.0});
/// Right-handed perspective with Vulkan's depth range: view z = −near → depth 0, −far → 1;
/// clip y is not flipped (a Vulkan renderer flips with a negative viewport height).
Mat4 perspective(double fov_y_rad, double aspect, double near_m, double far_m);

/// An asymmetric field of view: the angles of the frustum's four sides from the view's −z axis,
/// radians, in OpenXR's convention (XrFovf): left and down are negative when the side lies left
/// of or below the axis, right and up positive when it lies right of or above it. Each in
/// (−π/2, π/2), left < right, down < up. A headset's eye usually sees farther outwards and down
/// than inwards and up.
struct FovAngles {
  double left_rad = -std::numbers::pi / 4.0;
  double right_rad = std::numbers::pi / 4.0;
  double up_rad = std::numbers::pi / 4.0;
  double down_rad = -std::numbers::pi / 4.0;
};
/// The off-axis perspective of `fov` (docs/lod.md L.12) with perspective()'s depth range and
/// orientation: a view direction (tan α, tan β, −1) maps to NDC x = −1 at α = left, +1 at α =
/// right, y = −1 at β = down, +1 at β = up. Precondition: `fov` valid (validate(Camera)).
Mat4 perspective(const FovAngles& fov, double near_m, double far_m);

/// A plane n·p + d = 0 with |n| = 1; points with n·p + d ≥ 0 are inside.
struct Plane {
  double nx = 0.0, ny = 0.0, nz = 0.0, d = 0.0;
};
/// The six inward-facing planes: left, right, bottom, top, near, far.
struct Frustum {
  std::array<Plane, 6> planes{};
};
/// The planes of clip space −w ≤ x, y ≤ w, 0 ≤ z ≤ w of a view-projection matrix (Gribb and
/// Hartmann 2001), normalised.
Frustum frustum_from_view_projection(const Mat4& view_projection);

/// The camera of the renderer, `ocean lod` and the tests. The default form is a symmetric
/// frustum (fov_y_rad, aspect) with a level horizon (up = +y); a headset's eye also rolls (up
/// leans with the head) and has an asymmetric frustum (fov).
struct Camera {
  Vec3 position_m;                            ///< eye, world metres
  Vec3 target_m{0.0, 0.0, -1.0};              ///< a point it looks at, ≠ position_m
  double fov_y_rad = std::numbers::pi / 3.0;  ///< vertical field of view, (0, π); default 60°
  double aspect = 16.0 / 9.0;                 ///< width / height, > 0
  double near_m = 0.5;                        ///< near plane distance, > 0
  double far_m = 1.0e5;                       ///< far plane distance, > near_m
  /// The world direction the picture's up leans towards (look_at's `up`), finite, ≠ 0: +y keeps
  /// the horizon level; the head's up rolls the picture (L.11).
  Vec3 up{0.0, 1.0, 0.0};
  /// An asymmetric frustum (L.12); when set, fov_y_rad and aspect are not used (the picture's
  /// width and height span the angles whatever its pixel aspect, as a headset's eye image).
  std::optional<FovAngles> fov;
};
/// invalid_argument naming the field for non-finite values, eye == target, a zero up, or ranges
/// above.
Status validate(const Camera& camera);
/// perspective(...) · look_at(position_m, target_m, up), with perspective(*fov, ...) when fov is
/// set. Precondition: validate(camera) is ok.
Mat4 view_projection(const Camera& camera);
/// The vertical angle the camera spans, radians: fov_y_rad, or up − down with fov.
double vertical_fov_rad(const Camera& camera);
Frustum camera_frustum(const Camera& camera);
/// The frustum's eight corners, world metres: near (bottom-left, bottom-right, top-right,
/// top-left), then far in the same order. Precondition: validate(camera) is ok.
std::array<Vec3, 8> frustum_corners(const Camera& camera);
/// Six planes bounding both cameras' frusta (L.13): for each side the one of the two cameras'
/// planes that needs the smaller outward shift to hold all sixteen corners, shifted that far
/// (shifts under 1e-9 of the far distance are the corners' rounding and not made).
/// Two eyes of parallel axes give the left eye's left plane, the right eye's right plane and
/// the shared others unshifted. Precondition: both cameras valid.
Frustum bounding_frustum(const Camera& a, const Camera& b);

/// Aebi, VR Ocean, eqs. 59–60 (L.6): false only when the box centre ± half extents lies wholly
/// outside one plane (tests the corner farthest along each plane normal). Conservative: a box
/// outside the frustum near an edge or corner can still answer true.
bool box_visible(const Frustum& frustum, Vec3 centre, Vec3 half_extents);

// ---- grid snapping (snapping.cpp) ---------------------------------------------------------------

/// The snap step δ = S/V (L.9): the vertex spacing of the coarsest level, so every level's
/// vertices stay on one world lattice when the grid moves (Aebi, VR Ocean, eq. 69, prints S/(2V);
/// see docs/lod.md). Precondition: S > 0, V > 0.
double snap_step_m(double ocean_size_m, int vertices);
/// ⌊value/step⌋·step, exact when value/step is representable (Aebi, VR Ocean, eq. 69).
double snap(double value_m, double step_m);

// ---- selection (quadtree.cpp) -------------------------------------------------------------------

/// Edge bits of a stitching configuration (Aebi, VR Ocean, eq. 64): the bit is set when the
/// neighbour across that edge is one level coarser; that edge then drops its odd vertices.
enum EdgeBit : std::uint8_t { kEast = 1, kNorth = 2, kWest = 4, kSouth = 8 };
inline constexpr int kConfigurations = 16;

/// What select_patches needs per frame.
struct LodParams {
  double ocean_size_m = 1024.0;  ///< S, in [256, 8192] m
  Quality quality = quality_preset(QualityPreset::medium);
  Vec3 camera_position_m;  ///< the viewer of the distance test (L.3), world metres
  /// Culling planes (camera_frustum or frustum_from_view_projection). Ignored when !cull.
  Frustum frustum;
  bool cull = true;  ///< false: every leaf is emitted, covering the whole ocean square
  /// true: the grid centre is the camera's (x, z) snapped to snap_step_m (L.9); false: it is
  /// (fixed_centre_x_m, fixed_centre_z_m) unchanged.
  bool follow_camera = true;
  double fixed_centre_x_m = 0.0;
  double fixed_centre_z_m = 0.0;
  /// Largest |y| of the displaced surface, m, for the culling boxes (L.5); negative: 0.015·S
  /// (Aebi's default h_max = 0.03·S taken as a crest-to-trough range).
  double max_vertical_displacement_m = -1.0;
  /// Largest horizontal (choppy) displacement, m, ≥ 0; widens the culling boxes (L.5).
  double max_horizontal_displacement_m = 0.0;
};
/// invalid_argument naming the field for anything outside the ranges above or non-finite.
Status validate(const LodParams& params);

/// One patch to draw: the unit mesh of PatchMeshes scaled by size_m and moved to the centre
/// (Aebi, VR Ocean, eq. 70). 16 bytes, ready for an instance buffer.
struct PatchInstance {
  float centre_x_m = 0.0f;  ///< world x of the patch centre, m
  float centre_z_m = 0.0f;  ///< world z of the patch centre, m
  float size_m = 0.0f;      ///< side s_l = S/2^l, m (the uniform scale of eq. 70)
  std::uint8_t grid_x = 0;  ///< node column at its level, [0, 2^level)
  std::uint8_t grid_y = 0;  ///< node row (+z) at its level, [0, 2^level)
  std::uint8_t level = 0;   ///< l in [0, L_max]
  std::uint8_t config = 0;  ///< stitching configuration, EdgeBit mask in [0, 15]
};
static_assert(sizeof(PatchInstance) == 16);

/// A run of instances sharing one configuration: one instanced draw of
/// PatchMeshes::indices[config].
struct Batch {
  std::uint32_t config = 0;  ///< [0, 15]
  std::uint32_t first = 0;   ///< index of the first instance in LodSelection::instances
  std::uint32_t count = 0;   ///< > 0
};

/// The result of select_patches, owned by the caller and reused every frame.
struct LodSelection {
  int max_level = 0;             ///< L_max of the last selection
  double grid_centre_x_m = 0.0;  ///< centre of the ocean square, world metres
  double grid_centre_z_m = 0.0;
  std::vector<PatchInstance> instances;  ///< sorted by config; the batches index into it
  std::vector<Batch> batches;            ///< ≤ 16, ascending config, empty configs left out
  std::array<std::uint32_t, kMaxLevels + 1> patches_per_level{};
  std::array<std::uint32_t, kConfigurations> patches_per_config{};
  /// Aebi's subdivision map: W×W (W = 2^L_max) finest cells, row-major [gy·W + gx], each the
  /// level of the leaf covering it — culled leaves included.
  std::vector<std::uint8_t> subdivision_map;
  int map_width = 0;  ///< W
  /// Scratch of select_patches; contents unspecified.
  std::vector<std::uint8_t> split;
  std::vector<std::uint32_t> stack;
  std::vector<PatchInstance> unsorted;
};

/// Setup step: reserves every vector of `selection` for the largest selection an ocean of side
/// `ocean_size_m` can produce (W² instances), so that later select_patches calls with that size or
/// a smaller one never allocate. invalid_argument for a size outside [256, 8192].
Status reserve_selection(LodSelection& selection, double ocean_size_m);

/// Per frame: chooses the patches for `params` (docs/lod.md L.2–L.8): the distance test of Aebi,
/// VR Ocean, eqs. 57–58 over an explicit stack, a 2:1 balancing pass (so that the 16 stitching
/// configurations close every crack), the subdivision map, frustum culling of the leaves,
/// neighbour flags (eqs. 62–64) and batching by configuration (eq. 70).
/// Allocation: none once reserve_selection was called for this ocean size (vectors are cleared
/// and refilled within their capacity). Never throws. Not thread-safe on one selection; distinct
/// selections may be filled concurrently. On invalid params returns invalid_argument and leaves
/// `selection` empty.
Status select_patches(const LodParams& params, LodSelection& selection);

// ---- patch meshes and stitching (stitching.cpp) -------------------------------------------------

/// The shared patch mesh: (V+1)² vertices and one index buffer per configuration, built once.
struct PatchMeshes {
  int vertices = 0;  ///< V
  /// (V+1)² vertices (x, z) in the unit square [−0.5, 0.5]², vertex (i, j) at index
  /// i + j·(V+1) (Aebi, VR Ocean, eqs. 67–68); y = 0.
  std::vector<float> positions_xz;
  /// Triangle lists (3 indices per triangle), one per configuration: 8·(V/2)² − (V/2)·popcount
  /// triangles (eq. L.8).
  std::array<std::vector<std::uint16_t>, kConfigurations> indices;
};

/// Triangle list of one configuration for a V×V-quad patch (Aebi, VR Ocean, eqs. 65–68, L.8): V/2 ×
/// V/2 cells of 3×3 vertices fanned around their centre; on an edge flagged in `config` the cells
/// drop that edge's midpoint. Preconditions: V even in [2, 254], config in [0, 15].
std::vector<std::uint16_t> build_patch_indices(int vertices, int config);
/// All 16 index buffers and the vertices. invalid_argument unless V is even in [2, 254].
Result<PatchMeshes> build_patch_meshes(int vertices);

// ---- skirt (skirt.cpp) --------------------------------------------------------------------------

/// How finely the skirt is cut: the default is Aebi's (3 vertex pairs); a renderer that bends the
/// skirt with the planet's curvature needs more.
struct SkirtTessellation {
  int segments = 2;  ///< quads along each side of the square, even, ≥ 2
  int rings = 1;     ///< quads from the square out to the outer edge, ≥ 1
};

/// The horizon skirt of Aebi, VR Ocean, §5.7 (L.10): a grid from the north edge of the ocean
/// square (half-extent S/2) out to the outer half-extent R, drawn 4 times rotated by 0°, 90°,
/// 180°, 270° about +y around the grid centre, so the four trapezoids tile the square ring
/// between S/2 and R. With the default tessellation it is Aebi's strip of 3 vertex pairs.
struct SkirtMesh {
  /// (segments + 1)·(rings + 1) vertices (x, z) relative to the grid centre, m, y = 0, ring by
  /// ring from the inside: vertex i of ring k at (d_k·(−1 + 2i/segments), d_k), with the ring's
  /// half-extent d_k = (S/2)·(R/(S/2))^(k/rings) (rings spaced geometrically).
  std::vector<float> positions_xz;
  /// Triangle strip over (inner, outer) pairs west to east; only for rings = 1, empty otherwise.
  std::vector<std::uint16_t> strip;
  std::vector<std::uint16_t> triangles;  ///< 2·segments·rings triangles, facing +y
  /// Instance i rotates by i·90° about +y: (x, z) → (c·x + s·z, −s·x + c·z), stored {c, s}.
  std::array<std::array<float, 2>, 4> rotations{};
};
/// invalid_argument unless S is in [256, 8192], the outer half-extent R > S/2 and the
/// tessellation is in range (four copies within 16-bit indices); R ≤ 0 selects the default
/// R = 10·S.
Result<SkirtMesh> build_skirt(double ocean_size_m, double outer_half_extent_m = -1.0,
                              SkirtTessellation tessellation = {});

}  // namespace ocean::lod
