// Camera matrices, frustum planes and the AABB visibility test.
//
// Sources: Aebi, VR Ocean, §5.2.2 (eqs. 59–61); G. Gribb and K. Hartmann, "Fast Extraction of
// Viewing Frustum Planes from the World-View-Projection Matrix" (2001), adapted to Vulkan's [0, 1]
// depth; docs/lod.md L.5–L.6.
#include <algorithm>
#include <cassert>
#include <cmath>

#include "ocean/lod.hpp"

namespace ocean::lod {

namespace {

double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 sub(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Vec3 normalize(Vec3 v) {
  const double n = std::sqrt(dot(v, v));
  return {v.x / n, v.y / n, v.z / n};
}
double& at(Mat4& a, int row, int col) { return a.m[static_cast<std::size_t>(col * 4 + row)]; }
double at(const Mat4& a, int row, int col) { return a.m[static_cast<std::size_t>(col * 4 + row)]; }

Status require_finite_vec(std::string_view name, Vec3 v) {
  for (double c : {v.x, v.y, v.z}) {
    if (Status s = require_finite(name, c); !s.ok()) return s;
  }
  return {};
}

}  // namespace

Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 r;
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 4; ++col) {
      double s = 0.0;
      for (int k = 0; k < 4; ++k) s += at(a, row, k) * at(b, k, col);
      at(r, row, col) = s;
    }
  }
  return r;
}

Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up) {
  const Vec3 f = normalize(sub(target, eye));
  Vec3 side = cross(f, up);
  // Looking along ±up: any side vector works; world −z as view up keeps +x to the right when
  // looking straight down.
  if (dot(side, side) < 1e-12 * dot(up, up)) side = cross(f, Vec3{0.0, 0.0, -1.0});
  const Vec3 s = normalize(side);
  const Vec3 u = cross(s, f);
  Mat4 v;
  const Vec3 rows[3] = {s, u, {-f.x, -f.y, -f.z}};
  for (int r = 0; r < 3; ++r) {
    at(v, r, 0) = rows[r].x;
    at(v, r, 1) = rows[r].y;
    at(v, r, 2) = rows[r].z;
    at(v, r, 3) = -dot(rows[r], eye);
  }
  at(v, 3, 3) = 1.0;
  return v;
}

Mat4 perspective(double fov_y_rad, double aspect, double near_m, double far_m) {
  const double f = 1.0 / std::tan(0.5 * fov_y_rad);
  Mat4 p;
  at(p, 0, 0) = f / aspect;
  at(p, 1, 1) = f;
  at(p, 2, 2) = far_m / (near_m - far_m);
  at(p, 2, 3) = near_m * far_m / (near_m - far_m);
  at(p, 3, 2) = -1.0;
  return p;
}

// L.12: x_ndc = (2·tan α − (t_r + t_l))/(t_r − t_l) for a view direction (tan α, tan β, −1),
// i.e. clip x = (2·x_v + (t_r + t_l)·z_v)/(t_r − t_l) with w = −z_v; y alike with up and down.
// Depth as perspective(): z_v = −near → 0, −far → 1.
Mat4 perspective(const FovAngles& fov, double near_m, double far_m) {
  const double tl = std::tan(fov.left_rad), tr = std::tan(fov.right_rad);
  const double td = std::tan(fov.down_rad), tu = std::tan(fov.up_rad);
  Mat4 p;
  at(p, 0, 0) = 2.0 / (tr - tl);
  at(p, 0, 2) = (tr + tl) / (tr - tl);
  at(p, 1, 1) = 2.0 / (tu - td);
  at(p, 1, 2) = (tu + td) / (tu - td);
  at(p, 2, 2) = far_m / (near_m - far_m);
  at(p, 2, 3) = near_m * far_m / (near_m - far_m);
  at(p, 3, 2) = -1.0;
  return p;
}

Frustum frustum_from_view_projection(const Mat4& vp) {
  auto row = [&](int r) {
    return std::array<double, 4>{at(vp, r, 0), at(vp, r, 1), at(vp, r, 2), at(vp, r, 3)};
  };
  const auto r0 = row(0), r1 = row(1), r2 = row(2), r3 = row(3);
  auto plane = [](std::array<double, 4> a, std::array<double, 4> b, double sign) {
    Plane p{a[0] + sign * b[0], a[1] + sign * b[1], a[2] + sign * b[2], a[3] + sign * b[3]};
    const double n = std::sqrt(p.nx * p.nx + p.ny * p.ny + p.nz * p.nz);
    if (n > 0.0) p = {p.nx / n, p.ny / n, p.nz / n, p.d / n};
    return p;
  };
  const std::array<double, 4> zero{};
  return {{plane(r3, r0, 1.0), plane(r3, r0, -1.0), plane(r3, r1, 1.0), plane(r3, r1, -1.0),
           plane(r2, zero, 1.0), plane(r3, r2, -1.0)}};
}

Status validate(const Camera& camera) {
  if (Status s = require_finite_vec("camera.position_m", camera.position_m); !s.ok()) return s;
  if (Status s = require_finite_vec("camera.target_m", camera.target_m); !s.ok()) return s;
  const Vec3 d = sub(camera.target_m, camera.position_m);
  if (!(dot(d, d) > 0.0) || std::isinf(dot(d, d))) {
    return invalid_argument(
        "camera.target_m equals camera.position_m: the view direction is "
        "undefined; give a target away from the camera");
  }
  if (Status s = require_finite_vec("camera.up", camera.up); !s.ok()) return s;
  if (!(dot(camera.up, camera.up) > 0.0) || std::isinf(dot(camera.up, camera.up))) {
    return invalid_argument("camera.up is zero: give the direction the picture's up leans to");
  }
  if (camera.fov) {
    const FovAngles& f = *camera.fov;
    constexpr double kEdge = 1.5707;  // just inside π/2: the side's tangent stays finite
    if (Status s = require_in_range("camera.fov.left_rad", f.left_rad, -kEdge, kEdge); !s.ok())
      return s;
    if (Status s = require_in_range("camera.fov.right_rad", f.right_rad, -kEdge, kEdge); !s.ok())
      return s;
    if (Status s = require_in_range("camera.fov.up_rad", f.up_rad, -kEdge, kEdge); !s.ok())
      return s;
    if (Status s = require_in_range("camera.fov.down_rad", f.down_rad, -kEdge, kEdge); !s.ok())
      return s;
    if (!(f.right_rad - f.left_rad >= 1e-6))
      return invalid_argument("camera.fov.right_rad = " + format_number(f.right_rad) +
                              " must exceed camera.fov.left_rad = " + format_number(f.left_rad));
    if (!(f.up_rad - f.down_rad >= 1e-6))
      return invalid_argument("camera.fov.up_rad = " + format_number(f.up_rad) +
                              " must exceed camera.fov.down_rad = " + format_number(f.down_rad));
  } else {
    if (Status s = require_in_range("camera.fov_y_rad", camera.fov_y_rad, 1e-6, 3.14159); !s.ok()) {
      return s;
    }
    if (Status s = require_positive("camera.aspect", camera.aspect); !s.ok()) return s;
  }
  if (Status s = require_positive("camera.near_m", camera.near_m); !s.ok()) return s;
  if (Status s = require_positive("camera.far_m", camera.far_m); !s.ok()) return s;
  if (!(camera.far_m > camera.near_m)) {
    return invalid_argument(
        "camera.far_m = " + format_number(camera.far_m) +
        " is out of range: must be > camera.near_m = " + format_number(camera.near_m));
  }
  return {};
}

Mat4 view_projection(const Camera& c) {
  const Mat4 projection = c.fov ? perspective(*c.fov, c.near_m, c.far_m)
                                : perspective(c.fov_y_rad, c.aspect, c.near_m, c.far_m);
  return projection * look_at(c.position_m, c.target_m, c.up);
}

double vertical_fov_rad(const Camera& c) {
  return c.fov ? c.fov->up_rad - c.fov->down_rad : c.fov_y_rad;
}

Frustum camera_frustum(const Camera& camera) {
  return frustum_from_view_projection(view_projection(camera));
}

std::array<Vec3, 8> frustum_corners(const Camera& c) {
  // The view basis of look_at: rows s (right), u (up), −f; a view point (x, y, z) is at
  // eye + x·s + y·u − z·f in the world.
  const Mat4 v = look_at(c.position_m, c.target_m, c.up);
  const Vec3 s{at(v, 0, 0), at(v, 0, 1), at(v, 0, 2)};
  const Vec3 u{at(v, 1, 0), at(v, 1, 1), at(v, 1, 2)};
  const Vec3 f{-at(v, 2, 0), -at(v, 2, 1), -at(v, 2, 2)};
  double tl, tr, td, tu;
  if (c.fov) {
    tl = std::tan(c.fov->left_rad), tr = std::tan(c.fov->right_rad);
    td = std::tan(c.fov->down_rad), tu = std::tan(c.fov->up_rad);
  } else {
    tu = std::tan(0.5 * c.fov_y_rad), td = -tu;
    tr = tu * c.aspect, tl = -tr;
  }
  const double tx[4] = {tl, tr, tr, tl}, ty[4] = {td, td, tu, tu};
  std::array<Vec3, 8> corners{};
  for (int k = 0; k < 8; ++k) {
    const double d = k < 4 ? c.near_m : c.far_m;
    const double x = tx[k % 4] * d, y = ty[k % 4] * d;
    corners[static_cast<std::size_t>(k)] = {c.position_m.x + x * s.x + y * u.x + d * f.x,
                                            c.position_m.y + x * s.y + y * u.y + d * f.y,
                                            c.position_m.z + x * s.z + y * u.z + d * f.z};
  }
  return corners;
}

// L.13: each side's plane from the camera whose plane the other's corners leave least outside,
// moved out past them.
Frustum bounding_frustum(const Camera& a, const Camera& b) {
  const Frustum fa = camera_frustum(a), fb = camera_frustum(b);
  std::array<Vec3, 16> corners{};
  const std::array<Vec3, 8> ca = frustum_corners(a), cb = frustum_corners(b);
  std::copy(ca.begin(), ca.end(), corners.begin());
  std::copy(cb.begin(), cb.end(), corners.begin() + 8);
  // Corners are computed to about 1e-16 of their distance: a plane that leaves one out by less
  // than 1e-9 of the far distance holds it (and stays unmoved, as for parallel eyes).
  const double rounding = 1e-9 * std::max(a.far_m, b.far_m);
  const auto shift = [&](const Plane& p) {
    double lowest = 0.0;
    for (const Vec3& q : corners)
      lowest = std::min(lowest, p.nx * q.x + p.ny * q.y + p.nz * q.z + p.d);
    return lowest < -rounding ? -lowest : 0.0;
  };
  Frustum hull;
  for (std::size_t i = 0; i < 6; ++i) {
    const double sa = shift(fa.planes[i]), sb = shift(fb.planes[i]);
    Plane p = sb < sa ? fb.planes[i] : fa.planes[i];
    p.d += std::min(sa, sb);
    hull.planes[i] = p;
  }
  return hull;
}

// L.6 (Aebi, VR Ocean, eqs. 59–60): the positive vertex is the box corner farthest along n; if even
// it is outside a plane, the whole box is.
bool box_visible(const Frustum& frustum, Vec3 c, Vec3 e) {
  for (const Plane& p : frustum.planes) {
    const double px = c.x + (p.nx >= 0.0 ? e.x : -e.x);
    const double py = c.y + (p.ny >= 0.0 ? e.y : -e.y);
    const double pz = c.z + (p.nz >= 0.0 ? e.z : -e.z);
    if (p.nx * px + p.ny * py + p.nz * pz + p.d < 0.0) return false;
  }
  return true;
}

}  // namespace ocean::lod
