// The flags simulating subcommands share (see simulation_flags.hpp).
#include "simulation_flags.hpp"

#include <cmath>

#include "ocean/preset.hpp"

namespace ocean::cli {

nlohmann::ordered_json to_json(const SimulationConfig& config) {
  return nlohmann::ordered_json::parse(preset::to_json(config));
}

void add_simulation_flags(CLI::App& command, SimulationFlags& f) {
  command.add_option("--preset", f.preset_path,
                     "calm, moderate, storm or a preset JSON file (see presets/)");
  command.add_option("--set", f.set, "override a preset key: --set sea.wind_sea.fetch_m=5e4");
  add_spectrum_flags(command, f.sea);
  command.add_option("--resolution", f.resolution,
                     "grid size N per cascade (power of two, 16-2048)");
  command.add_option("--seed", f.seed, "random seed (integer)");
  command.add_option("--choppiness", f.choppiness, "horizontal displacement lambda >= 0");
  command.add_option("--cascades", f.cascades, "patch sizes L1,L2,... in metres, largest first");
  command.add_option("--normals", f.normals, "central-difference | analytic | sobel");
  command.add_option("--loop-period", f.loop_period, "loop period T, s (0 = no loop)");
}

Result<SimulationConfig> resolve_config(const SimulationFlags& f) {
  preset::Document doc;
  if (!f.preset_path.empty()) {
    if (Status s = doc.merge_preset(f.preset_path, "--preset"); !s.ok()) return s;
  }
  for (const std::string& assignment : f.set) {
    if (Status s = doc.set(assignment, "--set"); !s.ok()) return s;
  }
  Result<SimulationConfig> parsed = doc.config();
  if (!parsed.ok()) return parsed.status();
  SimulationConfig c = std::move(parsed).value();
  // Explicit sea-state flags replace the preset's wind sea.
  const SpectrumFlags& s = f.sea;
  const bool any_sea_flag = !s.hs.empty() || !s.tp.empty() || !s.wind_speed.empty() ||
                            !s.fetch.empty() || !s.gamma.empty() || !s.depth.empty() ||
                            s.model != SpectrumFlags{}.model;
  if (any_sea_flag) {
    Result<FrequencySpectrumParams> spectrum = to_params(s);
    if (!spectrum.ok()) return spectrum.status();
    c.sea.wind_sea.spectrum = spectrum.value();
    c.sea.dispersion.gravity_mps2 = spectrum.value().gravity_mps2;
    c.sea.dispersion.depth_m = kInfiniteDepth;
  }
  const std::pair<const std::string*, const char*> numbers[] = {{&f.choppiness, "--choppiness"},
                                                                {&f.loop_period, "--loop-period"}};
  for (const auto& [text, flag] : numbers) {
    if (text->empty()) continue;
    Result<double> v = parse_number(flag, *text);
    if (!v.ok()) return v.status();
    (text == &f.choppiness ? c.choppiness : c.loop_period_s) = v.value();
  }
  if (!f.resolution.empty()) {
    Result<double> v = parse_number("--resolution", f.resolution);
    if (!v.ok()) return v.status();
    if (v.value() != std::floor(v.value()) || std::abs(v.value()) > 1e6) {
      return invalid_argument("--resolution = " + f.resolution +
                              " is out of range: must be a power of two in [16, 2048]");
    }
    c.resolution = static_cast<int>(v.value());
  }
  if (!f.seed.empty()) {
    Result<double> v = parse_number("--seed", f.seed);
    if (!v.ok()) return v.status();
    if (v.value() < 0 || v.value() != std::floor(v.value()) || v.value() > 9e15) {
      return invalid_argument("--seed = " + f.seed + " is out of range: must be an integer >= 0");
    }
    c.seed = static_cast<std::uint64_t>(v.value());
  }
  if (!f.cascades.empty()) {
    Result<std::vector<double>> sizes = parse_number_list("--cascades", f.cascades);
    if (!sizes.ok()) return sizes.status();
    c.cascade_patch_sizes_m = sizes.value();
  }
  if (!f.normals.empty()) {
    Result<NormalMethod> m = parse_normal_method(f.normals);
    if (!m.ok()) return Status(m.status().code(), "--normals: " + m.status().message());
    c.normals = m.value();
  }
  if (Status st = validate(c); !st.ok()) return st;
  if (Result<SeaState> sea = SeaState::make(c.sea); !sea.ok()) return sea.status();
  return c;
}

}  // namespace ocean::cli
