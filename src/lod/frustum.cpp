// Camera matrices, frustum planes and the AABB visibility test.
//
// Sources: Aebi, VR Ocean, §5.2.2 (eqs. 59–61); G. Gribb and K. Hartmann, "Fast Extraction of
// Viewing Frustum Planes from the World-View-Projection Matrix" (2001), adapted to Vulkan's [0, 1]
// depth; docs/lod.md L.5–L.6.
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
  if (Status s = require_in_range("camera.fov_y_rad", camera.fov_y_rad, 1e-6, 3.14159); !s.ok()) {
    return s;
  }
  if (Status s = require_positive("camera.aspect", camera.aspect); !s.ok()) return s;
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
  return perspective(c.fov_y_rad, c.aspect, c.near_m, c.far_m) * look_at(c.position_m, c.target_m);
}

Frustum camera_frustum(const Camera& camera) {
  return frustum_from_view_projection(view_projection(camera));
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
