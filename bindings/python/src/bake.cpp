// ocean.bake, ocean.merge, ocean.shard_frames and ocean.surface_stats: ocean/bake.hpp and
// ocean/statistics.hpp with the GIL released while they run, their arguments checked as
// `ocean bake` and `ocean stats` check their flags; bake and merge stop on SIGINT, SIGTERM and
// SIGHUP (signals.hpp).
#include "ocean/bake.hpp"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <atomic>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "errors.hpp"
#include "integers.hpp"
#include "ocean/parameters.hpp"
#include "ocean/statistics.hpp"
#include "ocean/task_runner.hpp"
#include "signals.hpp"

namespace py = pybind11;

namespace ocean::python {
namespace {

// Runs `work` without the GIL and raises its status with the GIL again.
template <class F>
void without_gil(F&& work) {
  Status s;
  {
    const py::gil_scoped_release release;
    s = work();
  }
  check(s);
}

// Runs `work(cancel)` without the GIL, `cancel` set by SIGINT, SIGTERM or SIGHUP when called
// from the main thread, and raises as StopOnSignals::finish does with the GIL again.
template <class F>
void interruptible(std::string_view what, F&& work) {
  StopOnSignals stop;
  Status s;
  {
    const py::gil_scoped_release release;
    s = work(stop.flag());
  }
  stop.finish(s, what);
}

bake::Formats parse_formats(const std::vector<std::string>& names) {
  if (names.empty()) raise(invalid_argument("formats must name at least one of exr, png or npy"));
  bake::Formats f{.npy = false, .png = false, .exr = false};
  for (const std::string& name : names) {
    if (name == "npy") {
      f.npy = true;
    } else if (name == "png") {
      f.png = true;
    } else if (name == "exr") {
      f.exr = true;
    } else {
      raise(invalid_argument("formats: '" + excerpt(name) +
                             "' is unknown: must be exr, png or npy"));
    }
  }
  return f;
}

void bake_frames(const py::object& preset, const std::filesystem::path& out,
                 const Integer& frame_arg, double fps, double time_s,
                 const std::vector<std::string>& formats, const std::string& backend,
                 const std::optional<std::string>& shard) {
  constexpr params::NumberOption<double> kFps{
      .flag = "--fps", .accept = params::Accept::in_range, .lo = 1e-3, .hi = 1e4};
  constexpr params::NumberOption<double> kTime{.flag = "--time", .accept = params::Accept::finite};
  constexpr params::NumberOption<double> kFrames{
      .flag = "--frames", .lo = 1.0, .hi = static_cast<double>(bake::kMaxFrames)};
  if (out.empty()) raise(invalid_argument("bake needs --out DIR"));
  bake::BakeParams params{.output_dir = out, .formats = parse_formats(formats)};
  const SimulationConfig config = config_of(preset);
  check(params::check(kFps, fps, format_number(fps)));
  check(params::check(kTime, time_s, format_number(time_s)));
  const long long frames = in_range(frame_arg, kFrames);
  params.frame_count = frames;
  params.fps = fps;
  params.start_time_s = time_s;
  if (shard) {
    const bake::Shard s = take(bake::parse_shard(*shard, "--shard"));
    if (s.count > frames) {
      raise(invalid_argument("--shard " + excerpt(*shard) + ": " + std::to_string(frames) +
                             " frame(s) make at most " + std::to_string(frames) + " shard(s)"));
    }
    params.shard = s;
  }
  interruptible("bake", [&](const std::atomic<bool>* cancel) {
    params.cancel = cancel;
    return bake::bake(config, backend, params);
  });
}

py::dict stats_dict(const SurfaceStats& s) {
  // The fields by name, as `ocean stats --json` names them; the optional ones None when unset.
  static constexpr std::pair<const char*, double SurfaceStats::*> kNumbers[] = {
      {"patch_size_m", &SurfaceStats::patch_size_m},
      {"time_s", &SurfaceStats::time_s},
      {"hs_measured_m", &SurfaceStats::hs_measured_m},
      {"hs_spectrum_m", &SurfaceStats::hs_spectrum_m},
      {"hs_closed_form_m", &SurfaceStats::hs_closed_form_m},
      {"resolved_variance_fraction", &SurfaceStats::resolved_variance_fraction},
      {"independent_wave_vectors", &SurfaceStats::independent_wave_vectors},
      {"hs_sampling_rel_std", &SurfaceStats::hs_sampling_rel_std},
      {"mean_height_m", &SurfaceStats::mean_height_m},
      {"mean_square_slope", &SurfaceStats::mean_square_slope},
      {"folded_fraction", &SurfaceStats::folded_fraction},
      {"min_jacobian", &SurfaceStats::min_jacobian},
      {"foam_coverage", &SurfaceStats::foam_coverage},
      {"mean_foam", &SurfaceStats::mean_foam},
      {"whitecap_coverage", &SurfaceStats::whitecap_coverage}};
  static constexpr std::pair<const char*, std::optional<double> SurfaceStats::*> kOptionals[] = {
      {"height_skewness", &SurfaceStats::height_skewness},
      {"height_kurtosis", &SurfaceStats::height_kurtosis},
      {"cox_munk_mss", &SurfaceStats::cox_munk_mss},
      {"monahan_whitecap_coverage", &SurfaceStats::monahan_whitecap_coverage},
      {"max_imaginary_rel_hs", &SurfaceStats::max_imaginary_rel_hs},
      {"loop_error_rel_hs", &SurfaceStats::loop_error_rel_hs}};
  py::dict d;
  d["resolution"] = s.resolution;
  d["cascades"] = s.cascades;
  d["seeds"] = s.seeds;
  d["model"] = s.model;
  for (const auto& [name, field] : kNumbers) d[name] = s.*field;
  d["resolved_mss_upwind"] = s.resolved_slope_variance.upwind;
  d["resolved_mss_crosswind"] = s.resolved_slope_variance.crosswind;
  const auto component = [](const std::optional<SlopeVariance>& v, double SlopeVariance::*field) {
    return v ? py::object(py::float_((*v).*field)) : py::none();
  };
  d["unresolved_mss_upwind"] = component(s.unresolved_slope_variance, &SlopeVariance::upwind);
  d["unresolved_mss_crosswind"] = component(s.unresolved_slope_variance, &SlopeVariance::crosswind);
  d["total_mss"] = s.unresolved_slope_variance
                       ? py::object(py::float_(s.resolved_slope_variance.total() +
                                               s.unresolved_slope_variance->total()))
                       : py::none();
  d["cox_munk_mss_upwind"] = component(s.cox_munk_slope_variance, &SlopeVariance::upwind);
  d["cox_munk_mss_crosswind"] = component(s.cox_munk_slope_variance, &SlopeVariance::crosswind);
  for (const auto& [name, field] : kOptionals)
    d[name] = (s.*field).has_value() ? py::object(py::float_(*(s.*field))) : py::none();
  return d;
}

}  // namespace

void bind_bake(py::module_& m) {
  m.def("bake", &bake_frames, py::arg("preset"), py::arg("out"), py::kw_only(),
        py::arg("frames") = 1, py::arg("fps") = 30.0, py::arg("time") = 0.0,
        py::arg("formats") = std::vector<std::string>{"npy"}, py::arg("backend") = "cpu",
        py::arg("shard") = py::none(),
        R"doc(Bakes frames of the preset's simulation into a folder, as `ocean bake` does.

The GIL is released while it runs; Ctrl-C stops it between files with nothing half-written.

Parameters
----------
preset : Preset, str or None
    An ocean.Preset, a built-in name or a preset file; None: the defaults.
out : str or os.PathLike
    The folder: files and manifest.json (src/bake/README.md).
frames : int, optional
    Frames to bake, 1 to 1000000.
fps : float, optional
    Frames per second.
time : float, optional
    Time of the first frame, s.
formats : list of str, optional
    Any of 'npy', 'png', 'exr'.
backend : str, optional
    'cpu' or 'vulkan'.
shard : str, optional
    'I/N': only shard I of N, for ocean.merge.)doc");
  m.def(
      "merge",
      [](const std::vector<std::filesystem::path>& shards, const std::filesystem::path& out) {
        if (out.empty()) raise(invalid_argument("merge needs an output folder (out)"));
        interruptible("merge", [&](const std::atomic<bool>* cancel) {
          return bake::merge(shards, {.output_dir = out, .cancel = cancel});
        });
      },
      py::arg("shards"), py::arg("out"),
      R"doc(Joins the folders of a sharded bake, byte for byte the one-machine bake.

Parameters
----------
shards : list of str or os.PathLike
    The shards' folders; ValueError names a missing, repeated or mismatched one.
out : str or os.PathLike
    The joined bake's folder.)doc");
  m.def(
      "shard_frames",
      [](const Integer& frame_arg, const Integer& index_arg, const Integer& count_arg) {
        // The ranges of bake::shard_frames (within them index·frames cannot overflow).
        const long long frames = in_range(
            frame_arg, {.flag = "frames", .lo = 1, .hi = static_cast<double>(bake::kMaxFrames)});
        const long long count =
            in_range(count_arg, {.flag = "count", .lo = 1, .hi = static_cast<double>(frames)});
        const long long index =
            in_range(index_arg, {.flag = "index", .lo = 0, .hi = static_cast<double>(count - 1)});
        const bake::FrameRange r = bake::shard_frames(frames, {index, count});
        return std::pair(r.first, r.end);
      },
      py::arg("frames"), py::arg("index"), py::arg("count"),
      R"doc(The frames a shard writes in a bake.

Parameters
----------
frames : int
    Frames of the whole bake, 1 to 1000000.
index : int
    The shard, 0 to count - 1.
count : int
    Shards, 1 to frames.

Returns
-------
tuple of int
    (first, end): the shard writes frames first to end - 1.)doc");
  m.def(
      "surface_stats",
      [](const py::object& preset, const Integer& seed_arg, double time_s,
         const Integer& thread_arg) {
        // As `ocean stats --seeds` and --time.
        constexpr params::NumberOption<double> kSeeds{.flag = "--seeds", .lo = 1, .hi = 1e5};
        constexpr params::NumberOption<double> kTime{.flag = "--time",
                                                     .accept = params::Accept::finite};
        const auto seeds = static_cast<int>(in_range(seed_arg, kSeeds));
        check(params::check(kTime, time_s, format_number(time_s)));
        const auto threads = static_cast<int>(in_range(thread_arg, kThreads));
        const SimulationConfig config = config_of(preset);
        std::optional<SurfaceStats> stats;
        without_gil([&]() -> Status {
          const std::unique_ptr<TaskRunner> runner = make_tbb_runner(threads);
          Result<SurfaceStats> r = compute_surface_stats(config, seeds, time_s, *runner);
          if (!r.ok()) return r.status();
          stats = std::move(r).value();
          return {};
        });
        return stats_dict(*stats);
      },
      py::arg("preset") = py::none(), py::kw_only(), py::arg("seeds") = 4, py::arg("time") = 0.0,
      py::arg("threads") = 0,
      R"doc(Statistics of the simulated surface over several realisations (`ocean stats`).

Parameters
----------
preset : Preset, str or None, optional
    An ocean.Preset, a built-in name or a preset file; None: the defaults.
seeds : int, optional
    Realisations, 1 to 100000.
time : float, optional
    Simulation time, s.
threads : int, optional
    0 (every hardware thread) to 256.

Returns
-------
dict
    Measured and spectral Hs, height moments, slopes, Jacobian and foam, as `ocean stats
    --json` names them.)doc");
}

}  // namespace ocean::python
