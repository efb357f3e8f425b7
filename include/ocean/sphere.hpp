// ocean/sphere.hpp — the sea on a sphere (docs/rendering.md R.30–R.37): the cascades sampled
// tri-planarly (Paleologue, "Ocean Simulation with FFT and WebGPU", 2024, the sphere section),
// heights along the sphere's normal, the choppy displacement in its tangent plane, and the
// quadtree LOD on the six faces of a cube-sphere with frustum and horizon culling.
//
// CPU only, double precision. Conventions: planet-centred metres, +Y the north pole's axis; a
// direction n = (cos lat·cos lon, sin lat, cos lat·sin lon), so longitude turns from +x towards
// +z and the tangent frame (east, up, north) is right-handed like the flat sea's (x, y, z). The
// math, with equation numbers R.30…, is docs/rendering.md.
//
// Errors: functions that take user input return Status/Result (never throw); preconditions on
// validated data are asserts.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <unordered_set>
#include <vector>

#include "ocean/core.hpp"
#include "ocean/lod.hpp"

namespace ocean::sphere {

using lod::Vec3;

// ---- the tangent frame and the tri-planar weights (sphere_frame.cpp) ---------------------------

/// An orthonormal frame at a point of the unit sphere: t1 × n = −t2 (so (t1, n, −t2) is (east,
/// up, north)).
struct TangentFrame {
  Vec3 t1;             ///< Paleologue's t₁ = (−sin φ, 0, cos φ): east
  Vec3 t2;             ///< Paleologue's t₂ = (cos θ cos φ, −sin θ, cos θ sin φ): south
  Vec3 n;              ///< the sphere's unit normal
  bool polar = false;  ///< true: the polar cap's axis frame (R.31), not the seed's
};

/// Within this angle of a pole (sin θ < kPolarCapSin) the frame is the cap's axis frame.
inline constexpr double kPolarCapSin = 0.1;

/// Paleologue's frame with θ the colatitude and φ the longitude of n (R.30). Precondition: n is
/// a unit vector not at a pole (sin θ > 0).
TangentFrame seed_frame(Vec3 n);
/// The axis frame of the polar caps (R.31): t1 = the unit projection of +z on the tangent
/// plane, t2 = n × t1. Equal to seed_frame on the meridian φ = 0. Precondition: |n_z| < 1.
TangentFrame polar_frame(Vec3 n);
/// seed_frame outside the caps, polar_frame inside them (R.31). Precondition: |n| = 1.
TangentFrame tangent_frame(Vec3 n);

/// The tri-planar weights of the projections along x, y, z at the unit normal n (R.32): the
/// sharpened |n_a|, scaled so their squares sum to one (variance-preserving, Heitz & Neyret
/// 2018), so that two uncorrelated projections blend with the variance of either.
std::array<double, 3> triplanar_weights(Vec3 n);

/// The displacement (Dx, h, Dz) of the flat sea at the plane point (x, z), as
/// Simulator::displacement_at returns it.
using FlatSampler = std::function<std::array<double, 3>(double x, double z)>;

/// A point of the displaced sphere.
struct SurfacePoint {
  Vec3 position_m;  ///< planet-centred, displaced
  double height_m;  ///< along the sphere's normal, above R
  double d1_m;      ///< tangential displacement along the frame's t1
  double d2_m;      ///< and t2
};

/// The sea on a sphere of radius R at the unit direction n (R.33–R.34): each projection a
/// samples the flat sea at the point's coordinates in its plane; heights add along n, the
/// projections' horizontal displacements are projected on the tangent plane and add there; all
/// with the weights of triplanar_weights. Frame-free except for (d1, d2), given in
/// tangent_frame(n). Preconditions: R > 0, |n| = 1.
SurfacePoint displaced_point(double radius_m, Vec3 n, const FlatSampler& sample);

/// The Jacobian of the tangential displacement at n in the frame `frame` (R.35): det(I + ∂d/∂s)
/// with s the arc lengths along t1, t2, by central differences of step `step_m`. Invariant under
/// a rotation of the frame about n (R.35), so the foam does not see where the frame switches.
double jacobian(double radius_m, Vec3 n, const TangentFrame& frame, const FlatSampler& sample,
                double step_m);

// ---- the cube-sphere (cube_sphere.cpp) ---------------------------------------------------------

inline constexpr int kFaces = 6;
/// The deepest level of a face's quadtree: finest patches of ~15 m on Earth.
inline constexpr int kMaxSphereLevels = 20;

/// Face f's axes (R.36): its outward normal N, and U, V with V = U × N, so that patch (x, z)
/// → (U, V) keeps the flat mesh's triangles facing outwards. Cube point N + u·U + v·V,
/// u, v ∈ [−1, 1].
struct FaceAxes {
  Vec3 n, u, v;
};
FaceAxes face_axes(int face);
/// The cube point N + u·U + v·V of face `face`.
Vec3 cube_point(int face, double u, double v);
/// The unit direction of a cube point (the gnomonic map's inverse, R.36).
Vec3 cube_to_sphere(Vec3 cube);
/// The face and (u, v) of the cube's ray through a non-zero point: the face whose axis has the
/// largest |component|, then p divided by it.
void sphere_to_face(Vec3 p, int& face, double& u, double& v);

/// dir(c + δ) − dir(c) in single precision, as the vertex shader computes it (sphere.glsl's
/// sphere_offset mirrors it, R.38): δ/|c+δ| − c·(2c·δ + δ·δ)/(|c+δ|·|c|·(|c+δ| + |c|)), whose
/// rounding errors are relative to |δ| rather than to |c|, so that R times it stays within a
/// millimetre for the patches near the camera on Earth. c is a cube point of a patch centre, δ
/// a vertex's offset from it (both exact in float: dyadic).
std::array<float, 3> sphere_offset(std::array<float, 3> c, std::array<float, 3> delta);

// ---- selection (sphere_select.cpp) -------------------------------------------------------------

struct SphereLodParams {
  double radius_m = 6.371e6;  ///< R > 0
  lod::Quality quality = lod::quality_preset(lod::QualityPreset::high);
  Vec3 camera_position_m;  ///< planet-centred, outside the sphere
  /// Culling planes in planet-centred metres. Ignored when !cull.
  lod::Frustum frustum;
  bool cull = true;  ///< false: every leaf of all six faces is emitted (a closed sphere)
  /// Side below which no patch splits, m (> 0); the levels stop at kMaxSphereLevels anyway.
  double finest_patch_m = 32.0;
  double max_vertical_displacement_m = 0.0;    ///< largest |h| of the waves, ≥ 0
  double max_horizontal_displacement_m = 0.0;  ///< largest tangential displacement, ≥ 0
};
/// invalid_argument naming the field for values outside the ranges above or non-finite, and
/// for a camera inside the sphere.
Status validate(const SphereLodParams& params);

/// One patch of a face: the unit mesh of lod::PatchMeshes mapped onto face `face` at cube
/// coordinates centre (u, v) ± size/2 and pushed onto the sphere.
struct SpherePatch {
  std::uint32_t x = 0, y = 0;             ///< node column (along U) and row (along V) at its level
  std::uint8_t face = 0;                  ///< [0, 6)
  std::uint8_t level = 0;                 ///< [0, kMaxSphereLevels]
  std::uint8_t config = 0;                ///< stitching configuration, lod::EdgeBit mask
  double centre_u = 0.0, centre_v = 0.0;  ///< cube coordinates of the centre, dyadic
  double size = 0.0;                      ///< side in cube coordinates, 2/2^level
};

/// The result of select_sphere_patches, reused every frame.
struct SphereSelection {
  int max_level = 0;                        ///< the deepest level any face may reach this frame
  std::vector<SpherePatch> patches;         ///< sorted by config; batches index into it
  std::vector<lod::Batch> batches;          ///< ≤ 16
  std::uint32_t culled_frustum = 0;         ///< leaves outside the frustum
  std::uint32_t culled_horizon = 0;         ///< leaves behind the horizon (R.37)
  std::vector<std::uint64_t> leaves;        ///< scratch: every leaf, culled ones too
  std::unordered_set<std::uint64_t> split;  ///< scratch: the split nodes
};

/// Per frame (R.36–R.37): each face's quadtree splits a node while the camera is nearer than
/// τ·s (s its side on the sphere) and s > finest_patch_m; then 2:1 balancing across edges and
/// across the cube's faces, so the 16 stitching configurations close every crack; then the
/// leaves outside the frustum or behind the horizon are dropped. Allocates (vectors grow to the
/// largest selection and are reused). invalid_argument from validate(params), with an empty
/// selection.
Status select_sphere_patches(const SphereLodParams& params, SphereSelection& selection);

}  // namespace ocean::sphere
