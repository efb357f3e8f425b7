// ocean/xr.hpp — an OpenXR session for a headset: instance, the HMD system, a Vulkan context on
// the device the runtime renders with (XR_KHR_vulkan_enable), a stereo session with one
// swapchain per eye, and the frame loop's calls (xrWaitFrame, xrBeginFrame, xrLocateViews,
// xrEndFrame), and each located view as the renderer's camera (eye_camera). The library draws
// nothing here: the caller records both eyes in one pass (the renderer's record_stereo()) and
// the session copies each half into its eye's swapchain image, or records each eye (record())
// and the session copies it.
//
// A frame:
//   session->poll_events();                       // begins/ends the session as the runtime says
//   if (session->exiting()) stop; if (!session->running()) idle;
//   FrameState f = session->begin_frame().value(); // waits for the runtime: predicted display time
//   simulate(f.predicted_display_time_ns);         // the time the picture will be seen
//   for eye in 0, 1: session->submit_eye(eye, record(view from f.views[eye]), source image);
//   (or both eyes in one pass: session->submit_stereo(record_stereo(...), source image))
//   session->end_frame();                          // one projection layer, the located views
//
// Contract: make() fails with `io_error` and one line ("XR_RUNTIME_JSON: ...", naming the file
// and kRuntimeManifestMaxBytes) when XR_RUNTIME_JSON names what is not a regular file of at most
// that size, checked before the loader reads it (the loader reads it whole, with no bound of its
// own: /dev/zero or a FIFO would exhaust memory or block); with `unsupported` and one line ("no
// OpenXR runtime: ...") when the loader finds no runtime (XR_RUNTIME_JSON naming no file among
// the cases), the runtime has no HMD or no XR_KHR_vulkan_enable, or the Vulkan device lacks what
// the renderer needs; every other call returns a Status naming the OpenXR call and its XrResult.
// Threading: one thread drives a session and its context's queue. Allocation: make() allocates;
// the per-frame calls do not.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include "ocean/core.hpp"
#include "ocean/lod.hpp"
#include "ocean/task_runner.hpp"
#include "ocean/vk.hpp"

namespace ocean::xr {

struct SessionParams {
  std::string application_name = "ocean";
  /// XR_APILAYER_LUNARG_core_validation (Debian: openxr-layer-corevalidation) and the Vulkan
  /// validation layer; `unsupported` when the OpenXR layer is not installed.
  bool validation = false;
};

/// A pose in the session's LOCAL reference space: metres, right-handed, +Y up, −Z forward
/// (OpenXR's axes, which map onto the ocean's world unchanged: docs/conventions.md),
/// orientation a unit quaternion (x, y, z, w).
struct Pose {
  std::array<double, 4> orientation{0.0, 0.0, 0.0, 1.0};
  std::array<double, 3> position_m{0.0, 0.0, 0.0};
};

/// The angles of an eye's frustum sides from its forward axis, radians (XrFovf: left and down
/// negative when the side lies left of or below the axis).
struct Fov {
  double left_rad = -0.785, right_rad = 0.785, up_rad = 0.785, down_rad = -0.785;
};

struct EyeView {
  Pose pose;
  Fov fov;
};

/// The world camera of a located view (docs/vr.md V.1–V.2): at the pose's position plus
/// `origin_m` (the LOCAL space's origin in the world), looking along the pose's −Z with the
/// pose's +Y as up (the head's roll drawn), and the view's own asymmetric field of view
/// (lod::Camera::fov). Pure arithmetic; precondition: a unit quaternion.
lod::Camera eye_camera(const EyeView& eye, lod::Vec3 origin_m, double near_m, double far_m);
/// The head of one stereo selection: the eyes' mid-point, eye 0's orientation and field of
/// view (the LOD measures distances from its position; the renderer culls by both eyes).
lod::Camera head_camera(const std::array<lod::Camera, 2>& eyes);

struct FrameState {
  std::int64_t predicted_display_time_ns = 0;    ///< XrTime the frame will be displayed at
  std::int64_t predicted_display_period_ns = 0;  ///< the runtime's frame period
  bool should_render = false;      ///< false: skip submit_eye, end_frame submits no layer
  std::array<EyeView, 2> views{};  ///< xrLocateViews at the predicted time: left, right
};

/// The largest runtime manifest (the JSON file XR_RUNTIME_JSON names) make() lets the loader
/// read, bytes (1 MiB): a manifest names a library and a few fields, a few hundred bytes.
inline constexpr std::uint64_t kRuntimeManifestMaxBytes = std::uint64_t{1} << 20;

class Session {
 public:
  /// Instance, system, Vulkan context (graphics, the runtime's extensions), session, LOCAL
  /// space and two swapchains of the recommended eye size in an sRGB RGBA8 format.
  static Result<std::unique_ptr<Session>> make(const SessionParams& params);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  [[nodiscard]] const std::shared_ptr<vk::Context>& context() const;
  [[nodiscard]] int eye_width() const;   ///< pixels, each eye's swapchain image
  [[nodiscard]] int eye_height() const;  ///< pixels
  [[nodiscard]] const std::string& runtime_name() const;

  /// Handles the runtime's events: begins the session when it is READY, ends it when STOPPING.
  Status poll_events();
  /// Frames may be run (the session has begun and is not stopping).
  [[nodiscard]] bool running() const;
  /// The runtime ended the session (EXITING or LOSS_PENDING): leave the frame loop.
  [[nodiscard]] bool exiting() const;
  /// xrWaitFrame (blocks until the runtime wants the next frame), xrBeginFrame, xrLocateViews.
  /// Precondition: running().
  Result<FrameState> begin_frame();
  /// Acquires eye `eye`'s (0 left, 1 right) swapchain image, records `record` into the session's
  /// command buffer followed by a copy of `source` into that image, submits, waits, releases.
  /// `source`: an RGBA8 sRGB image of eye_width() × eye_height() in TRANSFER_SRC_OPTIMAL once
  /// `record` has run (what render::Renderer::record() leaves in srgb_image()).
  Status submit_eye(int eye, FunctionRef<Status(VkCommandBuffer)> record, VkImage source);
  /// Both eyes from one side-by-side picture (the renderer's record_stereo()): acquires both
  /// eyes' images, records `record` followed by copies of the left half of `source` into eye
  /// 0's image and the right half into eye 1's, submits once, waits, releases both. `source`:
  /// RGBA8 sRGB, 2·eye_width() × eye_height(), TRANSFER_SRC_OPTIMAL once `record` has run.
  Status submit_stereo(FunctionRef<Status(VkCommandBuffer)> record, VkImage source);
  /// xrEndFrame at the predicted time: one projection layer with the views begin_frame located,
  /// or no layer when !should_render.
  Status end_frame();
  /// xrRequestExitSession: the runtime will stop the session; keep polling until exiting().
  Status request_exit();

  struct State;  // OpenXR and Vulkan handles (src/xr/state.hpp)

 private:
  Session() = default;
  std::unique_ptr<State> state_;
};

}  // namespace ocean::xr
