// The fly-through camera of `ocean view` (see free_camera.hpp).
#include "view/free_camera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ocean::cli::view {

FreeCamera::FreeCamera(lod::Vec3 eye, lod::Vec3 target, const FreeCameraParams& params)
    : params_(params), position_(eye) {
  const double dx = target.x - eye.x, dy = target.y - eye.y, dz = target.z - eye.z;
  const double horizontal = std::hypot(dx, dz);
  yaw_rad_ = horizontal > 0.0 ? std::atan2(dz, dx) : 0.0;
  pitch_rad_ =
      std::clamp(std::atan2(dy, horizontal), -params_.max_pitch_rad, params_.max_pitch_rad);
  position_.y = std::max(position_.y, params_.min_height_m);
}

lod::Vec3 FreeCamera::forward() const {
  const double c = std::cos(pitch_rad_);
  return {c * std::cos(yaw_rad_), std::sin(pitch_rad_), c * std::sin(yaw_rad_)};
}

void FreeCamera::update(const CameraInput& in, double dt_s) {
  if (in.looking) {
    // Mouse right turns right (yaw towards +z at yaw 0); mouse down looks down.
    yaw_rad_ =
        std::remainder(yaw_rad_ + in.mouse_dx_px * params_.turn_rad_per_px, 2.0 * std::numbers::pi);
    pitch_rad_ = std::clamp(pitch_rad_ - in.mouse_dy_px * params_.turn_rad_per_px,
                            -params_.max_pitch_rad, params_.max_pitch_rad);
  }
  const lod::Vec3 f = forward();
  // right = forward × up, normalised in the horizontal plane (never zero: |pitch| < π/2).
  const lod::Vec3 r{-std::sin(yaw_rad_), 0.0, std::cos(yaw_rad_)};
  const auto axis = [](bool plus, bool minus) { return (plus ? 1.0 : 0.0) - (minus ? 1.0 : 0.0); };
  const double along = axis(in.forward, in.back);
  const double side = axis(in.right, in.left);
  const double vertical = axis(in.up, in.down);
  double mx = along * f.x + side * r.x, my = along * f.y + vertical, mz = along * f.z + side * r.z;
  const double length = std::sqrt(mx * mx + my * my + mz * mz);
  if (length > 0.0) {
    const double step = params_.speed_mps * (in.fast ? params_.fast_factor : 1.0) * dt_s / length;
    mx *= step, my *= step, mz *= step;
    position_.x += mx, position_.y += my, position_.z += mz;
  }
  position_.y = std::max(position_.y, params_.min_height_m);
}

lod::Camera FreeCamera::camera(double fov_y_rad, double aspect, double near_m, double far_m) const {
  const lod::Vec3 f = forward();
  // The target only fixes the direction; 100 m keeps it well away from the eye in float terms.
  return {
      .position_m = position_,
      .target_m = {position_.x + 100.0 * f.x, position_.y + 100.0 * f.y, position_.z + 100.0 * f.z},
      .fov_y_rad = fov_y_rad,
      .aspect = aspect,
      .near_m = near_m,
      .far_m = far_m};
}

}  // namespace ocean::cli::view
