// `ocean xr`: the sea in a headset through OpenXR. The runtime's predicted display time drives
// the simulation time (the picture shows the sea at the moment it is seen); each eye is a mono
// render from the pose xrLocateViews gives for that time, copied into the eye's swapchain image.
// The simulation runs on the ready task runner, woken before xrWaitFrame returns, so that its
// workers are running when the frame's work starts (docs/performance.md, paced frames).
#include "ocean/xr.hpp"

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "ocean/backends.hpp"
#include "ocean/names.hpp"
#include "ocean/render.hpp"
#include "simulation_flags.hpp"
#include "stop_signals.hpp"

namespace ocean::cli {

namespace {

struct XrOptions {
  SimulationFlags sim;
  std::string frames = "0";
  std::string eye_height = "6";
  std::string quality = "high";
  bool validation = false;
  bool json = false;
};

constexpr NumberOption<long long> kXrFrames{
    .flag = "--frames", .accept = Accept::whole_in_range, .lo = 0.0, .hi = 1e9};
constexpr NumberOption<double> kEyeHeight{
    .flag = "--eye-height", .accept = Accept::in_range, .lo = 0.5, .hi = 1e4};

// The eye's camera: the LOCAL space's origin `eye_height_m` above the sea, looking along the
// pose's −Z. The renderer's camera is symmetric and has no roll (lod::Camera): the vertical
// field of view spans the larger of the up and down angles, and a tilted head is drawn level;
// the stereo renderer will take the views' own projections.
lod::Camera eye_camera(const xr::EyeView& eye, double eye_height_m, double aspect) {
  const auto& q = eye.pose.orientation;  // x, y, z, w
  // R(q)·(0, 0, −1): the third column of the rotation matrix, negated.
  const std::array<double, 3> forward = {-2.0 * (q[0] * q[2] + q[3] * q[1]),
                                         -2.0 * (q[1] * q[2] - q[3] * q[0]),
                                         -(1.0 - 2.0 * (q[0] * q[0] + q[1] * q[1]))};
  const lod::Vec3 position{eye.pose.position_m[0], eye.pose.position_m[1] + eye_height_m,
                           eye.pose.position_m[2]};
  lod::Camera camera;
  camera.position_m = position;
  camera.target_m = {position.x + 100.0 * forward[0], position.y + 100.0 * forward[1],
                     position.z + 100.0 * forward[2]};
  camera.fov_y_rad = 2.0 * std::max(std::fabs(eye.fov.up_rad), std::fabs(eye.fov.down_rad));
  camera.aspect = aspect;
  return camera;
}

int run_xr(const XrOptions& o) {
  Result<long long> frames = parse(kXrFrames, o.frames);
  if (!frames.ok()) return report(frames.status());
  Result<double> eye_height = parse(kEyeHeight, o.eye_height);
  if (!eye_height.ok()) return report(eye_height.status());
  SimulationFlags sim_flags = o.sim;
  if (sim_flags.preset_path.empty()) sim_flags.preset_path = "moderate";
  Result<SimulationConfig> config = resolve_config(sim_flags);
  if (!config.ok()) return report(config.status());
  SimulationConfig c = std::move(config).value();
  c.outputs = FrameOutputs::textures();

  // The OpenXR loader prints its own lines on stderr when it finds no runtime; the error below
  // says it in one. XR_LOADER_DEBUG set by the user wins.
  ::setenv("XR_LOADER_DEBUG", "none", 0);
  Result<std::unique_ptr<xr::Session>> made = xr::Session::make({.validation = o.validation});
  if (!made.ok()) return report(made.status());
  xr::Session& session = *made.value();
  auto runner = std::shared_ptr<TaskRunner>(make_ready_runner());
  Result<std::unique_ptr<Simulator>> sim = make_simulator(c, "cpu", runner);
  if (!sim.ok()) return report(sim.status());
  Result<std::unique_ptr<render::Renderer>> renderer = render::Renderer::make(
      session.context(), {.width = session.eye_width(), .height = session.eye_height()});
  if (!renderer.ok()) return report(renderer.status());
  render::Renderer& r = *renderer.value();
  if (Status s = r.configure(c); !s.ok()) return report(s);
  render::View view;
  Result<lod::QualityPreset> quality = lod::parse_preset(o.quality);
  if (!quality.ok()) {
    return report(invalid_argument("--quality = " + excerpt(o.quality) +
                                   " is not a quality: must be " +
                                   name_list(lod::kQualityPresetNames, ", ", " or ")));
  }
  view.quality = lod::quality_preset(quality.value());
  view.shading = render::sky_preset(o.sim.preset_path == "storm" ? "overcast" : "clear").value();
  const double aspect = double(session.eye_width()) / session.eye_height();

  StopSignals stop;
  std::vector<std::int64_t> display_ns;
  std::vector<double> simulation_s;
  bool exit_requested = false;
  while (!session.exiting()) {
    if (Status s = session.poll_events(); !s.ok()) return report(s);
    const bool done = (frames.value() > 0 && display_ns.size() >= std::size_t(frames.value())) ||
                      stop.received() != 0;
    if (done && !exit_requested && session.running()) {
      if (Status s = session.request_exit(); !s.ok()) return report(s);
      exit_requested = true;
      continue;  // the runtime may stop the session at once: poll before another frame
    }
    if (!session.running()) {  // waiting for READY, or for the end after STOPPING
      if (done && !exit_requested) break;  // stopped before the session began: nothing to end
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      continue;
    }
    runner->wake();  // xrWaitFrame returns about a period before display: be ready for it
    Result<xr::FrameState> f = session.begin_frame();
    if (!f.ok()) return report(f.status());
    const xr::FrameState& frame = f.value();
    if (display_ns.empty()) display_ns.reserve(std::size_t(frames.value()));
    // Simulation time is display time: seconds since the first frame's predicted display.
    const double t = display_ns.empty()
                         ? 0.0
                         : double(frame.predicted_display_time_ns - display_ns.front()) * 1e-9;
    if (frame.should_render) {
      sim.value()->step(t);
      if (Status s = r.upload(sim.value()->frame()); !s.ok()) return report(s);
      for (int eye = 0; eye < 2; ++eye) {
        view.camera = eye_camera(frame.views[std::size_t(eye)], eye_height.value(), aspect);
        if (Status s = session.submit_eye(
                eye, [&](VkCommandBuffer cmd) { return r.record(cmd, view); }, r.srgb_image());
            !s.ok())
          return report(s);
      }
    }
    if (Status s = session.end_frame(); !s.ok()) return report(s);
    if (exit_requested) continue;  // frames until the runtime says STOPPING are not counted
    display_ns.push_back(frame.predicted_display_time_ns);
    simulation_s.push_back(t);
  }
  if (o.json) {
    nlohmann::ordered_json out;
    out["runtime"] = session.runtime_name();
    out["eye_width"] = session.eye_width();
    out["eye_height"] = session.eye_height();
    out["frames"] = display_ns.size();
    out["display_times_ns"] = display_ns;
    out["simulation_times_s"] = simulation_s;
    print_json(out);
  } else {
    std::cout << "ocean xr: " << display_ns.size() << " frames on '" << session.runtime_name()
              << "', " << session.eye_width() << "×" << session.eye_height() << " per eye\n";
  }
  return kExitOk;
}

}  // namespace

Command add_xr_command(CLI::App& app) {
  auto options = std::make_shared<XrOptions>();
  CLI::App* cmd = app.add_subcommand(
      "xr", "Show the sea in a headset through the system's OpenXR runtime (XR_RUNTIME_JSON)");
  add_simulation_flags(*cmd, options->sim);
  add_option(*cmd, kXrFrames, options->frames,
             "Frames to show, then end the session (0: until the runtime ends it or Ctrl-C)")
      ->capture_default_str();
  add_option(*cmd, kEyeHeight, options->eye_height,
             "Metres of the headset's LOCAL space origin above the mean sea level")
      ->capture_default_str();
  cmd->add_option("--quality", options->quality,
                  "LOD quality: " + name_list(lod::kQualityPresetNames, ", ", ", "))
      ->capture_default_str();
  cmd->add_flag("--validation", options->validation,
                "OpenXR core validation layer and Vulkan validation layer on");
  cmd->add_flag("--json", options->json,
                "Print the frames' predicted display times and simulation times as JSON");
  return {cmd, [options] { return run_xr(*options); }};
}

}  // namespace ocean::cli
