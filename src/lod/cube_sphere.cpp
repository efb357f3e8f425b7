// The cube-sphere (docs/rendering.md R.36): six faces, each a square [−1, 1]² of cube
// coordinates with its own quadtree, pushed onto the unit sphere by normalisation (the inverse
// of the gnomonic projection). The faces' grids meet at the cube's edges at the same dyadic
// points from both sides, so the flat LOD's 2:1 rule and 16 stitching configurations carry over
// across the faces' edges.
//
// This work is based on: Cozzi & Ring, "3D Engine Design for Virtual Globes" (2011), ch. 4
// (tessellating a globe from a cube's faces).
#include <cassert>
#include <cmath>

#include "ocean/sphere.hpp"

namespace ocean::sphere {

namespace {

// Faces +x, −x, +y, −y, +z, −z, each with V = U × N (R.36): the flat patch's (x, y, z) maps to
// (U, N, V), a rotation, so triangles that face +y face outwards.
constexpr FaceAxes kFaceAxes[kFaces] = {
    {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},    // +x: U = z, V = y
    {{-1, 0, 0}, {0, 0, -1}, {0, 1, 0}},  // −x: U = −z, V = y
    {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},    // +y: the flat sea's x, z
    {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},  // −y
    {{0, 0, 1}, {-1, 0, 0}, {0, 1, 0}},   // +z: U = −x, V = y
    {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}},   // −z: U = x, V = y
};

double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

}  // namespace

FaceAxes face_axes(int face) {
  assert(face >= 0 && face < kFaces);
  return kFaceAxes[face];
}

Vec3 cube_point(int face, double u, double v) {
  const FaceAxes& f = kFaceAxes[face];
  return {f.n.x + u * f.u.x + v * f.v.x, f.n.y + u * f.u.y + v * f.v.y,
          f.n.z + u * f.u.z + v * f.v.z};
}

Vec3 cube_to_sphere(Vec3 c) {
  const double inv = 1.0 / std::sqrt(dot(c, c));
  return {c.x * inv, c.y * inv, c.z * inv};
}

void sphere_to_face(Vec3 p, int& face, double& u, double& v) {
  const double a[3] = {std::abs(p.x), std::abs(p.y), std::abs(p.z)};
  const int axis = a[0] >= a[1] && a[0] >= a[2] ? 0 : (a[1] >= a[2] ? 1 : 2);
  const double c = axis == 0 ? p.x : (axis == 1 ? p.y : p.z);
  face = 2 * axis + (c < 0.0 ? 1 : 0);
  const double inv = 1.0 / a[axis];  // onto the face's plane at distance 1
  u = dot(p, kFaceAxes[face].u) * inv;
  v = dot(p, kFaceAxes[face].v) * inv;
}

std::array<float, 3> sphere_offset(std::array<float, 3> c, std::array<float, 3> delta) {
  // R.38: dir(c + δ) − dir(c) = δ/|c + δ| + c·(1/|c + δ| − 1/|c|), the bracket rewritten as
  // −(2c·δ + δ·δ)/(|c + δ|·|c|·(|c + δ| + |c|)) so that no two large numbers are subtracted.
  const float cc = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
  const float cd = c[0] * delta[0] + c[1] * delta[1] + c[2] * delta[2];
  const float dd = delta[0] * delta[0] + delta[1] * delta[1] + delta[2] * delta[2];
  const std::array<float, 3> v{c[0] + delta[0], c[1] + delta[1], c[2] + delta[2]};
  const float lv = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), lc = std::sqrt(cc);
  const float k = -(2.0f * cd + dd) / (lv * lc * (lv + lc));
  return {delta[0] / lv + c[0] * k, delta[1] / lv + c[1] * k, delta[2] / lv + c[2] * k};
}

}  // namespace ocean::sphere
