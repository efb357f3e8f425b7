// `ocean bake`: the flags of a bake (frames or one whole loop, formats, times, a shard) turned into
// the library's BakeParams (ocean/bake.hpp, which writes the files and the manifest), a progress
// bar, the first frame's contact sheet (its path checked with the folder, before the first frame),
// and SIGINT/SIGTERM/SIGHUP turned into the bake's cancellation (exit 128 + the signal).
// `--merge DIR...` joins the folders of a sharded bake instead (ocean::bake::merge).
#include "ocean/bake.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <set>

#include "cli_common.hpp"
#include "commands.hpp"
#include "contact_sheet.hpp"
#include "ocean/world.hpp"
#include "output_name.hpp"
#include "progress.hpp"
#include "simulation_flags.hpp"
#include "stop_signals.hpp"
#include "wave_flags.hpp"

namespace ocean::cli {

namespace {

constexpr NumberOption<double> kBakeFps{
    .flag = "--fps", .accept = Accept::in_range, .lo = 1e-3, .hi = 1e4};
constexpr NumberOption<double> kBakeTime{.flag = "--time", .accept = Accept::finite};
constexpr NumberOption<long long> kBakeFrames{.flag = "--frames",
                                              .accept = Accept::integer_in_range,
                                              .lo = 1.0,
                                              .hi = 1e6,
                                              .echo = Echo::text};

struct BakeOptions {
  SimulationFlags sim;
  WaveFlags waves;
  std::string out;
  std::vector<std::string> formats;
  std::string frames, fps = "30", time = "0", backend = "cpu";
  bool loop = false;
  std::string contact_sheet;
  std::string shard;               // "I/N"
  std::vector<std::string> merge;  // shard folders to join into --out
};

// An interrupted bake or merge: the signal named, exit 128 + the signal (the shell's convention
// for a job ended by one); otherwise the usual one-line error.
int report_stop(const Status& s, const StopSignals& stop, std::string_view what) {
  if (s.code() == ErrorCode::cancelled && stop.received() != 0)
    return report_interrupted(stop, what, s.message());
  return report(s);
}

// `ocean bake --merge DIR... --out OUT`: the only other flag it takes is --out.
int run_merge(const BakeOptions& o, const CLI::App& command) {
  for (const CLI::Option* option : command.get_options()) {
    const std::string name = option->get_name();
    if (option->count() > 0 && name != "--merge" && name != "--out") {
      return report(invalid_argument("--merge takes only --out: " + name +
                                     " belongs to a bake, not to a merge"));
    }
  }
  if (o.out.empty()) return report(invalid_argument("--merge needs --out DIR"));
  if (Status s = check_output_name("--out", o.out); !s.ok()) return report(s);
  const std::vector<std::filesystem::path> dirs(o.merge.begin(), o.merge.end());
  const StopSignals stop;
  if (Status s = bake::merge(dirs, {.output_dir = o.out, .cancel = stop.flag()}); !s.ok())
    return report_stop(s, stop, "merge");
  std::cerr << "ocean: merged " << dirs.size() << " shard(s) into " << o.out << "\n";
  return kExitOk;
}

int run_bake(const BakeOptions& o) {
  if (o.out.empty()) return report(invalid_argument("bake needs --out DIR"));
  if (Status s = check_output_name("--out", o.out); !s.ok()) return report(s);
  if (!o.contact_sheet.empty()) {
    if (Status s = check_output_name("--contact-sheet", o.contact_sheet); !s.ok()) return report(s);
  }
  bake::BakeParams params{.output_dir = o.out};
  const std::set<std::string> formats(o.formats.begin(), o.formats.end());
  if (!formats.empty()) params.formats = {.npy = false, .png = false, .exr = false};
  for (const std::string& f : formats) {
    if (f == "npy") {
      params.formats.npy = true;
    } else if (f == "png") {
      params.formats.png = true;
    } else if (f == "exr") {
      params.formats.exr = true;
    } else {
      return report(
          invalid_argument("--format = '" + excerpt(f) + "' is unknown: must be exr, png or npy"));
    }
  }
  Result<SimulationConfig> config = resolve_config(o.sim);
  if (!config.ok()) return report(config.status());
  const SimulationConfig& c = config.value();
  Result<double> fps = parse(kBakeFps, o.fps);
  if (!fps.ok()) return report(fps.status());
  Result<double> start = parse(kBakeTime, o.time);
  if (!start.ok()) return report(start.status());
  long long frames = 1;
  if (o.loop) {
    if (!o.frames.empty()) return report(invalid_argument("give --frames N or --loop, not both"));
    if (!(c.loop_period_s > 0))
      return report(invalid_argument("--loop needs a loop period > 0 (--loop-period)"));
    frames = bake::loop_frame_count(c, fps.value());
    if (frames < 1 || frames > bake::kMaxFrames)
      return report(invalid_argument("--loop at --fps " + excerpt(o.fps) + " gives " +
                                     std::to_string(frames) + " frames: must be 1 to 1000000"));
  } else if (!o.frames.empty()) {
    Result<long long> v = parse(kBakeFrames, o.frames);
    if (!v.ok()) return report(v.status());
    frames = v.value();
  }
  params.frame_count = frames;
  params.fps = fps.value();
  params.start_time_s = start.value();
  if (!o.waves.damping_mask.empty() || !o.waves.bathymetry.empty() || o.waves.shallows != "none") {
    return report(invalid_argument(
        "--damping-mask, --bathymetry and --shallows are not applied by bake: its tiles are "
        "periodic and a "
        "world-space map has no place on them (ocean query applies them)"));
  }
  Result<std::optional<waves::LayerParams>> layer =
      layer_params(o.waves, c.choppiness, params.start_time_s);
  if (!layer.ok()) return report(layer.status());
  // The layer as the world builds it (ocean/world.hpp; a bake has no objects).
  Result<std::unique_ptr<world::World>> world =
      world::World::make({.layer = std::move(layer).value()}, c);
  if (!world.ok()) return report(world.status());
  params.local_layer = world.value()->local_layer();
  params.calm = o.waves.calm;
  if (params.calm && params.local_layer == nullptr)
    return report(invalid_argument("--calm needs --local-area X0,Z0,SIZE_M (the layer to write)"));
  if (params.calm && !o.contact_sheet.empty())
    return report(invalid_argument("--contact-sheet draws the sea's maps: not with --calm"));
  if (params.local_layer != nullptr) print_warnings(*params.local_layer, params.start_time_s);
  bake::FrameRange range{0, frames};
  if (!o.shard.empty()) {
    Result<bake::Shard> shard = bake::parse_shard(o.shard, "--shard");
    if (!shard.ok()) return report(shard.status());
    if (shard.value().count > frames) {
      return report(invalid_argument("--shard " + o.shard + ": " + std::to_string(frames) +
                                     " frame(s) make at most " + std::to_string(frames) +
                                     " shard(s)"));
    }
    params.shard = shard.value();
    range = bake::shard_frames(frames, shard.value());
  }
  if (!o.contact_sheet.empty()) params.other_outputs.emplace_back(o.contact_sheet);
  Progress progress("bake", range.end - range.first);
  const auto on_frame = [&](const bake::FrameDone& done) -> Status {
    if (done.index == range.first && !o.contact_sheet.empty()) {
      char title[200];
      std::snprintf(
          title, sizeof title, "ocean bake: %s, Hs %.2f m, t = %.2f s, %d^2 × %zu cascades",
          std::string(to_string(c.sea.wind_sea.spectrum.model)).c_str(), done.height_png_range_m,
          done.time_s, c.resolution, c.cascade_patch_sizes_m.size());
      const Result<SheetSize> sheet =
          write_contact_sheet(frame_maps_sheet(*done.frame, title), o.contact_sheet);
      if (!sheet.ok()) return sheet.status();
    }
    progress.update(done.index + 1 - range.first);
    if (done.index + 1 == range.end) progress.finish();
    return {};
  };
  // From here on SIGINT/SIGTERM/SIGHUP stop the bake between two files: no temporary is left and
  // the manifest says what was written.
  const StopSignals stop;
  params.cancel = stop.flag();
  if (Status s = bake::bake(c, o.backend, params, on_frame); !s.ok()) {
    progress.end_line();
    return report_stop(s, stop, "bake");
  }
  std::cerr << "ocean: wrote " << range.end - range.first << " frame(s) to " << o.out << "\n";
  return kExitOk;
}

}  // namespace

Command add_bake_command(CLI::App& app) {
  auto o = std::make_shared<BakeOptions>();
  CLI::App* command = app.add_subcommand(
      "bake", "Simulate frames and write displacement/normal/foam maps with mips (npy, png, exr)");
  add_simulation_flags(*command, o->sim);
  add_wave_flags(*command, o->waves);
  command->add_option("--out", o->out, "output directory (created if missing)");
  command->add_option("--format", o->formats, "exr | png | npy (repeatable; default npy)");
  add_option(*command, kBakeFrames, o->frames, "number of frames (default 1)");
  command->add_flag("--loop", o->loop, "one whole loop period of frames at --fps");
  add_option(*command, kBakeFps, o->fps, "frames per second")->capture_default_str();
  add_option(*command, kBakeTime, o->time, "time of the first frame, s")->capture_default_str();
  command->add_option("--backend", o->backend, "simulation backend (see ocean info)")
      ->capture_default_str();
  command->add_option("--contact-sheet", o->contact_sheet,
                      "also draw the first frame's maps to this PNG");
  command->add_option("--shard", o->shard,
                      "I/N: write only block I (0..N-1) of N of the frames, with its own manifest");
  command
      ->add_option("--merge", o->merge,
                   "DIR...: join the folders of shards 0..N-1 into --out (takes only --out)")
      ->expected(1, -1);
  return {command,
          [o, command] { return o->merge.empty() ? run_bake(*o) : run_merge(*o, *command); }};
}

}  // namespace ocean::cli
