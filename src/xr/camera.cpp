// A located view as the renderer's camera (docs/vr.md V.1–V.2): the pose's rotation gives the
// view direction (−Z) and the picture's up (+Y), so a rolled head rolls the picture; XrFovf's
// four angles give the asymmetric frustum (docs/lod.md L.11–L.12).
//
// Sources: The Khronos Group, "The OpenXR Specification" 1.0: "XrPosef" (Spaces: the pose
// takes the view's space into the base space; a view looks along its −Z with +Y up) and
// "XrFovf" (View and Projection State, xrLocateViews: angleLeft, angleRight, angleUp,
// angleDown).
#include "ocean/xr.hpp"

namespace ocean::xr {

namespace {

// R(q)·v for a unit quaternion q = (x, y, z, w) (v + 2w(u × v) + 2u × (u × v), u = (x, y, z)).
lod::Vec3 rotate(const std::array<double, 4>& q, lod::Vec3 v) {
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  const lod::Vec3 t{2.0 * (y * v.z - z * v.y), 2.0 * (z * v.x - x * v.z),
                    2.0 * (x * v.y - y * v.x)};
  return {v.x + w * t.x + (y * t.z - z * t.y), v.y + w * t.y + (z * t.x - x * t.z),
          v.z + w * t.z + (x * t.y - y * t.x)};
}

}  // namespace

lod::Camera eye_camera(const EyeView& eye, lod::Vec3 origin_m, double near_m, double far_m) {
  const lod::Vec3 forward = rotate(eye.pose.orientation, {0.0, 0.0, -1.0});
  const lod::Vec3 p{origin_m.x + eye.pose.position_m[0], origin_m.y + eye.pose.position_m[1],
                    origin_m.z + eye.pose.position_m[2]};
  lod::Camera c;
  c.position_m = p;
  c.target_m = {p.x + forward.x, p.y + forward.y, p.z + forward.z};
  c.up = rotate(eye.pose.orientation, {0.0, 1.0, 0.0});
  c.fov = lod::FovAngles{.left_rad = eye.fov.left_rad,
                         .right_rad = eye.fov.right_rad,
                         .up_rad = eye.fov.up_rad,
                         .down_rad = eye.fov.down_rad};
  c.near_m = near_m;
  c.far_m = far_m;
  return c;
}

lod::Camera head_camera(const std::array<lod::Camera, 2>& eyes) {
  lod::Camera head = eyes[0];
  const lod::Vec3 a = eyes[0].position_m, b = eyes[1].position_m;
  head.position_m = {0.5 * (a.x + b.x), 0.5 * (a.y + b.y), 0.5 * (a.z + b.z)};
  head.target_m = {head.position_m.x + (eyes[0].target_m.x - a.x),
                   head.position_m.y + (eyes[0].target_m.y - a.y),
                   head.position_m.z + (eyes[0].target_m.z - a.z)};
  return head;
}

}  // namespace ocean::xr
