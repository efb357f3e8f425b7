// The flags simulating subcommands share (see simulation_flags.hpp).
#include "simulation_flags.hpp"

#include <cmath>

#include "ocean/plan.hpp"
#include "ocean/preset.hpp"

namespace ocean::cli {

namespace {
// ocean::validate checks the values and names the fields; these flags only refuse what is not a
// number of the right kind.
constexpr NumberOption<double> kChoppiness{.flag = "--choppiness"};
constexpr NumberOption<double> kLoopPeriod{.flag = "--loop-period"};
constexpr NumberOption<double> kCascadeSizes{.flag = "--cascades"};
// The power-of-two range is ocean::validate's ("resolution = 100 is out of range ..."); here only
// a whole number small enough for an int.
constexpr NumberOption<int> kGridResolution{.flag = "--resolution",
                                            .accept = Accept::integer_in_range,
                                            .lo = -1e6,
                                            .hi = 1e6,
                                            .echo = Echo::text,
                                            .says = "a power of two in [16, 2048]"};
// Below 2^53, where every integer is exact as a double.
constexpr NumberOption<std::uint64_t> kSeed{.flag = "--seed",
                                            .accept = Accept::integer_in_range,
                                            .lo = 0.0,
                                            .hi = 9e15,
                                            .echo = Echo::text,
                                            .says = "an integer >= 0"};
}  // namespace

nlohmann::ordered_json to_json(const SimulationConfig& config) {
  return nlohmann::ordered_json::parse(preset::to_json(config));
}

void add_simulation_flags(CLI::App& command, SimulationFlags& f) {
  command.add_option(
      "--preset", f.preset_path,
      name_list(preset::builtin_names(), ", ", ", ") + " or a preset JSON file (see presets/)");
  command.add_option("--set", f.set, "override a preset key: --set sea.wind_sea.fetch_m=5e4");
  add_spectrum_flags(command, f.sea);
  add_option(command, kGridResolution, f.resolution,
             "grid size N per cascade (power of two, 16-2048)");
  add_option(command, kSeed, f.seed, "random seed (integer)");
  add_option(command, kChoppiness, f.choppiness, "horizontal displacement lambda >= 0");
  add_option(command, kCascadeSizes, f.cascades, "patch sizes L1,L2,... in metres, largest first");
  command.add_option("--normals", f.normals, name_list(kNormalMethodNames, " | ", " | "));
  add_option(command, kLoopPeriod, f.loop_period, "loop period T, s (0 = no loop)");
  command.add_option("--band-roles", f.band_roles,
                     "ROLE,ROLE,...: one per cascade, largest first: both (default) | displace "
                     "(moves the surface, flat shading) | shade (normals and foam, no motion)");
}

namespace {
// The preset file and the --set overrides, in that order.
Result<preset::Document> resolve_document(const SimulationFlags& f) {
  preset::Document doc;
  if (!f.preset_path.empty()) {
    if (Status s = doc.merge_preset(f.preset_path, "--preset"); !s.ok()) return s;
  }
  for (const std::string& assignment : f.set) {
    if (Status s = doc.set(assignment, "--set"); !s.ok()) return s;
  }
  return doc;
}
}  // namespace

Result<preset::PictureSettings> resolve_picture(const SimulationFlags& f) {
  Result<preset::Document> doc = resolve_document(f);
  if (!doc.ok()) return doc.status();
  return doc.value().picture();
}

Result<SimulationConfig> resolve_config(const SimulationFlags& f) {
  Result<preset::Document> doc = resolve_document(f);
  if (!doc.ok()) return doc.status();
  Result<SimulationConfig> parsed = doc.value().config();
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
  if (!f.choppiness.empty()) {
    Result<double> v = parse(kChoppiness, f.choppiness);
    if (!v.ok()) return v.status();
    c.choppiness = v.value();
  }
  if (!f.loop_period.empty()) {
    Result<double> v = parse(kLoopPeriod, f.loop_period);
    if (!v.ok()) return v.status();
    c.loop_period_s = v.value();
  }
  if (!f.resolution.empty()) {
    Result<int> v = parse(kGridResolution, f.resolution);
    if (!v.ok()) return v.status();
    c.resolution = v.value();
  }
  if (!f.seed.empty()) {
    Result<std::uint64_t> v = parse(kSeed, f.seed);
    if (!v.ok()) return v.status();
    c.seed = v.value();
  }
  if (!f.cascades.empty()) {
    Result<std::vector<double>> sizes = parse_list(kCascadeSizes, f.cascades);
    if (!sizes.ok()) return sizes.status();
    c.cascade_patch_sizes_m = sizes.value();
  }
  if (!f.normals.empty()) {
    Result<NormalMethod> m = parse_normal_method(f.normals);
    if (!m.ok()) return Status(m.status().code(), "--normals: " + m.status().message());
    c.normals = m.value();
  }
  if (!f.band_roles.empty()) {
    Result<std::vector<BandRole>> roles = parse_band_roles(f.band_roles);
    if (!roles.ok())
      return Status(roles.status().code(), "--band-roles: " + roles.status().message());
    c.band_roles = std::move(roles).value();
  }
  if (Result<SimulationPlan> plan = SimulationPlan::make(c); !plan.ok()) return plan.status();
  return c;
}

}  // namespace ocean::cli
