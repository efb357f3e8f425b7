// `ocean stats`: statistics of the simulated surface (Hs measured against the spectrum, height
// moments, slopes, Jacobian and foam, numerical checks) over several seeds, as JSON or a table.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "ocean/statistics.hpp"
#include "simulation_flags.hpp"

namespace ocean::cli {

namespace {

constexpr NumberOption<int> kSeeds{.flag = "--seeds",
                                   .accept = Accept::integer_in_range,
                                   .lo = 1.0,
                                   .hi = 1e5,
                                   .echo = Echo::text};
constexpr NumberOption<double> kStatsTime{.flag = "--time", .accept = Accept::finite};
// The range SimulationConfig accepts for a cascade.
constexpr NumberOption<double> kPatchSize{
    .flag = "--patch-size", .accept = Accept::in_range, .lo = 0.01, .hi = 1e6};

struct StatsOptions {
  SimulationFlags simulation;
  std::string patch_size, seeds = "8", time = "0";
  bool json = false;
};

struct StatRow {
  const char* key;
  nlohmann::ordered_json value;
  const char* unit;
};

nlohmann::ordered_json optional_json(const std::optional<double>& v) {
  return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr);
}

std::optional<double> upwind(const std::optional<SlopeVariance>& v) {
  return v ? std::optional<double>(v->upwind) : std::nullopt;
}
std::optional<double> crosswind(const std::optional<SlopeVariance>& v) {
  return v ? std::optional<double>(v->crosswind) : std::nullopt;
}
// The cascades' slope variance and the waves shorter than they resolve: what Cox & Munk measured.
std::optional<double> total_mss(const SurfaceStats& s) {
  if (!s.unresolved_slope_variance) return std::nullopt;
  return s.resolved_slope_variance.total() + s.unresolved_slope_variance->total();
}

std::vector<StatRow> rows(const SurfaceStats& s) {
  return {
      {"model", s.model, ""},
      {"wind_speed_mps", optional_json(s.wind_speed_mps), "m/s"},
      {"resolution", s.resolution, "texels"},
      {"patch_size_m", s.patch_size_m, "m"},
      {"cascades", s.cascades, ""},
      {"seeds", s.seeds, ""},
      {"first_seed", s.first_seed, ""},
      {"time_s", s.time_s, "s"},
      {"choppiness", s.choppiness, ""},
      {"loop_period_s", s.loop_period_s, "s"},
      {"hs_measured_m", s.hs_measured_m, "m"},
      {"hs_spectrum_m", s.hs_spectrum_m, "m"},
      {"hs_closed_form_m", s.hs_closed_form_m, "m"},
      {"resolved_variance_fraction", s.resolved_variance_fraction, ""},
      {"independent_wave_vectors", s.independent_wave_vectors, ""},
      {"hs_sampling_rel_std", s.hs_sampling_rel_std, ""},
      {"mean_height_m", s.mean_height_m, "m"},
      {"height_skewness", optional_json(s.height_skewness), ""},
      {"height_kurtosis", optional_json(s.height_kurtosis), ""},
      {"mean_square_slope", s.mean_square_slope, ""},
      {"cox_munk_mss", optional_json(s.cox_munk_mss), ""},
      {"resolved_mss_upwind", s.resolved_slope_variance.upwind, ""},
      {"resolved_mss_crosswind", s.resolved_slope_variance.crosswind, ""},
      {"unresolved_mss_upwind", optional_json(upwind(s.unresolved_slope_variance)), ""},
      {"unresolved_mss_crosswind", optional_json(crosswind(s.unresolved_slope_variance)), ""},
      {"total_mss", optional_json(total_mss(s)), ""},
      {"cox_munk_mss_upwind", optional_json(upwind(s.cox_munk_slope_variance)), ""},
      {"cox_munk_mss_crosswind", optional_json(crosswind(s.cox_munk_slope_variance)), ""},
      {"folded_fraction", s.folded_fraction, ""},
      {"min_jacobian", s.min_jacobian, ""},
      {"foam_coverage", s.foam_coverage, ""},
      {"mean_foam", s.mean_foam, ""},
      {"whitecap_coverage", s.whitecap_coverage, ""},
      {"monahan_whitecap_coverage", optional_json(s.monahan_whitecap_coverage), ""},
      {"max_imaginary_rel_hs", optional_json(s.max_imaginary_rel_hs), ""},
      {"loop_error_rel_hs", optional_json(s.loop_error_rel_hs), ""},
  };
}

// Flags of this command that resolve_config does not know.
struct StatsInputs {
  int seeds = 8;
  double time_s = 0.0;
  std::optional<double> patch_size_m;
};

Result<StatsInputs> parse_inputs(const StatsOptions& o) {
  StatsInputs in;
  Result<int> seeds = parse(kSeeds, o.seeds);
  if (!seeds.ok()) return seeds.status();
  in.seeds = seeds.value();
  Result<double> time = parse(kStatsTime, o.time);
  if (!time.ok()) return time.status();
  in.time_s = time.value();
  if (!o.patch_size.empty()) {
    Result<double> size = parse(kPatchSize, o.patch_size);
    if (!size.ok()) return size.status();
    in.patch_size_m = size.value();
  }
  return in;
}

int run_stats(const StatsOptions& o) {
  Result<StatsInputs> inputs = parse_inputs(o);
  if (!inputs.ok()) return report(inputs.status());
  Result<SimulationConfig> resolved = resolve_config(o.simulation);
  if (!resolved.ok()) return report(resolved.status());
  SimulationConfig config = std::move(resolved).value();
  // One cascade of --patch-size; else the cascades the user chose (--cascades, a preset or
  // --set); else a single 1000 m patch.
  if (inputs.value().patch_size_m) {
    config.cascade_patch_sizes_m = {*inputs.value().patch_size_m};
  } else if (o.simulation.cascades.empty() &&
             config.cascade_patch_sizes_m == SimulationConfig{}.cascade_patch_sizes_m) {
    config.cascade_patch_sizes_m = {1000.0};
  }
  const std::unique_ptr<TaskRunner> runner = make_tbb_runner();
  Result<SurfaceStats> stats =
      compute_surface_stats(config, inputs.value().seeds, inputs.value().time_s, *runner);
  if (!stats.ok()) return report(stats.status());
  const std::vector<StatRow> table = rows(stats.value());
  if (o.json) {
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    for (const StatRow& r : table) j[r.key] = r.value;
    print_json(j);
    return kExitOk;
  }
  std::cout << std::left << std::setw(28) << "key" << std::setw(24) << "value"
            << "unit\n";
  for (const StatRow& r : table) {
    const std::string value = r.value.is_string() ? r.value.get<std::string>() : r.value.dump();
    std::cout << std::setw(28) << r.key << std::setw(24) << value << r.unit << "\n";
  }
  return kExitOk;
}

}  // namespace

Command add_stats_command(CLI::App& app) {
  auto options = std::make_shared<StatsOptions>();
  CLI::App* command = app.add_subcommand(
      "stats", "Statistics of the simulated surface (Hs, height moments, slopes, foam) over seeds");
  add_simulation_flags(*command, options->simulation);
  add_option(*command, kPatchSize, options->patch_size,
             "one cascade of this patch side, m (overrides --cascades; default 1000)");
  add_option(*command, kSeeds, options->seeds,
             "number of realisations: seed, seed+1, ..., seed+N-1")
      ->capture_default_str();
  add_option(*command, kStatsTime, options->time, "simulation time t, s")->capture_default_str();
  command->add_flag("--json", options->json, "print JSON instead of a table");
  return {command, [options] { return run_stats(*options); }};
}

}  // namespace ocean::cli
