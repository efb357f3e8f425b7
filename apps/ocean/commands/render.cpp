// `ocean render`: a picture (PNG, or linear HDR EXR), an image sequence or an MP4 (through the
// ffmpeg program) of a sea state from a camera, headless on any Vulkan device (lavapipe
// included). With no arguments it writes ocean.png: the moderate sea at eye level towards a
// low sun. The output name is data (output_name.hpp): never a printf format, never a shell word.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <span>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "contact_sheet.hpp"
#include "motion_output.hpp"
#include "object_flags.hpp"
#include "ocean/io.hpp"
#include "ocean/scene.hpp"
#include "output_name.hpp"
#include "progress.hpp"
#include "render_output.hpp"
#include "simulation_flags.hpp"
#include "stereo_flags.hpp"
#include "stop_signals.hpp"
#include "video_writer.hpp"
#include "view_flags.hpp"
#include "wave_flags.hpp"

namespace ocean::cli {

namespace {

struct RenderOptions {
  SimulationFlags sim;
  std::string out = "ocean.png";
  ViewFlags picture;
  std::string time = "20", frames = "1", fps = "30", warmup = "4";
  std::string sun_elevation, sun_azimuth, exposure, sky;
  std::string contact_sheet;
  std::vector<std::string> objects;  // --object, repeatable
  bool floating = false;             // --float
  std::string seabed;                // --seabed DEPTH_M
  WaveFlags waves;
  StereoFlags stereo;
  std::string motion_vectors;  // --motion-vectors FILE.png
  std::string supersample = "1";
  bool taa = false;  // --taa
  bool json = false;
};

constexpr NumberOption<double> kSunElevation{
    .flag = "--sun-elevation", .accept = Accept::in_range, .lo = -10.0, .hi = 90.0};
constexpr NumberOption<double> kSunAzimuth{
    .flag = "--sun-azimuth", .accept = Accept::in_range, .lo = -360.0, .hi = 360.0};
constexpr NumberOption<double> kExposure{
    .flag = "--exposure", .accept = Accept::in_range, .lo = 1e-3, .hi = 1e3};
constexpr NumberOption<double> kTime{
    .flag = "--time", .accept = Accept::in_range, .lo = 0.0, .hi = 1e9};
constexpr NumberOption<long long> kFrames{
    .flag = "--frames", .accept = Accept::whole_in_range, .lo = 1.0, .hi = 1e6};
constexpr NumberOption<double> kFps{
    .flag = "--fps", .accept = Accept::in_range, .lo = 1e-3, .hi = 1000.0};
constexpr NumberOption<double> kSeabed{
    .flag = "--seabed", .accept = Accept::in_range, .lo = 1e-3, .hi = 1e4, .unit = "m"};
constexpr NumberOption<int> kSupersample{.flag = "--supersample",
                                         .accept = Accept::integer_in_range,
                                         .lo = 1.0,
                                         .hi = render::kMaxSupersample};
constexpr NumberOption<double> kWarmup{
    .flag = "--warmup", .accept = Accept::in_range, .lo = 0.0, .hi = 600.0};

enum class OutputKind { png, exr, mp4 };

// Cells per side of the damping grid the renderer samples (docs/rendering.md R.24).
constexpr int kDampingResolution = 512;

struct Inputs {
  std::optional<waves::LayerParams> layer;        // wakes and waveforms, or none
  std::shared_ptr<const waves::Damping> damping;  // mask and bathymetry, or null
  bool calm = false;                              // only the layer, no sea
  render::SceneParams scene;
  render::View view;
  OutputPattern out;  // --out, read by the output-name rule
  OutputKind kind = OutputKind::png;
  double time_s = 0.0, fps = 30.0, warmup_s = 0.0;
  long long frames = 1;
  std::vector<ObjectSpec> objects;
  std::optional<double> ipd;  // --stereo: both eyes side by side, this far apart
  int supersample = 1;        // the picture is drawn this many times wider and taller (R.60)
  bool taa = false;           // temporal anti-aliasing (R.61)
};

// --taa: the first frame is the mean of this many jittered draws at its time; later frames blend
// into it with View::TemporalAntiAliasing's default weight.
constexpr int kTaaStillSamples = 16;

Result<Inputs> parse_inputs(const RenderOptions& o) {
  Inputs in;
  SimulationFlags sim = o.sim;
  if (sim.preset_path.empty()) sim.preset_path = "moderate";  // the picture of `./dev main`
  Result<SimulationConfig> config = resolve_config(sim);
  if (!config.ok()) return config.status();
  in.scene.config = std::move(config).value();
  // The renderer uploads the displacement and the RGBA8 chain: no float normals, J or foam.
  in.scene.config.outputs = FrameOutputs::textures();
  Result<double> t = parse(kTime, o.time);
  if (!t.ok()) return t.status();
  in.time_s = t.value();
  // The local layer: wakes and waveforms drawn over the sea (docs/rendering.md R.19). Without
  // --local-area, layer_params names one that holds the wakes at the first frame's time (W.19).
  in.calm = o.waves.calm;
  if (in.calm && o.waves.local_area.empty() && o.waves.wakes.empty() && o.waves.waveforms.empty())
    return invalid_argument("--calm draws only the local layer: give --local-area X0,Z0,SIZE_M");
  if (in.calm) {  // the sea is not drawn: simulate the smallest one
    in.scene.config.resolution = 16;
    in.scene.config.cascade_patch_sizes_m.resize(1);
  }
  Result<std::shared_ptr<const waves::Damping>> damping = make_damping(o.waves, in.scene.config);
  if (!damping.ok()) return damping.status();
  in.damping = damping.value();
  Result<std::optional<waves::LayerParams>> layer =
      layer_params(o.waves, in.scene.config.choppiness, in.time_s);
  if (!layer.ok()) return layer.status();
  in.layer = std::move(layer).value();
  if (Status s = add_shore_wave(o.waves, in.scene.config, in.layer); !s.ok()) return s;
  // The preset's picture settings, under the flags (--far-field-range wins).
  if (Status s = parse_view_flags(o.picture, sim, 1, in.scene, in.view); !s.ok()) return s;
  if (in.calm) in.scene.config.far_noise.resolution = 0;  // no sea, no far field
  Result<std::optional<double>> ipd = parse_stereo_flags(o.stereo);
  if (!ipd.ok()) return ipd.status();
  in.ipd = ipd.value();
  if (!o.motion_vectors.empty()) {
    if (in.ipd.has_value())
      return invalid_argument("--motion-vectors draws one view, not --stereo");
    if (std::filesystem::path(o.motion_vectors).extension() != ".png")
      return invalid_argument("--motion-vectors = '" + excerpt(o.motion_vectors) +
                              "': the name must end in .png");
  }
  if (in.ipd.has_value()) {  // each eye is --width wide; the picture holds both
    if (in.scene.width > 8192)
      return invalid_argument("--stereo: --width is at most 8192 (the picture is twice as wide)");
    in.scene.width *= 2;
  }
  Result<int> supersample = parse(kSupersample, o.supersample);
  if (!supersample.ok()) return supersample.status();
  in.supersample = supersample.value();
  if (in.supersample > 1) {
    if (!o.motion_vectors.empty())
      return invalid_argument("--motion-vectors are of the picture as drawn, not --supersample");
    const long long drawn_w = static_cast<long long>(in.scene.width) * in.supersample;
    const long long drawn_h = static_cast<long long>(in.scene.height) * in.supersample;
    if (drawn_w > 16384 || drawn_h > 16384)
      return invalid_argument("--supersample " + std::to_string(in.supersample) + " draws " +
                              std::to_string(drawn_w) + " x " + std::to_string(drawn_h) +
                              " pixels: at most 16384 a side (lower --width, --height or the "
                              "factor)");
    in.scene.width = static_cast<int>(drawn_w);
    in.scene.height = static_cast<int>(drawn_h);
  }
  in.taa = o.taa;
  if (in.taa && in.supersample > 1)
    return invalid_argument("--taa or --supersample: one anti-aliasing, not both");
  if (in.taa) {
    if (Status s = check_taa_support(in.scene, in.view); !s.ok()) return s;
  }
  render::View& v = in.view;
  // The sky: named, or by sea state (a storm is overcast), then the explicit sun flags.
  std::string sky = o.sky;
  if (sky.empty()) sky = o.sim.preset_path == "storm" ? "overcast" : "clear";
  Result<render::ShadingParams> shading = render::sky_preset(sky);
  if (!shading.ok())
    return invalid_argument("--sky = " + excerpt(sky) + " is not a sky: must be " +
                            name_list(render::kSkyNames, ", ", " or "));
  v.shading = shading.value();
  if (!o.sun_elevation.empty()) {
    Result<double> e = parse(kSunElevation, o.sun_elevation);
    if (!e.ok()) return e.status();
    v.shading.sun_elevation_deg = e.value();
  }
  if (!o.sun_azimuth.empty()) {
    Result<double> a = parse(kSunAzimuth, o.sun_azimuth);
    if (!a.ok()) return a.status();
    v.shading.sun_azimuth_deg = a.value();
  }
  if (!o.exposure.empty()) {
    Result<double> e = parse(kExposure, o.exposure);
    if (!e.ok()) return e.status();
    v.shading.exposure = e.value();
  }
  Result<long long> frames = parse(kFrames, o.frames);
  if (!frames.ok()) return frames.status();
  in.frames = frames.value();
  Result<double> fps = parse(kFps, o.fps);
  if (!fps.ok()) return fps.status();
  in.fps = fps.value();
  Result<double> warmup = parse(kWarmup, o.warmup);
  if (!warmup.ok()) return warmup.status();
  in.warmup_s = warmup.value();
  for (const std::string& text : o.objects) {
    Result<ObjectSpec> spec = parse_object_spec(text);
    if (!spec.ok()) return spec.status();
    in.objects.push_back(spec.value());
  }
  if (!o.seabed.empty()) {
    Result<double> depth = parse(kSeabed, o.seabed);
    if (!depth.ok()) return depth.status();
    v.seabed = {.enabled = true, .depth_m = depth.value()};
  }
  // The first frame's 16 draws share one time: the motion after them is none.
  if (in.taa && in.frames == 1 && !o.motion_vectors.empty())
    return invalid_argument(
        "--motion-vectors with --taa: the first frame's jittered draws share one time, so its "
        "motion is none; give --frames 2 or more");
  if (o.floating && o.objects.empty())
    return invalid_argument("--float needs at least one --object");
  if (o.floating) {  // the bodies are integrated from t = 0 to the last frame (kMaxFloatTime_s)
    const double last = in.time_s + static_cast<double>(in.frames - 1) / in.fps;
    const std::string bound = "out of range with --float: must be at most " +
                              format_number(kMaxFloatTime_s) +
                              " s (the objects are integrated from t = 0 in 1/60 s steps)";
    if (in.time_s > kMaxFloatTime_s)
      return invalid_argument("--time = " + format_number(in.time_s) + " is " + bound);
    if (last > kMaxFloatTime_s)
      return invalid_argument("--time " + format_number(in.time_s) + " with --frames " +
                              std::to_string(in.frames) + " at --fps " + format_number(in.fps) +
                              " ends at " + format_number(last) + " s, " + bound);
  }
  for (const ObjectSpec& spec : in.objects) {
    if (spec.speed_mps > 0.0 && !o.floating)
      return invalid_argument("--object " + excerpt(spec.kind) +
                              ": a speed drives a floating object; add --float");
  }
  Result<OutputPattern> out = parse_output_pattern(o.out, "--out");
  if (!out.ok()) return out.status();
  in.out = std::move(out).value();
  const std::string ext = std::filesystem::path(in.out.name()).extension().string();
  if (ext == ".png") {
    in.kind = OutputKind::png;
  } else if (ext == ".exr") {
    in.kind = OutputKind::exr;
  } else if (ext == ".mp4") {
    in.kind = OutputKind::mp4;
  } else {
    return invalid_argument("--out = '" + excerpt(o.out) +
                            "': the name must end in .png, .exr or .mp4");
  }
  if (in.kind == OutputKind::mp4 && in.out.numbered)
    return invalid_argument("--out = '" + excerpt(o.out) +
                            "': an MP4 is one file, its name takes no frame-number field (%d "
                            "numbers the files of a PNG or EXR sequence)");
  return in;
}

// The drawn picture averaged down to the written one (render::resolve_supersampled, R.60).
template <class T>
Status resolve(std::vector<T>& pixels, const Inputs& in) {
  if (in.supersample == 1) return {};
  Result<std::vector<T>> r = render::resolve_supersampled(
      std::span<const T>(pixels), in.scene.width, in.scene.height, in.supersample);
  if (!r.ok()) return r.status();
  pixels = std::move(r).value();
  return {};
}

// Frame f's file: a single frame, and an MP4 of any length, is written under the name; a
// sequence's frames are numbered.
std::filesystem::path frame_path(const Inputs& in, long long frame) {
  return in.frames == 1 || in.kind == OutputKind::mp4 ? in.out.name() : in.out.name_for(frame);
}

Status write_hdr_exr(const std::filesystem::path& path, int w, int h,
                     const std::vector<float>& rgba) {
  const std::size_t n = static_cast<std::size_t>(w) * h;
  std::vector<float> planes(3 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t c = 0; c < 3; ++c) planes[c * n + i] = rgba[4 * i + c];
  const io::ExrChannel channels[] = {
      {"R", planes.data()}, {"G", planes.data() + n}, {"B", planes.data() + 2 * n}};
  return io::write_exr(path, w, h, channels, io::ExrPixelType::half);
}

// The contact sheet of the documentation: calm, moderate and storm seas from a low grazing, an
// eye-level and a high view, one labelled tile each.
struct SheetView {
  const char* name;
  std::array<double, 3> eye, target;
};
// Heights are above the crests: the sea's Hs is added to the first two.
constexpr SheetView kSheetViews[] = {{"low grazing (Hs + 1.5 m)", {0, 1.5, 0}, {300, 0.5, 60}},
                                     {"eye level (Hs + 8 m)", {0, 8, 0}, {300, -4, 60}},
                                     {"high (120 m)", {0, 120, 0}, {500, 0, 250}}};
constexpr const char* kSheetSeas[] = {"calm", "moderate", "storm"};

int run_contact_sheet(const RenderOptions& o) {
  if (o.supersample != RenderOptions{}.supersample)
    return report(invalid_argument("--contact-sheet draws its tiles once: no --supersample"));
  if (o.taa) return report(invalid_argument("--contact-sheet draws its tiles once: no --taa"));
  if (Status s = check_output_name("--contact-sheet", o.contact_sheet); !s.ok()) return report(s);
  RenderOptions tile = o;
  if (o.picture.width == ViewFlags{}.width && o.picture.height == ViewFlags{}.height)
    tile.picture.width = "480", tile.picture.height = "270";
  tile.out = "tile.png";
  tile.sim.preset_path = kSheetSeas[0];
  Result<Inputs> first = parse_inputs(tile);
  if (!first.ok()) return report(first.status());
  const int w = first.value().scene.width, h = first.value().scene.height;
  if (Status s = check_picture_memory(w, h, kSheetBytesPerTilePixel, "a contact sheet"); !s.ok())
    return report(s);
  const int cols = 3, rows = 3;
  ContactSheet sheet{.title = "ocean render: calm, moderate, storm", .columns = cols};
  Result<std::unique_ptr<render::Scene>> made = render::Scene::make(first.value().scene);
  if (!made.ok()) return report(made.status());
  render::Scene& scene = *made.value();
  Progress progress("contact sheet", rows * cols);
  std::vector<std::uint8_t> rgba;
  for (int r = 0; r < rows; ++r) {
    tile.sim.preset_path = kSheetSeas[r];
    tile.sky.clear();
    Result<Inputs> in = parse_inputs(tile);
    if (!in.ok()) return report(in.status());
    if (Status s = scene.reconfigure(in.value().scene.config); !s.ok()) return report(s);
    if (Status s = scene.warm_up(in.value().time_s, in.value().warmup_s); !s.ok()) return report(s);
    const double hs = scene.renderer().significant_wave_height_m();
    for (int c = 0; c < cols; ++c) {
      render::View view = in.value().view;
      const SheetView& sv = kSheetViews[c];
      const double lift = c < 2 ? hs : 0.0;
      view.camera.position_m = {sv.eye[0], sv.eye[1] + lift, sv.eye[2]};
      view.camera.target_m = {sv.target[0], sv.target[1] + lift, sv.target[2]};
      if (Status s = scene.renderer().draw(view); !s.ok()) return report(s);
      if (Status s = scene.renderer().read_srgb(rgba); !s.ok()) return report(s);
      char label[160];
      std::snprintf(label, sizeof label, "%s, Hs %.1f m, %s", kSheetSeas[r], hs, sv.name);
      plot::Image picture{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w * h) * 3)};
      for (std::size_t i = 0; i < static_cast<std::size_t>(w * h); ++i) {
        for (std::size_t k = 0; k < 3; ++k) picture.rgb[3 * i + k] = rgba[4 * i + k];
      }
      sheet.tiles.push_back({label, std::move(picture)});
      progress.update(r * cols + c + 1);
    }
  }
  progress.finish();
  const Result<SheetSize> written = write_contact_sheet(sheet, o.contact_sheet);
  if (!written.ok()) return report(written.status());
  std::cout << "wrote " << o.contact_sheet << " (" << written.value().width << "x"
            << written.value().height << ", 9 views on " << scene.context()->info.name << ")\n";
  return kExitOk;
}

// A render that SIGINT, SIGTERM or SIGHUP stopped: one line, exit 128 + the signal. What was
// written stays (the files of a sequence's finished frames, each whole); an MP4's temporary goes
// with its writer.
int report_render_stop(const StopSignals& stop, const Inputs& in, long long frames_written) {
  if (in.kind == OutputKind::mp4 || frames_written == 0)
    return report_interrupted(stop, "render", "nothing written");
  return report_interrupted(
      stop, "render",
      std::to_string(frames_written) + " of " + std::to_string(in.frames) + " frames written");
}

int run_render(const RenderOptions& o) {
  if (!o.contact_sheet.empty() && o.stereo.stereo)
    return report(invalid_argument("--stereo draws one view, not a --contact-sheet"));
  if (!o.contact_sheet.empty()) return run_contact_sheet(o);
  Result<Inputs> parsed = parse_inputs(o);
  if (!parsed.ok()) return report(parsed.status());
  const Inputs& in = parsed.value();
  // --backend cuda without a device: the backend's one line, before any window or file.
  if (Status s = render::Scene::available(in.scene.backend); !s.ok()) return report(s);
  // From here on SIGINT/SIGTERM/SIGHUP stop the render between two frames, or between two steps
  // of the floating bodies, with nothing half-written.
  const StopSignals stop;
  // Fail before any work when the output cannot be written (or ffmpeg cannot be started).
  if (Status s = io::check_parent_writable(frame_path(in, 0)); !s.ok()) return report(s);
  if (!o.motion_vectors.empty()) {
    if (Status s = io::check_parent_writable(o.motion_vectors); !s.ok()) return report(s);
  }
  // ... or when the picture cannot fit in memory.
  // Indexed by OutputKind: png, exr, mp4.
  constexpr std::uint64_t kBytesPerPixel[] = {kPngBytesPerPixel, kExrBytesPerPixel,
                                              kVideoBytesPerPixel};
  constexpr const char* kWhat[] = {"a PNG", "an EXR", "an MP4"};
  const auto kind = static_cast<std::size_t>(in.kind);
  if (Status s =
          check_picture_memory(in.scene.width, in.scene.height, kBytesPerPixel[kind], kWhat[kind]);
      !s.ok())
    return report(s);
  // The picture written; the one drawn is --supersample times wider and taller.
  const int w = in.scene.width / in.supersample, h = in.scene.height / in.supersample;
  VideoWriter video;
  if (in.kind == OutputKind::mp4) {
    if (Status s = video.open(in.out.name(), w, h, in.fps); !s.ok()) return report(s);
  }
  Result<RenderObjects> objects = load_objects(in.objects, o.floating);
  if (!objects.ok()) return report(objects.status());
  // The objects, their wakes and the layer, stepped to each frame's time (ocean/world.hpp).
  Result<std::unique_ptr<world::World>> world_made =
      world::World::make({.objects = std::move(objects.value().objects),
                          .floating = o.floating,
                          .layer = in.layer,
                          .choppiness = in.scene.config.choppiness},
                         in.scene.config);
  if (!world_made.ok()) return report(world_made.status());
  world::World& world = *world_made.value();
  Result<std::unique_ptr<render::Scene>> made = render::Scene::make(in.scene);
  if (!made.ok()) return report(made.status());
  render::Scene& scene = *made.value();
  if (!scene.interop().empty()) std::cerr << "ocean: note: " << scene.interop() << "\n";
  render::Renderer& renderer = scene.renderer();
  if (Status s = check_mesh_support(in.view, *scene.context()); !s.ok()) return report(s);
  if (Status s = renderer.set_meshes(objects.value().meshes); !s.ok()) return report(s);
  if (Status s = check_stereo_device(in.ipd, *scene.context()); !s.ok()) return report(s);
  render::View view = in.view;
  std::vector<std::uint8_t> srgb;
  std::vector<float> hdr;
  Progress progress("render", in.frames);
  renderer.set_calm(in.calm);
  if (in.damping != nullptr) {
    const DampingSamples d = sample_damping(*in.damping, kDampingResolution, render::kDampingBands);
    const Status set = renderer.set_damping({.origin_m = d.origin_m,
                                             .size_m = d.size_m,
                                             .resolution = d.resolution,
                                             .band_weights = d.band_weights,
                                             .depth_m = d.depth_m,
                                             .breaking_fraction = d.breaking_fraction});
    if (!set.ok()) return report(set);
  }
  // The layer composited with the sea by the simulator; each step hands the frame's local
  // surface to the renderer (Scene::step, R.19), its foam accumulated through the warm-up.
  scene.simulator().set_damping(in.damping);
  scene.simulator().set_local_layer(world.local_layer());
  if (world.local_layer() != nullptr) print_warnings(*world.local_layer(), in.time_s);
  scene.follow(view);  // the far field's map around the camera (R.13b)
  for (long long f = 0; f < in.frames; ++f) {
    const double t = in.time_s + static_cast<double>(f) / in.fps;
    // With motion vectors the first frame has one before it, 1/fps earlier (R.26).
    const bool motion = f == 0 && !o.motion_vectors.empty();
    Status stepped =
        f == 0 ? scene.warm_up(motion ? t - 1.0 / in.fps : t, in.warmup_s) : scene.step(t);
    if (stepped.ok() && motion) {
      if (Status s = renderer.set_motion_vectors(true); !s.ok()) return report(s);
      if (Status s = renderer.draw(view); !s.ok()) return report(s);
      stepped = scene.step(t);
    }
    if (!stepped.ok()) return report(stepped);
    // The objects to the frame's time, and the driven objects' wakes from their tracks (W.17):
    // a new layer goes to the simulator, and the frame is simulated again so that its
    // composited surface holds it.
    Result<bool> new_layer = advance_world(world, t, scene.simulator(), stop.flag());
    if (!new_layer.ok()) {
      const Status& s = new_layer.status();
      if (s.code() != ErrorCode::cancelled || stop.received() == 0) return report(s);
      progress.end_line();
      return report_render_stop(stop, in, f);
    }
    place_objects(objects.value(), world, view.objects);
    if (new_layer.value()) {
      if (Status s = scene.step(t); !s.ok()) return report(s);
    }
    if (in.taa && f == 0) {  // the history started from the first frame's jittered draws
      if (Status s = renderer.set_motion_vectors(true); !s.ok()) return report(s);
      view.temporal_aa = {.enabled = true, .current_weight = 1.0 / kTaaStillSamples};
      for (int k = 1; k < kTaaStillSamples; ++k)
        if (Status s =
                in.ipd.has_value() ? renderer.draw_stereo(view, *in.ipd) : renderer.draw(view);
            !s.ok())
          return report(s);
    } else if (in.taa && f == 1) {
      view.temporal_aa.current_weight = render::View::TemporalAntiAliasing{}.current_weight;
    }
    const Status drawn =
        in.ipd.has_value() ? renderer.draw_stereo(view, *in.ipd) : renderer.draw(view);
    if (!drawn.ok()) return report(drawn);
    if (stop.received() != 0) {  // a signal during the frame's work: its file is not begun
      progress.end_line();
      return report_render_stop(stop, in, f);
    }
    const std::filesystem::path path = frame_path(in, f);
    Status written;
    if (in.kind == OutputKind::exr) {
      if (Status s = renderer.read_hdr(hdr); !s.ok()) return report(s);
      if (Status s = resolve(hdr, in); !s.ok()) return report(s);
      written = write_hdr_exr(path, w, h, hdr);
    } else {
      if (Status s = renderer.read_srgb(srgb); !s.ok()) return report(s);
      if (Status s = resolve(srgb, in); !s.ok()) return report(s);
      written = in.kind == OutputKind::png ? write_srgb_png(path, w, h, srgb) : video.write(srgb);
    }
    if (!written.ok()) return report(written);
    if (in.frames > 1) progress.update(f + 1);
  }
  if (in.kind == OutputKind::mp4) {
    if (Status s = video.close(); !s.ok()) return report(s);
  }
  if (!o.motion_vectors.empty()) {  // the last frame's motion
    std::vector<float> xy;
    if (Status s = renderer.read_motion(xy); !s.ok()) return report(s);
    Result<double> scale = write_motion_png(o.motion_vectors, w, h, xy);
    if (!scale.ok()) return report(scale.status());
    if (!o.json)
      std::cout << "wrote " << o.motion_vectors << " (motion; full colour at " << scale.value()
                << " px per frame)\n";
  }
  if (in.frames > 1) progress.finish();
  if (Status s = validation_status(*scene.context()); !s.ok()) return report(s);
  const render::RenderStats& st = renderer.stats();
  if (o.json) {
    nlohmann::ordered_json j = {{"out", o.out},
                                {"width", w},
                                {"height", h},
                                {"supersample", in.supersample},
                                {"frames", in.frames},
                                {"device", scene.context()->info.name},
                                {"backend", in.scene.backend},
                                {"patches", st.patches},
                                {"draw_calls", st.draw_calls},
                                {"triangles", st.triangles},
                                {"lod_select_ms", st.cpu_select_ms},
                                {"gpu_ms", st.gpu_ms}};
    print_json(j);
  } else {
    std::cout << "wrote " << o.out << " (" << w << "x" << h << ", " << in.frames << " frame"
              << (in.frames == 1 ? "" : "s") << ") on " << scene.context()->info.name << ": "
              << st.patches << " patches, " << st.triangles << " triangles, " << st.draw_calls
              << " draws, GPU " << st.gpu_ms << " ms per frame\n";
  }
  return kExitOk;
}

}  // namespace

Command add_render_command(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* command =
      app.add_subcommand("render", "render the ocean to a PNG/EXR image, a sequence or an MP4");
  add_simulation_flags(*command, o->sim);
  add_view_flags(*command, o->picture, "image");
  command->add_option(
      "--out", o->out,
      "output .png (sRGB), .exr (linear HDR) or .mp4 (needs ffmpeg); default ocean.png. A "
      "sequence's PNG/EXR files are numbered name_00000.png, ..., or where the name holds one "
      "frame-number field, %d or %0Nd (N 1..18): shot_%05d.png. %% is a percent sign; any "
      "other % is refused");
  add_option(*command, kTime, o->time,
             "simulated time of the first frame, s (default 20); with --float the last frame's "
             "time is at most " +
                 format_number(kMaxFloatTime_s) + " s");
  add_option(*command, kFrames, o->frames, "number of frames (default 1)");
  add_option(*command, kFps, o->fps, "frames per second of a sequence (default 30)");
  add_option(*command, kWarmup, o->warmup,
             "seconds simulated before the first frame so foam builds up (default 4)");
  add_option(*command, kSunElevation, o->sun_elevation, "sun above the horizon, degrees");
  add_option(*command, kSunAzimuth, o->sun_azimuth, "sun azimuth from +x towards +z, degrees");
  add_option(*command, kExposure, o->exposure, "exposure before tone mapping (default 0.45)");
  command->add_option("--sky", o->sky,
                      name_list(render::kSkyNames, ", ", " or ") +
                          " (default: overcast for --preset storm, else clear); the --sun-* and "
                          "--exposure flags adjust it");
  command->add_option("--contact-sheet", o->contact_sheet,
                      "instead of one picture: a PNG of the calm, moderate and storm presets from "
                      "a low grazing, an eye-level and a high camera (tiles --width x --height, "
                      "default 480x270)");
  command
      ->add_option("--object", o->objects,
                   "KIND,X,Y,Z[,HEADING_DEG[,SPEED_MPS]]: an object in the picture, KIND box, "
                   "buoy, boat or a glTF 2.0 file (.glb/.gltf); X,Y,Z place its origin (m), the "
                   "heading turns it from +x towards +z; with --float a speed (0-30 m/s) drives "
                   "it from t = 0 along that heading by its propulsion, leaving a Kelvin wake "
                   "(in --local-area, or a 320 m square round it). Repeatable")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  command->add_flag("--float", o->floating,
                    "let the objects float: simulate them as rigid bodies on the waves from t = 0 "
                    "to the picture's time, at most " +
                        format_number(kMaxFloatTime_s) +
                        " s (1/60 s steps, the sea every second one: minutes of work; a span of a "
                        "minute or more shows its progress, Ctrl-C stops it) (glTF meshes must be "
                        "closed)");
  add_option(*command, kSeabed, o->seabed,
             "a sandy seabed this far below the sea level, m, seen through clear water "
             "(refraction, absorption of pure water); with --bathymetry at the map's depth "
             "where the map covers it");
  add_wave_flags(*command, o->waves);
  add_stereo_flags(*command, o->stereo);
  add_option(*command, kSupersample, o->supersample,
             "draw the picture N times wider and taller and average each N x N block in linear "
             "light (anti-aliasing; 1-4, default 1: N² times the drawing work)");
  command->add_flag(
      "--taa", o->taa,
      "temporal anti-aliasing (docs/rendering.md R.61): each frame drawn with a sub-pixel "
      "jitter and blended into the last along the motion vectors (weight 0.2); the first frame "
      "is the mean of " +
          std::to_string(kTaaStillSamples) +
          " jittered draws at its time (that many times its drawing work); with --stereo each eye "
          "on its own. Not with --supersample, --sphere, --mesh tessellation or --backend "
          "vulkan");
  command->add_option("--motion-vectors", o->motion_vectors,
                      "also write the last frame's motion vectors (camera and waves, pixels per "
                      "frame) as a PNG: red right, green down, grey still (docs/rendering.md "
                      "R.26)");
  command->add_flag("--json", o->json, "print the statistics as JSON");
  return {command, [o] { return run_render(*o); }};
}

}  // namespace ocean::cli
