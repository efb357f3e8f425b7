// view/free_camera.hpp — the fly-through camera of `ocean view`: a position and a yaw/pitch
// heading, moved by keys and turned by mouse drags. Plain data in, plain data out: the window
// code reads GLFW into CameraInput, the renderer gets a lod::Camera.
//
// Conventions (docs/conventions.md): world Y up, metres. Yaw is measured from +x towards +z
// (like the sun's azimuth), pitch above the horizontal. The view's right is forward × up, so
// at yaw 0 (looking along +x) right is +z.
#pragma once

#include "ocean/lod.hpp"

namespace ocean::cli::view {

/// One frame's input. Movement keys are held states; mouse deltas are pixels since last frame
/// (x right, y down, as windows report them).
struct CameraInput {
  bool forward = false, back = false;  ///< W / S, up / down arrows
  bool left = false, right = false;    ///< A / D, left / right arrows
  bool down = false, up = false;       ///< Q / E: along world Y
  bool fast = false;                   ///< Shift: speed × fast_factor
  bool looking = false;                ///< right mouse button held: mouse deltas turn the view
  double mouse_dx_px = 0.0, mouse_dy_px = 0.0;
};

struct FreeCameraParams {
  double speed_mps = 15.0;          ///< movement speed without Shift
  double fast_factor = 6.0;         ///< Shift multiplies the speed
  double turn_rad_per_px = 0.0035;  ///< mouse sensitivity
  /// The eye never goes below this height above y = 0: it may dive under the sea and see the
  /// waves from below (docs/rendering.md R.50), as deep as `ocean render --camera` allows.
  double min_height_m = -1000.0;
  double max_pitch_rad = 1.55;  ///< |pitch| limit, just under π/2 (no flip at the pole)
};

class FreeCamera {
 public:
  /// A camera at `eye` looking towards `target` (eye ≠ target); the eye is lifted to
  /// min_height_m when it is lower.
  FreeCamera(lod::Vec3 eye, lod::Vec3 target, const FreeCameraParams& params = {});

  /// Moves and turns by one frame of `input` lasting dt_s seconds (dt_s ≥ 0). Allocates nothing.
  void update(const CameraInput& input, double dt_s);

  /// The renderer's camera: this eye and heading with the given lens.
  [[nodiscard]] lod::Camera camera(double fov_y_rad, double aspect, double near_m = 0.2,
                                   double far_m = 2.0e5) const;

  /// Unit view direction.
  [[nodiscard]] lod::Vec3 forward() const;
  [[nodiscard]] lod::Vec3 position() const { return position_; }
  [[nodiscard]] double yaw_rad() const { return yaw_rad_; }
  [[nodiscard]] double pitch_rad() const { return pitch_rad_; }
  [[nodiscard]] const FreeCameraParams& params() const { return params_; }

 private:
  FreeCameraParams params_;
  lod::Vec3 position_;
  double yaw_rad_ = 0.0, pitch_rad_ = 0.0;
};

}  // namespace ocean::cli::view
