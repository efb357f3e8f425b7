// The local layer's flags: each value split at commas, checked, and handed to the library's
// LocalLayer (which validates the rest and builds the wake tables).
#include "wave_flags.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <limits>
#include <numbers>
#include <optional>

#include "options.hpp"
#include "shallows.hpp"

namespace ocean::cli {
namespace {

constexpr NumberOption<int> kLocalResolution{.flag = "--local-resolution",
                                             .accept = Accept::integer_in_range,
                                             .lo = waves::kMinLocalResolution,
                                             .hi = waves::kMaxLocalResolution,
                                             .echo = Echo::text};

Status flagged(const std::string& flag, const std::string& text, const Status& s) {
  return {s.code(), flag + " '" + excerpt(text) + "': " + s.message()};
}

Result<std::vector<double>> numbers(const std::string& flag, const std::string& text,
                                    std::size_t lo, std::size_t hi, const char* form) {
  Result<std::vector<double>> v = parse_number_list(flag, text);
  if (!v.ok()) return v.status();
  if (v.value().size() < lo || v.value().size() > hi)
    return invalid_argument(flag + " = '" + excerpt(text) + "' must be " + form);
  return v;
}

Result<waves::KelvinWake> parse_wake(const std::string& text) {
  const char* flag = "--kelvin-wake";
  Result<std::vector<double>> v = numbers(flag, text, 5, 5, "X,Z,HEADING_DEG,SPEED_MPS,LENGTH_M");
  if (!v.ok()) return v.status();
  const std::vector<double>& n = v.value();
  const waves::KelvinWake w{
      .x_m = n[0], .z_m = n[1], .heading_deg = n[2], .speed_mps = n[3], .hull_length_m = n[4]};
  if (Status s = waves::validate(w); !s.ok()) return flagged(flag, text, s);
  return w;
}

// "FILE,N1,N2,...": the map read from FILE (load_height_map) and lo..hi numbers after it.
struct FileAndNumbers {
  waves::HeightMap map;
  std::vector<double> numbers;
};
Result<FileAndNumbers> parse_file_and_numbers(const std::string& flag, const std::string& text,
                                              std::size_t lo, std::size_t hi, const char* form) {
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos || comma == 0)
    return invalid_argument(flag + " = '" + excerpt(text) + "' must be " + form);
  Result<std::vector<double>> v = numbers(flag, text.substr(comma + 1), lo, hi, form);
  if (!v.ok()) return v.status();
  Result<waves::HeightMap> map = waves::load_height_map(text.substr(0, comma));
  if (!map.ok()) return Status{map.status().code(), flag + ": " + map.status().message()};
  return FileAndNumbers{std::move(map).value(), std::move(v).value()};
}

// FILE,X,Z,SIZE_M,AMPLITUDE_M[,ROTATION_DEG] for a still map, or
// PATTERN,X,Z,SIZE_M,AMPLITUDE_M,ROTATION_DEG,FPS[,loop|hold] for a sequence whose file names hold
// {frame} or {frame:W} (W.16).
Result<waves::Waveform> parse_waveform(const std::string& text) {
  const std::string flag = "--waveform";
  const char* still = "FILE,X,Z,SIZE_M,AMPLITUDE_M[,ROTATION_DEG]";
  const char* animated = "PATTERN,X,Z,SIZE_M,AMPLITUDE_M,ROTATION_DEG,FPS[,loop|hold]";
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos || comma == 0 ||
      !waves::is_sequence_pattern(text.substr(0, comma))) {
    Result<FileAndNumbers> f = parse_file_and_numbers(flag, text, 4, 5, still);
    if (!f.ok() && std::count(text.begin(), text.end(), ',') > 5)  // a sequence without {frame}
      return invalid_argument(flag + " = '" + excerpt(text) + "' must be " + still +
                              " (an animated sequence's file name holds {frame})");
    if (!f.ok()) return f.status();
    const std::vector<double>& n = f.value().numbers;
    const waves::Waveform w{
        .map = std::make_shared<const waves::HeightMap>(std::move(f.value().map)),
        .x_m = n[0],
        .z_m = n[1],
        .size_m = n[2],
        .amplitude_m = n[3],
        .rotation_deg = n.size() > 4 ? n[4] : 0.0};
    if (Status s = waves::validate(w); !s.ok()) return flagged(flag, text, s);
    return w;
  }
  std::string rest = text.substr(comma + 1);
  waves::Playback playback = waves::Playback::loop;
  const std::size_t last = rest.rfind(',');
  const std::string word = last == std::string::npos ? rest : rest.substr(last + 1);
  if (std::optional<waves::Playback> named = value_of(waves::kPlaybackNames, word)) {
    playback = *named;
    rest = last == std::string::npos ? std::string() : rest.substr(0, last);
  }
  Result<std::vector<double>> v = numbers(flag, rest, 6, 6, animated);
  if (!v.ok()) return v.status();
  Result<std::vector<std::shared_ptr<const waves::HeightMap>>> frames =
      waves::load_height_map_sequence(text.substr(0, comma));
  if (!frames.ok()) return Status{frames.status().code(), flag + ": " + frames.status().message()};
  const std::vector<double>& n = v.value();
  const waves::Waveform w{.frames = std::move(frames).value(),
                          .fps_hz = n[5],
                          .playback = playback,
                          .x_m = n[0],
                          .z_m = n[1],
                          .size_m = n[2],
                          .amplitude_m = n[3],
                          .rotation_deg = n[4]};
  if (Status s = waves::validate(w); !s.ok()) return flagged(flag, text, s);
  return w;
}

// FILE,X0,Z0,SIZE_M of --damping-mask or --bathymetry. A PNG mask's [−1, 1] (load_height_map)
// is its gray level mapped back to [0, 1]; a depth needs metres, so a .npy file.
Result<waves::PlacedMap> parse_placed_map(const std::string& flag, const std::string& text,
                                          bool is_mask) {
  std::string ext = std::filesystem::path(text.substr(0, text.find(','))).extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (ext == ".png" && !is_mask)
    return invalid_argument(flag + " '" + excerpt(text) + "': depths in metres need a .npy file");
  Result<FileAndNumbers> f = parse_file_and_numbers(flag, text, 3, 3, "FILE,X0,Z0,SIZE_M");
  if (!f.ok()) return f.status();
  if (ext == ".png")
    for (float& v : f.value().map.values) v = 0.5f * (v + 1.0f);
  const std::vector<double>& n = f.value().numbers;
  return waves::PlacedMap{.map = std::make_shared<const waves::HeightMap>(std::move(f.value().map)),
                          .origin_m = {n[0], n[1]},
                          .size_m = n[2]};
}

// The wake's area suggestion (W.19): the steady pattern shown this many transverse wavelengths
// behind its object (at least kSuggestedHulls hull lengths), on cells of a tenth of the
// wavelength (its cusp waves, 2/3 of it, then keep 6.7 cells, clear of the table's taper, W.5).
constexpr double kSuggestedWavelengths = 12.0;
constexpr double kSuggestedHulls = 5.0;
constexpr double kSuggestedCellsPerWavelength = 10.0;

// A square holding each wake's object at time t with its wake behind it — the object 0.3 of the
// side in from the front, its track along the middle, so the hull and the 19.5° wedge stay clear
// of the wakes' soft edge (W.9b: 4 transverse wavelengths, at most a quarter side) — and each
// waveform's map, turned any way. Numbers rounded to two or three
// significant digits.
struct SuggestedArea {
  double x0 = 0.0, z0 = 0.0, size = 0.0;
  double shortest_wavelength_m = 0.0;  ///< of the wakes' transverse waves; +inf without wakes
};
SuggestedArea suggested_area(const std::vector<waves::KelvinWake>& wakes,
                             const std::vector<waves::Waveform>& forms, double time_s) {
  double x0 = std::numeric_limits<double>::infinity(), z0 = x0, x1 = -x0, z1 = -x0;
  const auto hold = [&](double x, double z, double half) {
    x0 = std::min(x0, x - half), z0 = std::min(z0, z - half);
    x1 = std::max(x1, x + half), z1 = std::max(z1, z + half);
  };
  constexpr double kG = 9.81;  // the wakes' gravity (LayerParams)
  SuggestedArea out{.shortest_wavelength_m = std::numeric_limits<double>::infinity()};
  for (const waves::KelvinWake& w : wakes) {
    const waves::WakePose p = waves::pose_at(w, time_s);
    const double wavelength = 2.0 * std::numbers::pi * p.speed_mps * p.speed_mps / kG;
    out.shortest_wavelength_m = std::min(out.shortest_wavelength_m, wavelength);
    // 0.7 of the side behind the object: 1.05 times the length wanted.
    const double side =
        1.5 * std::max(kSuggestedWavelengths * wavelength, kSuggestedHulls * w.hull_length_m);
    const double back = 0.2 * side;  // from the object to the square's centre
    hold(p.x_m - back * std::cos(p.heading_rad), p.z_m - back * std::sin(p.heading_rad),
         0.5 * side);
  }
  for (const waves::Waveform& w : forms) {
    const waves::HeightMap& m = w.frames.empty() ? *w.map : *w.frames.front();
    const double aspect = static_cast<double>(m.rows) / m.cols;
    hold(w.x_m, w.z_m, 0.5 * w.size_m * std::sqrt(1.0 + aspect * aspect));
  }
  const double size = std::max(x1 - x0, z1 - z0);
  const double unit = std::pow(10.0, std::floor(std::log10(size)) - 1.0);
  out.x0 = std::floor((0.5 * (x0 + x1 - size)) / unit) * unit;
  out.z0 = std::floor((0.5 * (z0 + z1 - size)) / unit) * unit;
  out.size = std::ceil((size + unit) / unit) * unit;
  return out;
}

// The error for wakes or waveforms without --local-area: it names a square that holds them
// (suggested_area) and, where the grid of `resolution` cells would give the shortest transverse
// wavelength fewer than 10 cells, a finer --local-resolution (W.19).
Status area_needed(const std::vector<waves::KelvinWake>& wakes,
                   const std::vector<waves::Waveform>& forms, double time_s, int resolution) {
  const SuggestedArea a = suggested_area(wakes, forms, time_s);
  std::string text =
      "--kelvin-wake and --waveform need --local-area X0,Z0,SIZE_M, the square the "
      "local layer covers: --local-area " +
      format_number(a.x0) + "," + format_number(a.z0) + "," + format_number(a.size);
  if (wakes.empty()) return invalid_argument(text + " holds the waveforms");
  const double wanted = a.size / (a.shortest_wavelength_m / kSuggestedCellsPerWavelength);
  int n = resolution;
  if (wanted > resolution) {
    n = std::min(64 * static_cast<int>(std::ceil(wanted / 64.0)), waves::kMaxLocalResolution);
    text += " --local-resolution " + std::to_string(n);
  }
  const double cells = std::round(10.0 * a.shortest_wavelength_m * n / a.size) / 10.0;
  text += " holds " + std::string(wakes.size() == 1 ? "the wake's object" : "the wakes' objects") +
          " at t = " + format_number(time_s) + " s and " + format_number(kSuggestedWavelengths) +
          " transverse wavelengths (2πU²/g) of " + (wakes.size() == 1 ? "its wake" : "each wake") +
          " behind, with " + format_number(cells) + " cells per transverse wavelength" +
          (wakes.size() == 1 ? "" : " of the slowest");
  return invalid_argument(text + (forms.empty() ? "" : ", and the waveforms"));
}

}  // namespace

void add_wave_flags(CLI::App& command, WaveFlags& f) {
  command.add_flag("--calm", f.calm, "no wind sea: only the local layer's wakes and waveforms");
  command.add_option("--kelvin-wake", f.wakes,
                     "X,Z,HEADING_DEG,SPEED_MPS,LENGTH_M: an object at (X, Z) at t = 0 moving "
                     "along HEADING (0 = +x, 90 = +z); repeatable");
  command.add_option(
      "--waveform", f.waveforms,
      "FILE,X,Z,SIZE_M,AMPLITUDE_M[,ROTATION_DEG]: a .npy, gray PNG or EXR height map "
      "centred at (X, Z); or PATTERN,X,Z,SIZE_M,AMPLITUDE_M,ROTATION_DEG,FPS"
      "[,loop|hold]: an animated sequence, the files whose names are PATTERN with "
      "{frame} (or {frame:W}, W digits) replaced by consecutive numbers, played at "
      "FPS, blended between frames; repeatable");
  command.add_option("--local-area", f.local_area, "X0,Z0,SIZE_M: the local layer's square");
  add_option(command, kLocalResolution, f.local_resolution, "cells per side of the local layer")
      ->capture_default_str();
  command.add_option("--damping-mask", f.damping_mask,
                     "FILE,X0,Z0,SIZE_M: .npy (or gray PNG) in [0, 1] from corner (X0, Z0); 0 = "
                     "the low band only, 1 = every band");
  command.add_option("--bathymetry", f.bathymetry,
                     "FILE,X0,Z0,SIZE_M: .npy water depth, m, from corner (X0, Z0); damps each "
                     "band where the water is shallow against its wavelength");
  command.add_option("--shallows", f.shallows,
                     "none, lily-pads (a damping mask), lagoon (an island 4 m high in a 400 m "
                     "bathymetry) or beach (a planar beach in a 600 m bathymetry), centred on the "
                     "origin, the sea's peak wave refracted and shoaled over the lagoon and the "
                     "beach; instead of --damping-mask and --bathymetry");
  command.add_option("--breaking-index", f.breaking_index,
                     "GAMMA: waves over --bathymetry break where their rms height exceeds GAMMA "
                     "times the depth (default 0.78, McCowan's solitary wave; 0: no breaking)");
}

Result<std::shared_ptr<const waves::Damping>> make_damping(const WaveFlags& f,
                                                           const SimulationConfig& config) {
  const std::optional<Shallows> shallows = parse_shallows(f.shallows);
  if (!shallows)
    return invalid_argument("--shallows = '" + excerpt(f.shallows) +
                            "': must be none, lily-pads, lagoon or beach");
  if (f.damping_mask.empty() && f.bathymetry.empty() && *shallows == Shallows::none)
    return std::shared_ptr<const waves::Damping>();
  if (f.calm)
    return invalid_argument(
        "--damping-mask, --bathymetry and --shallows damp the sea's bands: not with --calm");
  Result<std::vector<double>> gamma =
      numbers("--breaking-index", f.breaking_index, 1, 1, "one number (0: no breaking)");
  if (!gamma.ok()) return gamma.status();
  if (*shallows != Shallows::none) {
    if (!f.damping_mask.empty() || !f.bathymetry.empty())
      return invalid_argument(
          "--shallows is a scene of its own: not with --damping-mask or "
          "--bathymetry");
    Result<std::optional<waves::Damping>> scene =
        shallows_damping(*shallows, {0.0, 0.0}, config, gamma.value()[0]);
    if (!scene.ok()) return flagged("--breaking-index", f.breaking_index, scene.status());
    return std::make_shared<const waves::Damping>(std::move(*scene.value()));
  }
  waves::DampingParams p{.band_wavenumbers_radpm = band_wavenumbers(config),
                         .gravity_mps2 = config.sea.dispersion.gravity_mps2};
  if (!f.damping_mask.empty()) {
    Result<waves::PlacedMap> m = parse_placed_map("--damping-mask", f.damping_mask, true);
    if (!m.ok()) return m.status();
    p.mask = std::move(m).value();
  }
  if (!f.bathymetry.empty()) {
    Result<waves::PlacedMap> m = parse_placed_map("--bathymetry", f.bathymetry, false);
    if (!m.ok()) return m.status();
    p.bathymetry = std::move(m).value();
  }
  if (gamma.value()[0] != 0.0 && p.bathymetry.has_value()) {  // (W.25–W.27)
    Result<std::vector<double>> m0 = band_variances(config);
    if (!m0.ok()) return m0.status();
    p.band_variances_m2 = std::move(m0).value();
    p.breaking_index = gamma.value()[0];
  }
  Result<waves::Damping> d = waves::Damping::make(std::move(p));
  if (!d.ok()) {
    if (d.status().message().starts_with("breaking_index"))
      return flagged("--breaking-index", f.breaking_index, d.status());
    const bool mask = d.status().message().starts_with("damping mask");
    return flagged(mask ? "--damping-mask" : "--bathymetry", mask ? f.damping_mask : f.bathymetry,
                   d.status());
  }
  return std::make_shared<const waves::Damping>(std::move(d).value());
}

Status add_shore_wave(const WaveFlags& f, const SimulationConfig& config,
                      std::optional<waves::LayerParams>& layer) {
  const std::optional<Shallows> shallows = parse_shallows(f.shallows);
  if (!shallows || f.calm || (*shallows != Shallows::lagoon && *shallows != Shallows::beach))
    return {};
  Result<std::vector<double>> gamma =
      numbers("--breaking-index", f.breaking_index, 1, 1, "one number (0: no breaking)");
  if (!gamma.ok()) return {};
  Result<int> n = parse(kLocalResolution, f.local_resolution);
  if (!n.ok()) return n.status();
  Result<std::optional<waves::Waveform>> form = shallows_shore_wave(
      *shallows, {0.0, 0.0}, config, gamma.value()[0], n.value(), kShoreWaveFrames);
  if (!form.ok()) return form.status();
  if (!form.value().has_value()) return {};
  const waves::Waveform& w = *form.value();
  if (!layer.has_value()) {
    layer =
        waves::LayerParams{.area = {.origin_m = {w.x_m - 0.5 * w.size_m, w.z_m - 0.5 * w.size_m},
                                    .size_m = w.size_m,
                                    .resolution = n.value()},
                           .choppiness = config.choppiness,
                           .gravity_mps2 = config.sea.dispersion.gravity_mps2};
  }
  layer->waveforms.push_back(std::move(*form.value()));
  return {};
}

DampingSamples sample_damping(const waves::Damping& damping, int resolution, std::size_t bands) {
  double x0 = std::numeric_limits<double>::infinity(), z0 = x0, x1 = -x0, z1 = -x0;
  for (const std::optional<waves::PlacedMap>* m :
       {&damping.params().mask, &damping.params().bathymetry}) {
    if (!m->has_value()) continue;
    const waves::PlacedMap& p = m->value();
    x0 = std::min(x0, p.origin_m[0]), z0 = std::min(z0, p.origin_m[1]);
    x1 = std::max(x1, p.origin_m[0] + p.size_m);
    z1 = std::max(z1, p.origin_m[1] + p.size_m * p.map->rows / p.map->cols);
  }
  DampingSamples out;
  out.origin_m = {x0, z0};
  out.size_m = std::max(x1 - x0, z1 - z0);
  out.resolution = resolution;
  const auto n = static_cast<std::size_t>(resolution);
  out.band_weights.assign(n * n * bands, 1.0f);
  out.depth_m.assign(n * n, std::numeric_limits<float>::infinity());
  out.breaking_fraction.assign(n * n, 0.0f);
  std::vector<double> w(std::max(bands, damping.band_count()), 1.0);
  for (std::size_t row = 0; row < n; ++row) {
    for (std::size_t col = 0; col < n; ++col) {
      const double x = x0 + (static_cast<double>(col) + 0.5) * out.size_m / resolution;
      const double z = z0 + (static_cast<double>(row) + 0.5) * out.size_m / resolution;
      std::fill(w.begin(), w.end(), 1.0);
      damping.band_weights(x, z, w);
      const std::size_t cell = row * n + col;
      for (std::size_t b = 0; b < bands; ++b)
        out.band_weights[cell * bands + b] = static_cast<float>(w[b]);
      const waves::Surf surf = damping.surf(x, z);
      out.depth_m[cell] = static_cast<float>(surf.depth_m);
      out.breaking_fraction[cell] = static_cast<float>(surf.breaking_fraction);
    }
  }
  return out;
}

Result<std::optional<waves::LayerParams>> layer_params(const WaveFlags& f, double choppiness,
                                                       double time_s) {
  if (f.local_area.empty() && f.wakes.empty() && f.waveforms.empty())
    return std::optional<waves::LayerParams>();
  waves::LayerParams p;
  p.choppiness = choppiness;
  Result<int> n = parse(kLocalResolution, f.local_resolution);
  if (!n.ok()) return n.status();
  for (const std::string& text : f.wakes) {
    Result<waves::KelvinWake> w = parse_wake(text);
    if (!w.ok()) return w.status();
    p.wakes.push_back(std::move(w).value());
  }
  for (const std::string& text : f.waveforms) {
    Result<waves::Waveform> w = parse_waveform(text);
    if (!w.ok()) return w.status();
    p.waveforms.push_back(std::move(w).value());
  }
  if (f.local_area.empty()) return area_needed(p.wakes, p.waveforms, time_s, n.value());
  Result<std::vector<double>> area = numbers("--local-area", f.local_area, 3, 3, "X0,Z0,SIZE_M");
  if (!area.ok()) return area.status();
  p.area = {.origin_m = {area.value()[0], area.value()[1]},
            .size_m = area.value()[2],
            .resolution = n.value()};
  if (Status s = waves::validate(p.area); !s.ok()) return flagged("--local-area", f.local_area, s);
  return std::optional<waves::LayerParams>(std::move(p));
}

void print_warnings(const waves::LocalLayer& layer, double time_s) {
  for (const std::string& w : layer.warnings(time_s)) std::cerr << "ocean: warning: " << w << "\n";
}

}  // namespace ocean::cli
