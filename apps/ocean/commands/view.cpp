// `ocean view`: the ocean in a window — the renderer's picture blitted into a Vulkan swapchain
// (GLFW), a free camera, and a Dear ImGui panel with every simulation and shading parameter.
// `--frames N --screenshot F.png` runs a fixed number of frames and saves the 3D view, for tests
// and pictures (under xvfb-run on machines without a display).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "ocean/io.hpp"
#include "ocean/scene.hpp"
#include "output_name.hpp"
#include "render_output.hpp"
#include "simulation_flags.hpp"
#include "view/frame_times.hpp"
#include "view/free_camera.hpp"
#include "view/imgui_layer.hpp"
#include "view/interaction.hpp"
#include "view/panel.hpp"
#include "view/presenter.hpp"
#include "view/sea_controls.hpp"
#include "view_flags.hpp"

namespace ocean::cli {

namespace {

// The first frame shows t = 10 s after 4 s of warm-up at 10 Hz, so foam has built up as in a
// running simulation (ocean render does the same with its --time/--warmup defaults).
constexpr double kStartTime_s = 10.0;
constexpr double kWarmup_s = 4.0;
// With --frames, simulated time advances by this much per frame whatever the real frame time,
// so that screenshots are reproducible.
constexpr double kFixedStep_s = 1.0 / 30.0;

constexpr NumberOption<long long> kViewFrames{
    .flag = "--frames", .accept = Accept::whole_in_range, .lo = 0.0, .hi = 1e9};

struct ViewOptions {
  SimulationFlags sim;
  // Interactive defaults: a cheaper mesh and a 256² far-field map (15 ms a frame on two CPU cores
  // against 34 ms at 512², docs/performance.md; the octaves it cannot hold are drawn per pixel).
  ViewFlags picture{.quality = "medium", .far_noise_resolution = "256"};
  std::string frames = "0", screenshot;
  bool boat = false;
  std::string shallows = "none";
  bool camera_given = false;  // --camera or --target on the command line
  bool taa = false;           // --taa
};

struct ViewInputs {
  render::SceneParams scene;
  render::View view;
  int quality = 1;
  long long frames = 0;  // 0: until the window closes
  view::Shallows shallows = view::Shallows::none;
  bool taa_available = false;  // motion vectors can be drawn (uploaded frames, the flat sea)
};

Result<ViewInputs> parse_inputs(const ViewOptions& o) {
  ViewInputs in;
  SimulationFlags sim = o.sim;
  if (sim.preset_path.empty()) sim.preset_path = "moderate";  // as ocean render
  Result<SimulationConfig> config = resolve_config(sim);
  if (!config.ok()) return config.status();
  in.scene.config = std::move(config).value();
  // The renderer uploads the displacement and the RGBA8 chain: no float normals, J or foam.
  in.scene.config.outputs = FrameOutputs::textures();
  in.scene.swapchain = true;
  // The preset's picture settings, under the flags (--far-field-range wins).
  if (Status s = parse_view_flags(o.picture, sim, 64, in.scene, in.view); !s.ok()) return s;
  in.quality = static_cast<int>(lod::parse_preset(o.picture.quality).value());
  Result<long long> frames = parse(kViewFrames, o.frames);
  if (!frames.ok()) return frames.status();
  in.frames = frames.value();
  const std::optional<view::Shallows> shallows = view::parse_shallows(o.shallows);
  if (!shallows)
    return invalid_argument("--shallows = '" + excerpt(o.shallows) +
                            "': must be none, lily-pads, lagoon or beach");
  in.shallows = *shallows;
  const Status taa = check_taa_support(in.scene, in.view);
  in.taa_available = taa.ok();
  if (o.taa && !taa.ok()) return taa;
  if (!o.screenshot.empty()) {
    if (Status s = check_output_name("--screenshot", o.screenshot); !s.ok()) return s;
    if (std::filesystem::path(o.screenshot).extension() != ".png")
      return invalid_argument("--screenshot = '" + excerpt(o.screenshot) +
                              "': the name must end in .png");
  }
  return in;
}

// The mouse as the camera sees it: a right-button drag that did not start over the panel.
struct MouseDrag {
  bool active = false;
  double x = 0.0, y = 0.0;
};

view::CameraInput read_camera_input(GLFWwindow* window, const ImGuiIO& io, MouseDrag& drag) {
  view::CameraInput in;
  const auto down = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS; };
  if (!io.WantCaptureKeyboard) {
    in.forward = down(GLFW_KEY_W) || down(GLFW_KEY_UP);
    in.back = down(GLFW_KEY_S) || down(GLFW_KEY_DOWN);
    in.left = down(GLFW_KEY_A) || down(GLFW_KEY_LEFT);
    in.right = down(GLFW_KEY_D) || down(GLFW_KEY_RIGHT);
    in.down = down(GLFW_KEY_Q);
    in.up = down(GLFW_KEY_E);
    in.fast = down(GLFW_KEY_LEFT_SHIFT) || down(GLFW_KEY_RIGHT_SHIFT);
  }
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window, &x, &y);
  const bool held = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  if (held && !drag.active && !io.WantCaptureMouse) {
    drag.active = true;
  } else if (held && drag.active) {
    in.looking = true;
    in.mouse_dx_px = x - drag.x;
    in.mouse_dy_px = y - drag.y;
  } else if (!held) {
    drag.active = false;
  }
  drag.x = x, drag.y = y;
  return in;
}

// One key's press (not its hold), for toggles.
struct KeyEdge {
  int key;
  bool was_down = false;
  bool pressed(GLFWwindow* window, bool allowed) {
    const bool now = glfwGetKey(window, key) == GLFW_PRESS;
    const bool edge = now && !was_down && allowed;
    was_down = now;
    return edge;
  }
};

Status write_screenshot(render::Renderer& renderer, const std::filesystem::path& path) {
  std::vector<std::uint8_t> rgba;
  if (Status s = renderer.read_srgb(rgba); !s.ok()) return s;
  return write_srgb_png(path, renderer.width(), renderer.height(), rgba);
}

int run_view(const ViewOptions& o) {
  Result<ViewInputs> parsed = parse_inputs(o);
  if (!parsed.ok()) return report(parsed.status());
  ViewInputs in = std::move(parsed).value();
  if (!o.screenshot.empty()) {
    if (Status s = io::check_parent_writable(o.screenshot); !s.ok()) return report(s);
  }

  // --backend cuda without a device: the backend's one line, before any window or file.
  if (Status s = render::Scene::available(in.scene.backend); !s.ok()) return report(s);
  // Declaration order is destruction order in reverse: ImGui, swapchain and surface go before
  // the scene's Vulkan instance, the window and GLFW last.
  Result<std::unique_ptr<view::Window>> window =
      view::Window::open(in.scene.width, in.scene.height, "ocean view");
  if (!window.ok()) return report(window.status());
  GLFWwindow* handle = window.value()->handle();
  window.value()->framebuffer_size(in.scene.width, in.scene.height);
  in.scene.width = std::max(in.scene.width, 1), in.scene.height = std::max(in.scene.height, 1);
  in.scene.instance_extensions = window.value()->instance_extensions();
  Result<std::unique_ptr<render::Scene>> made = render::Scene::make(in.scene);
  if (!made.ok()) return report(made.status());
  render::Scene& scene = *made.value();
  if (!scene.interop().empty()) std::cerr << "ocean: note: " << scene.interop() << "\n";
  render::Renderer& renderer = scene.renderer();
  const vk::Context& ctx = *scene.context();
  if (in.view.debug == render::DebugView::wireframe && !ctx.wireframe)
    return report(unsupported("--view wireframe: Vulkan device '" + ctx.info.name +
                              "' lacks fillModeNonSolid"));
  if (Status s = check_mesh_support(in.view, ctx); !s.ok()) return report(s);
  Result<std::unique_ptr<view::Presenter>> presenter_made =
      view::Presenter::make(scene.context(), *window.value());
  if (!presenter_made.ok()) return report(presenter_made.status());
  view::Presenter& presenter = *presenter_made.value();
  Result<std::unique_ptr<view::ImGuiLayer>> imgui_made = view::ImGuiLayer::make(
      scene.context(), handle, presenter.render_pass(), presenter.min_image_count(),
      presenter.image_count(), /*srgb_target=*/true);
  if (!imgui_made.ok()) return report(imgui_made.status());
  view::ImGuiLayer& imgui = *imgui_made.value();

  // The boat circles, and the shallows lie, about the point the camera first looks at; with no
  // --camera or --target the view starts framed on them.
  const std::array<double, 2> scene_centre{in.view.camera.target_m.x, in.view.camera.target_m.z};
  const double scene_radius = view::scene_radius_m({.on = o.boat}, in.shallows);
  if (!o.camera_given && scene_radius > 0.0 && !in.view.sphere.enabled) {
    const lod::Camera& c = in.view.camera;
    const auto [eye, target] = view::framing_camera(
        scene_centre, scene_radius, {c.target_m.x - c.position_m.x, c.target_m.z - c.position_m.z},
        c.fov_y_rad, c.aspect);
    in.view.camera.position_m = {eye[0], eye[1], eye[2]};
    in.view.camera.target_m = {target[0], target[1], target[2]};
  }
  const view::FreeCamera start(in.view.camera.position_m, in.view.camera.target_m);
  view::FreeCamera camera = start;
  SimulationConfig config = in.scene.config;
  view::PanelState panel{.sea = view::sea_controls(config), .quality = in.quality};
  panel.boat.on = o.boat;
  panel.boat.centre_m = scene_centre;
  panel.shallows = static_cast<int>(in.shallows);
  panel.taa = o.taa;
  Result<std::unique_ptr<view::InteractionScene>> interaction_made =
      view::InteractionScene::make(renderer, config);
  if (!interaction_made.ok()) return report(interaction_made.status());
  view::InteractionScene& interaction = *interaction_made.value();
  view::PanelStats stats{.device = ctx.info.name,
                         .backend = in.scene.backend,
                         .wireframe_available = ctx.wireframe,
                         .taa_available = in.taa_available};
  view::FrameTimes times;
  MouseDrag drag;
  KeyEdge f1{GLFW_KEY_F1}, space{GLFW_KEY_SPACE};
  bool show_panel = true;
  std::uint64_t generation = 0;  // the presenter's swapchain the renderer is sized for
  double t = kStartTime_s;
  scene.follow(in.view);  // the far field's map around the camera (R.13b)
  if (Status s = scene.warm_up(t, kWarmup_s); !s.ok()) return report(s);
  if (Status s = interaction.set_boat(panel.boat, t, scene.simulator()); !s.ok()) return report(s);
  if (Status s = interaction.set_shallows(in.shallows, scene_centre, config, renderer); !s.ok())
    return report(s);
  // Temporal anti-aliasing (R.61) follows the motion vectors, drawn while it is on.
  const auto set_taa = [&](bool on) {
    in.view.temporal_aa.enabled = on;
    return renderer.set_motion_vectors(on);
  };
  if (Status s = set_taa(panel.taa); !s.ok()) return report(s);
  long long frame = 0;
  auto last = std::chrono::steady_clock::now();

  while (glfwWindowShouldClose(handle) == GLFW_FALSE && (in.frames == 0 || frame < in.frames)) {
    glfwPollEvents();
    const auto now = std::chrono::steady_clock::now();
    const double dt = std::clamp(std::chrono::duration<double>(now - last).count(), 0.0, 0.25);
    last = now;
    if (frame > 0) times.add(dt * 1000.0);
    int fw = 0, fh = 0;
    window.value()->framebuffer_size(fw, fh);
    if (fw == 0 || fh == 0) {  // minimised: nothing to draw into
      glfwWaitEvents();
      continue;
    }
    // One frame in flight: the renderer's host-visible buffers are free again after this.
    if (Status s = presenter.wait_frame(); !s.ok()) return report(s);
    if (Status s = imgui.status(); !s.ok()) return report(s);
    if (frame > 0) {  // the finished frame's GPU time, into renderer.stats()
      if (Result<double> gpu = renderer.read_gpu_ms(); !gpu.ok()) return report(gpu.status());
    }

    imgui.new_frame();
    const ImGuiIO& io = ImGui::GetIO();
    if (glfwGetKey(handle, GLFW_KEY_ESCAPE) == GLFW_PRESS && !io.WantCaptureKeyboard)
      glfwSetWindowShouldClose(handle, GLFW_TRUE);
    if (f1.pressed(handle, true)) show_panel = !show_panel;
    if (space.pressed(handle, !io.WantCaptureKeyboard)) panel.paused = !panel.paused;
    camera.update(read_camera_input(handle, io, drag), dt);
    stats.frame_ms = times.median_ms();
    stats.sim_time_s = t;
    stats.render = renderer.stats();
    stats.camera = camera.position();
    stats.width = renderer.width(), stats.height = renderer.height();
    view::PanelActions actions;
    if (show_panel) actions = view::draw_panel(panel, in.view, stats);
    ImGui::Render();
    if (actions.quit) glfwSetWindowShouldClose(handle, GLFW_TRUE);
    if (actions.reset_camera) camera = start;
    if (actions.sea_changed) {
      // A new spectrum: on lavapipe this takes a moment. A configuration the simulation
      // rejects leaves the previous one running and the message in the panel.
      Result<SimulationConfig> next = view::to_config(panel.sea, config);
      Status s = next.ok() ? scene.reconfigure(next.value()) : next.status();
      if (s.ok()) {
        config = next.value();
        panel.error.clear();
      } else {
        panel.error = s.message();
        if (next.ok()) {
          if (Status back = scene.reconfigure(config); !back.ok()) return report(back);
        }
      }
    }

    if (actions.taa_changed) {
      if (Status s = set_taa(panel.taa); !s.ok()) return report(s);
    }
    if (actions.boat_changed) {
      if (Status s = interaction.set_boat(panel.boat, t, scene.simulator()); !s.ok())
        return report(s);
    }
    if (actions.shallows_changed || (actions.sea_changed && panel.error.empty())) {
      // The damping's bands follow the cascades: a new sea needs them again.
      const auto scene_kind = static_cast<view::Shallows>(panel.shallows);
      if (Status s = interaction.set_shallows(scene_kind, scene_centre, config, renderer); !s.ok())
        return report(s);
    }

    if (!panel.paused) t += (in.frames > 0 ? kFixedStep_s : dt) * panel.time_scale;
    scene.follow(in.view);
    if (Status s = scene.step(t); !s.ok()) return report(s);
    if (Status s = interaction.update(t, scene.simulator(), in.view); !s.ok()) return report(s);
    // A new mesh density uploads through the renderer's own command buffer: before ours.
    if (actions.quality_changed) {
      if (Status s = renderer.prepare(in.view); !s.ok()) return report(s);
    }
    Result<bool> acquired = presenter.acquire();
    if (!acquired.ok()) return report(acquired.status());
    if (presenter.generation() != generation) {
      const VkExtent2D e = presenter.extent();
      if (static_cast<int>(e.width) != renderer.width() ||
          static_cast<int>(e.height) != renderer.height()) {
        if (Status s = renderer.resize(static_cast<int>(e.width), static_cast<int>(e.height));
            !s.ok())
          return report(s);
      }
      imgui.set_min_image_count(presenter.min_image_count());
      generation = presenter.generation();
    }
    if (!acquired.value()) continue;  // rebuilt: draw the next frame at the new size
    in.view.camera = camera.camera(in.view.camera.fov_y_rad,
                                   static_cast<double>(renderer.width()) / renderer.height());

    Result<VkCommandBuffer> cmd = presenter.begin();
    if (!cmd.ok()) return report(cmd.status());
    if (Status s = renderer.record(cmd.value(), in.view); !s.ok()) return report(s);
    presenter.blit_and_begin_overlay(cmd.value(), renderer.srgb_image(), renderer.width(),
                                     renderer.height());
    imgui.record(cmd.value());
    if (Status s = presenter.end_overlay(cmd.value()); !s.ok()) return report(s);
    if (Status s = presenter.submit_and_present(); !s.ok()) return report(s);
    ++frame;
  }
  if (Status s = presenter.wait_frame(); !s.ok()) return report(s);

  if (!o.screenshot.empty()) {
    if (frame == 0)
      return report(Status(ErrorCode::internal, "--screenshot: the window closed before a frame"));
    if (Status s = write_screenshot(renderer, o.screenshot); !s.ok()) return report(s);
    std::cout << "wrote " << o.screenshot << " (" << renderer.width() << "x" << renderer.height()
              << ", 3D view after " << frame << " frame" << (frame == 1 ? "" : "s") << ") on "
              << ctx.info.name << "\n";
  }
  if (Status s = validation_status(ctx); !s.ok()) return report(s);
  return kExitOk;
}

}  // namespace

Command add_view_command(CLI::App& app) {
  auto o = std::make_shared<ViewOptions>();
  CLI::App* command = app.add_subcommand(
      "view", "the ocean in a window: free camera and a panel with every parameter");
  add_simulation_flags(*command, o->sim);
  add_view_flags(*command, o->picture, "window");
  add_option(*command, kViewFrames, o->frames,
             "draw N frames then exit (simulated time advances 1/30 s per frame); "
             "default 0: until the window is closed");
  command->add_option("--screenshot", o->screenshot,
                      "after the last frame, save the 3D view (without the panel) as this PNG");
  command->add_flag("--boat", o->boat,
                    "start with a floating boat driven round the --target point by its "
                    "propulsion, leaving a Kelvin wake from its track "
                    "(panel: Boat and shallows)");
  command->add_option("--shallows", o->shallows,
                      "none, lily-pads (a damping mask) or lagoon (a bathymetry), about the "
                      "--target point; default none. With --boat or --shallows and no --camera "
                      "or --target the view starts framed on them, looking down 25 degrees");
  command->add_flag("--taa", o->taa,
                    "start with temporal anti-aliasing (docs/rendering.md R.61; panel: View): "
                    "each frame jittered and blended into the last along the motion vectors. Not "
                    "with --backend vulkan, --sphere or --mesh tessellation");
  return {command, [o, command] {
            o->camera_given = command->count("--camera") + command->count("--target") > 0;
            return run_view(*o);
          }};
}

}  // namespace ocean::cli
