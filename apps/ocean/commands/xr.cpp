// `ocean xr`: the sea in a headset through OpenXR. The runtime's predicted display time drives
// the simulation time (the picture shows the sea at the moment it is seen); each eye is drawn
// from the pose and field of view xrLocateViews gives for that time (roll and asymmetric frusta
// included, docs/vr.md V.1–V.2): both eyes in one multiview pass when the device has multiview,
// each half copied into its eye's swapchain image, else one render per eye.
// The simulation runs on the ready task runner, woken before xrWaitFrame returns, so that its
// workers are running when the frame's work starts, and its caches are warmed for the step then
// (Simulator::prepare_step; docs/performance.md, paced frames).
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
  bool no_multiview = false;
  bool taa = false;  // temporal anti-aliasing per eye (R.61)
  bool json = false;
};

constexpr NumberOption<long long> kXrFrames{
    .flag = "--frames", .accept = Accept::whole_in_range, .lo = 0.0, .hi = 1e9};
constexpr NumberOption<double> kEyeHeight{
    .flag = "--eye-height", .accept = Accept::in_range, .lo = 0.5, .hi = 1e4};

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
  // Both eyes side by side in one multiview pass (R.25), or one render per eye.
  const bool one_pass = session.context()->multiview && !o.no_multiview;
  // One renderer draws both eyes: its history holds both side by side, which the one-pass
  // frame keeps apart and a render per eye would overwrite.
  if (o.taa && o.no_multiview)
    return report(
        invalid_argument("--taa: draws both eyes in one multiview pass, not with --no-multiview"));
  if (o.taa && !one_pass)
    return report(
        unsupported("--taa: needs both eyes in one multiview pass, and the Vulkan device '" +
                    session.context()->info.name + "' lacks multiview"));
  Result<std::unique_ptr<render::Renderer>> renderer = render::Renderer::make(
      session.context(),
      {.width = (one_pass ? 2 : 1) * session.eye_width(), .height = session.eye_height()});
  if (!renderer.ok()) return report(renderer.status());
  render::Renderer& r = *renderer.value();
  if (Status s = r.configure(sim.value()->plan().surface()); !s.ok()) return report(s);
  if (o.taa)
    if (Status s = r.set_motion_vectors(true); !s.ok()) return report(s);
  render::View view;
  view.temporal_aa.enabled = o.taa;
  Result<lod::QualityPreset> quality = lod::parse_preset(o.quality);
  if (!quality.ok()) {
    return report(invalid_argument("--quality = " + excerpt(o.quality) +
                                   " is not a quality: must be " +
                                   name_list(lod::kQualityPresetNames, ", ", " or ")));
  }
  view.quality = lod::quality_preset(quality.value());
  view.shading = render::sky_preset(o.sim.preset_path == "storm" ? "overcast" : "clear").value();
  // The LOCAL space's origin `--eye-height` metres above the mean sea level.
  const lod::Vec3 origin{0.0, eye_height.value(), 0.0};
  const lod::Camera defaults;

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
    if (!session.running()) {              // waiting for READY, or for the end after STOPPING
      if (done && !exit_requested) break;  // stopped before the session began: nothing to end
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      continue;
    }
    // xrWaitFrame returns about a period before display: wake the workers and warm the caches
    // for the step that follows it.
    sim.value()->prepare_step();
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
      std::array<lod::Camera, 2> eyes;
      for (std::size_t e = 0; e < 2; ++e)
        eyes[e] = xr::eye_camera(frame.views[e], origin, defaults.near_m, defaults.far_m);
      if (one_pass) {
        view.camera = xr::head_camera(eyes);
        if (Status s = session.submit_stereo(
                [&](VkCommandBuffer cmd) { return r.record_stereo(cmd, view, eyes); },
                r.srgb_image());
            !s.ok())
          return report(s);
      } else {
        for (int eye = 0; eye < 2; ++eye) {
          view.camera = eyes[std::size_t(eye)];
          if (Status s = session.submit_eye(
                  eye, [&](VkCommandBuffer cmd) { return r.record(cmd, view); }, r.srgb_image());
              !s.ok())
            return report(s);
        }
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
    out["multiview"] = one_pass;
    out["frames"] = display_ns.size();
    out["display_times_ns"] = display_ns;
    out["simulation_times_s"] = simulation_s;
    print_json(out);
  } else {
    std::cout << "ocean xr: " << display_ns.size() << " frames on '" << session.runtime_name()
              << "', " << session.eye_width() << "×" << session.eye_height() << " per eye, "
              << (one_pass ? "both eyes in one multiview pass" : "one render per eye") << "\n";
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
  cmd->add_flag("--no-multiview", options->no_multiview,
                "Render the eyes one after the other even when the device has multiview");
  cmd->add_flag("--taa", options->taa,
                "Temporal anti-aliasing per eye (docs/rendering.md R.61): each frame jittered "
                "and blended into the eye's history along its motion vectors; needs multiview");
  cmd->add_flag(
      "--json", options->json,
      "Print the frames' predicted display times and simulation times, and whether both eyes "
      "were drawn in one multiview pass, as JSON");
  return {cmd, [options] { return run_xr(*options); }};
}

}  // namespace ocean::cli
