// The local layer's flags: each value split at commas, checked, and handed to the library's
// LocalLayer (which validates the rest and builds the wake tables).
#include "wave_flags.hpp"

#include <iostream>

#include "options.hpp"

namespace ocean::cli {
namespace {

constexpr NumberOption<int> kResolution{.flag = "--local-resolution",
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

Result<waves::Waveform> parse_waveform(const std::string& text) {
  const std::string flag = "--waveform";
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos || comma == 0) {
    return invalid_argument(flag + " = '" + excerpt(text) +
                            "' must be FILE,X,Z,SIZE_M,AMPLITUDE_M[,ROTATION_DEG]");
  }
  Result<std::vector<double>> v =
      numbers(flag, text.substr(comma + 1), 4, 5, "FILE,X,Z,SIZE_M,AMPLITUDE_M[,ROTATION_DEG]");
  if (!v.ok()) return v.status();
  Result<waves::HeightMap> map = waves::load_height_map(text.substr(0, comma));
  if (!map.ok()) return Status{map.status().code(), flag + ": " + map.status().message()};
  const std::vector<double>& n = v.value();
  const waves::Waveform w{.map = std::make_shared<const waves::HeightMap>(std::move(map).value()),
                          .x_m = n[0],
                          .z_m = n[1],
                          .size_m = n[2],
                          .amplitude_m = n[3],
                          .rotation_deg = n.size() > 4 ? n[4] : 0.0};
  if (Status s = waves::validate(w); !s.ok()) return flagged(flag, text, s);
  return w;
}

}  // namespace

void add_wave_flags(CLI::App& command, WaveFlags& f) {
  command.add_flag("--calm", f.calm, "no wind sea: only the local layer's wakes and waveforms");
  command.add_option("--kelvin-wake", f.wakes,
                     "X,Z,HEADING_DEG,SPEED_MPS,LENGTH_M: an object at (X, Z) at t = 0 moving "
                     "along HEADING (0 = +x, 90 = +z); repeatable");
  command.add_option("--waveform", f.waveforms,
                     "FILE,X,Z,SIZE_M,AMPLITUDE_M[,ROTATION_DEG]: a .npy or gray PNG height map "
                     "centred at (X, Z); repeatable");
  command.add_option("--local-area", f.local_area, "X0,Z0,SIZE_M: the local layer's square");
  add_option(command, kResolution, f.local_resolution, "cells per side of the local layer")
      ->capture_default_str();
}

Result<std::shared_ptr<const waves::LocalLayer>> make_layer(const WaveFlags& f, double choppiness) {
  if (f.local_area.empty()) {
    if (!f.wakes.empty() || !f.waveforms.empty())
      return invalid_argument("--kelvin-wake and --waveform need --local-area X0,Z0,SIZE_M");
    return std::shared_ptr<const waves::LocalLayer>();
  }
  waves::LayerParams p;
  p.choppiness = choppiness;
  Result<std::vector<double>> area = numbers("--local-area", f.local_area, 3, 3, "X0,Z0,SIZE_M");
  if (!area.ok()) return area.status();
  Result<int> n = parse(kResolution, f.local_resolution);
  if (!n.ok()) return n.status();
  p.area = {.origin_m = {area.value()[0], area.value()[1]},
            .size_m = area.value()[2],
            .resolution = n.value()};
  if (Status s = waves::validate(p.area); !s.ok()) return flagged("--local-area", f.local_area, s);
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
  Result<std::unique_ptr<waves::LocalLayer>> layer = waves::LocalLayer::make(std::move(p));
  if (!layer.ok()) return layer.status();
  return std::shared_ptr<const waves::LocalLayer>(std::move(layer).value());
}

void print_warnings(const waves::LocalLayer& layer, double time_s) {
  for (const std::string& w : layer.warnings(time_s)) std::cerr << "ocean: warning: " << w << "\n";
}

}  // namespace ocean::cli
