// src/bake/bake.cpp — the bake loop: parameter checks, the folder held as a transaction
// (output_folder.hpp), frame times, file naming per frame and cascade, the callback after every
// frame, cancellation between files, and the manifest written last saying whether it is complete.
#include "ocean/bake.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <nlohmann/json.hpp>
#include <span>
#include <vector>

#include "checksum.hpp"
#include "frame_files.hpp"
#include "manifest.hpp"
#include "ocean/backends.hpp"
#include "ocean/io.hpp"
#include "ocean/plan.hpp"
#include "ocean/preset.hpp"
#include "ocean/spectrum.hpp"
#include "output_folder.hpp"

namespace ocean::bake {
namespace {

using detail::Json;

Status check(const BakeParams& p) {
  if (p.output_dir.empty()) return invalid_argument("bake needs an output directory");
  if (!p.formats.npy && !p.formats.png && !p.formats.exr) {
    return invalid_argument("bake needs at least one format (npy, png or exr)");
  }
  if (p.frame_count < 1 || p.frame_count > kMaxFrames) {
    return invalid_argument("bake frame count " + std::to_string(p.frame_count) +
                            " is out of range: must be 1 to " + std::to_string(kMaxFrames));
  }
  if (!std::isfinite(p.fps) || !(p.fps > 0)) return invalid_argument("bake fps must be > 0");
  if (!std::isfinite(p.start_time_s)) return invalid_argument("bake start time must be finite");
  if (p.calm && p.local_layer == nullptr)
    return invalid_argument("a calm bake needs a local layer (nothing else to write)");
  if (p.shard && (p.shard->count < 1 || p.shard->count > p.frame_count || p.shard->index < 0 ||
                  p.shard->index >= p.shard->count)) {
    return invalid_argument("shard " + std::to_string(p.shard->index) + "/" +
                            std::to_string(p.shard->count) +
                            " is out of range: " + std::to_string(p.frame_count) +
                            " frame(s) make 1 to that many shards, numbered from 0");
  }
  return {};
}

// The frames this bake writes: all, or its shard's.
FrameRange written_frames(const BakeParams& p) {
  return p.shard ? shard_frames(p.frame_count, *p.shard) : FrameRange{0, p.frame_count};
}

// The manifest's "formats": the formats written, in alphabetical order.
Json format_names(const Formats& f) {
  Json names = Json::array();
  if (f.exr) names.push_back("exr");
  if (f.npy) names.push_back("npy");
  if (f.png) names.push_back("png");
  return names;
}

bool cancelled(const BakeParams& p) {
  return p.cancel != nullptr && p.cancel->load(std::memory_order_relaxed);
}

// The CRC-32 of a height map's samples as little-endian float32, with its size: enough to tell
// two waveforms apart without copying their maps into the manifest.
Json map_entry(const waves::HeightMap& map) {
  std::uint32_t crc = 0;
  for (const float v : map.values) {
    const auto u = std::bit_cast<std::uint32_t>(v);
    const std::array<std::byte, 4> le{std::byte(u & 0xFFU), std::byte((u >> 8U) & 0xFFU),
                                      std::byte((u >> 16U) & 0xFFU), std::byte(u >> 24U)};
    crc = detail::crc32_update(crc, le);
  }
  return {{"rows", map.rows}, {"cols", map.cols}, {"crc32", detail::crc32_hex(crc)}};
}

// Everything of the local layer that changes the frames but its area (the manifest's
// "local_area"): the wakes, the waveforms (their maps by size and CRC-32), the choppiness and g.
// Shards of one bake must agree on it (merge() compares it like every other entry).
Json layer_entry(const waves::LayerParams& lp) {
  Json wakes = Json::array(), waveforms = Json::array();
  for (const waves::KelvinWake& w : lp.wakes) {
    Json path = Json::array();
    for (const waves::Waypoint& p : w.path) path.push_back({p.time_s, p.x_m, p.z_m});
    wakes.push_back({{"x_m", w.x_m},
                     {"z_m", w.z_m},
                     {"heading_deg", w.heading_deg},
                     {"speed_mps", w.speed_mps},
                     {"hull_length_m", w.hull_length_m},
                     {"peak_height_m", w.peak_height_m ? Json(*w.peak_height_m) : Json(nullptr)},
                     {"fade_length_m", w.fade_length_m},
                     {"path", path}});
  }
  for (const waves::Waveform& w : lp.waveforms) {
    Json maps = Json::array();
    if (w.frames.empty() && w.map != nullptr) maps.push_back(map_entry(*w.map));
    for (const auto& frame : w.frames) maps.push_back(map_entry(*frame));
    waveforms.push_back({{"x_m", w.x_m},
                         {"z_m", w.z_m},
                         {"size_m", w.size_m},
                         {"amplitude_m", w.amplitude_m},
                         {"rotation_deg", w.rotation_deg},
                         {"fps_hz", w.fps_hz},
                         {"playback", std::string(name_of(waves::kPlaybackNames, w.playback))},
                         {"maps", maps}});
  }
  return {{"wakes", wakes},
          {"waveforms", waveforms},
          {"choppiness", lp.choppiness},
          {"gravity_mps2", lp.gravity_mps2}};
}

// The manifest's opening entries, in the order a reader wants them; "complete", "frames_written"
// and "stopped" are filled in when the bake ends.
Json manifest_head(const Simulator& sim, std::string_view backend, const BakeParams& p,
                   double range_m) {
  const SimulationConfig& c = sim.config();
  Json manifest{{"generator", p.generator}, {"complete", false}};
  if (p.shard) {  // a shard's manifest says which frames are its own (merge() reads it)
    const FrameRange r = written_frames(p);
    manifest["shard"] = {{"index", p.shard->index},
                         {"count", p.shard->count},
                         {"first_frame", r.first},
                         {"last_frame", r.end - 1}};
  }
  manifest.update(
      Json{{"frame_count", p.frame_count},
           {"frames_written", 0},
           {"stopped", nullptr},
           {"backend", std::string(backend)},
           {"config", Json::parse(preset::to_json(c))},
           {"fps", p.fps},
           {"start_time_s", p.start_time_s},
           {"formats", format_names(p.formats)},
           {"height_png_range_m", range_m},
           {"layout",
            "row-major [row][col][channel]; texel (col,row) starts at world (col, row)*L/N; "
            "displacement = (Dx, h, Dz) m; nfs = RGBA8 (normal x, normal z, foam, smoothness)"},
           {"cascades", Json::array()},
           {"frames", Json::array()}});
  if (!p.calm) {
    for (double size : c.cascade_patch_sizes_m)
      manifest["cascades"].push_back({{"patch_size_m", size}, {"resolution", c.resolution}});
  }
  manifest["calm"] = p.calm;
  if (p.local_layer != nullptr) {
    const waves::LocalArea& a = p.local_layer->params().area;
    manifest["local_area"] = {{"origin_m", {a.origin_m[0], a.origin_m[1]}},
                              {"size_m", a.size_m},
                              {"resolution", a.resolution},
                              {"edge_fraction", a.edge_fraction}};
    manifest["local_layer"] = layer_entry(p.local_layer->params());
  }
  return manifest;
}

// Records each file's size and CRC-32 in the frame's entry ("bytes", "crc32", in the order of
// "files"), read back from the folder: what merge() checks a shard's files against.
Status record_sums(const std::filesystem::path& dir, const std::vector<std::string>& names,
                   Json& entry) {
  Json bytes = Json::array(), crcs = Json::array();
  for (const std::string& name : names) {
    const Result<detail::FileSum> sum = detail::read_plain_file(dir / name, {});
    if (!sum.ok()) {
      return io_error("cannot read back " + io::quoted(dir / name) + ", just written: it " +
                      sum.status().message());
    }
    bytes.push_back(sum.value().bytes);
    crcs.push_back(detail::crc32_hex(sum.value().crc32));
  }
  entry["bytes"] = std::move(bytes);
  entry["crc32"] = std::move(crcs);
  return {};
}

// Evaluates the local layer at t and writes its heights as local_height_f<index>.npy [N][N] and,
// with the png format, local_height_f<index>.png: 16-bit gray mapping [−r, r] to [0, 65535],
// r = the frame's largest |h| (at least 1 mm), which the manifest's frame entry records.
Status write_local_frame(const waves::LocalLayer& layer, double t, const char* index,
                         const BakeParams& p, waves::LocalFrame& local,
                         std::vector<std::string>& names, Json& entry) {
  layer.evaluate(t, local);
  const auto n = static_cast<std::size_t>(local.area.resolution);
  std::vector<float> heights(n * n);
  double range = 1e-3;
  for (std::size_t i = 0; i < n * n; ++i) {
    heights[i] = local.displacement[3 * i + 1];
    range = std::max(range, std::abs(static_cast<double>(heights[i])));
  }
  const std::string stem = std::string("local_height_f") + index;
  const std::array<std::size_t, 2> shape{n, n};
  names.push_back(stem + ".npy");
  if (Status s = io::write_npy(p.output_dir / names.back(), heights.data(), shape); !s.ok())
    return s;
  if (!p.formats.png) return {};
  std::vector<std::uint16_t> gray(n * n);
  for (std::size_t i = 0; i < n * n; ++i)
    gray[i] = static_cast<std::uint16_t>(std::lround((heights[i] / range * 0.5 + 0.5) * 65535.0));
  entry["local_height_png_range_m"] = range;
  names.push_back(stem + ".png");
  return io::write_png16_gray(p.output_dir / names.back(), static_cast<int>(n), static_cast<int>(n),
                              gray.data());
}

// Writes the composited local surface of the frame (Frame::local, M.7.9): local_displacement
// [N][N][3], local_normal [N][N][3], local_jacobian [N][N] and local_foam [N][N], .npy.
Status write_local_surface(const LocalSurfaceFrame& local, const char* index, const BakeParams& p,
                           std::vector<std::string>& names) {
  const auto n = static_cast<std::size_t>(local.resolution);
  const std::array<std::size_t, 3> vectors{n, n, 3};
  const std::array<std::size_t, 2> scalars{n, n};
  const struct {
    const char* stem;
    const std::vector<float>& values;
    std::span<const std::size_t> shape;
  } files[] = {{"local_displacement_f", local.displacement, vectors},
               {"local_normal_f", local.normal, vectors},
               {"local_jacobian_f", local.jacobian, scalars},
               {"local_foam_f", local.foam, scalars}};
  for (const auto& f : files) {
    if (cancelled(p)) return {ErrorCode::cancelled, "cancelled"};
    names.push_back(std::string(f.stem) + index + ".npy");
    if (Status s = io::write_npy(p.output_dir / names.back(), f.values.data(), f.shape); !s.ok())
      return s;
  }
  return {};
}

// Writes every frame's files, calling `on_frame` after each; returns the Status that stopped the
// bake (ok when all frames were written), with the frames written whole in `manifest`. The files
// of a frame left unfinished are removed.
Status write_frames(Simulator& sim, const BakeParams& p, const FrameCallback& on_frame,
                    double range_m, const detail::OutputFolder& folder, Json& manifest) {
  std::vector<std::string> names;
  waves::LocalFrame local;
  const FrameRange range = written_frames(p);
  for (long long f = 0; f < range.end; ++f) {
    if (cancelled(p)) return {ErrorCode::cancelled, "cancelled"};
    const double t = p.start_time_s + static_cast<double>(f) / p.fps;
    if (!p.calm) sim.step(t);
    // A shard steps through the frames before its own unwritten: foam accumulates over them.
    if (f < range.first) continue;
    names.clear();
    char index[24];
    std::snprintf(index, sizeof index, "%05lld", f);
    const Frame& frame = sim.frame();
    for (std::size_t k = 0; !p.calm && k < frame.cascades.size(); ++k) {
      char stem[48];
      std::snprintf(stem, sizeof stem, "c%zu_f%s", k, index);
      if (Status s = detail::write_cascade_files(frame.cascades[k], stem, folder.dir(), p.formats,
                                                 range_m, p.cancel, names);
          !s.ok()) {
        folder.remove(names);
        return s;
      }
    }
    Json entry{{"index", f}, {"time_s", t}};
    if (p.local_layer != nullptr) {
      Status s = write_local_frame(*p.local_layer, t, index, p, local, names, entry);
      if (s.ok() && !p.calm) s = write_local_surface(frame.local, index, p, names);
      if (!s.ok()) {
        folder.remove(names);
        return s;
      }
    }
    entry["files"] = names;
    if (Status s = record_sums(folder.dir(), names, entry); !s.ok()) {
      folder.remove(names);
      return s;
    }
    manifest["frames"].push_back(entry);
    manifest["frames_written"] = f + 1 - range.first;
    if (on_frame) {
      const FrameDone done{.index = f,
                           .frame_count = p.frame_count,
                           .time_s = t,
                           .frame = p.calm ? nullptr : &frame,
                           .local = p.local_layer != nullptr ? &local : nullptr,
                           .height_png_range_m = range_m};
      if (Status s = on_frame(done); !s.ok()) return s;
    }
  }
  return {};
}

// The transaction from the start of writing to the manifest (see bake() in ocean/bake.hpp).
Status run(Simulator& sim, std::string_view backend, const BakeParams& p,
           const FrameCallback& on_frame, detail::OutputFolder& folder) {
  if (cancelled(p)) {
    return {ErrorCode::cancelled, "bake cancelled before its first frame; nothing written"};
  }
  if (Status s = folder.begin(); !s.ok()) return s;
  // The layer composited with the sea (M.7.9), its foam accumulated from the first frame.
  if (!p.calm && p.local_layer != nullptr && sim.local_layer() != p.local_layer.get())
    sim.set_local_layer(p.local_layer);
  const double range_m = height_png_range_m(sim.plan());
  Json manifest = manifest_head(sim, backend, p, range_m);
  const Status stop = write_frames(sim, p, on_frame, range_m, folder, manifest);
  const FrameRange range = written_frames(p);
  return detail::finish_manifest(folder.dir(), manifest, stop, range.end - range.first, "bake");
}

// Runs `body`, turning an escaping exception (out of memory) into an io_error.
template <typename Body>
Status guarded(Body&& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    return io_error(std::string("bake failed: ") + e.what());
  }
}

}  // namespace

long long loop_frame_count(const SimulationConfig& config, double fps) {
  if (!(config.loop_period_s > 0)) return 0;
  return std::llround(config.loop_period_s * fps);
}

double height_png_range_m(const SimulationPlan& plan) {
  return std::max(plan.significant_wave_height_m(), 1e-3);
}

Status bake(const SimulationConfig& config, std::string_view backend, const BakeParams& params,
            const FrameCallback& on_frame) {
  return guarded([&]() -> Status {
    if (Status s = check(params); !s.ok()) return s;
    // Fail on an unusable output folder before any simulation work.
    detail::OutputFolder folder;
    if (Status s = folder.open(params.output_dir, params.other_outputs); !s.ok()) return s;
    Result<std::unique_ptr<Simulator>> sim = make_simulator(config, backend);
    if (!sim.ok()) return sim.status();
    return run(*sim.value(), backend, params, on_frame, folder);
  });
}

Status bake(Simulator& simulator, const BakeParams& params, const FrameCallback& on_frame) {
  return guarded([&]() -> Status {
    if (Status s = check(params); !s.ok()) return s;
    detail::OutputFolder folder;
    if (Status s = folder.open(params.output_dir, params.other_outputs); !s.ok()) return s;
    return run(simulator, simulator.backend().name(), params, on_frame, folder);
  });
}

}  // namespace ocean::bake
