// `ocean query`: the height of the rendered surface above points (x, z) at a time — the sea of
// the simulation flags (or none with --calm) plus the local layer's wakes and waveforms — through
// the library's inverse-displacement query (Simulator::heights_at, ocean::heights_at), the sea's
// bands damped by --damping-mask and --bathymetry. The layer is the world's (ocean/world.hpp).
#include <iostream>
#include <memory>

#include "cli_common.hpp"
#include "commands.hpp"
#include "ocean/backends.hpp"
#include "ocean/world.hpp"
#include "simulation_flags.hpp"
#include "wave_flags.hpp"

namespace ocean::cli {

namespace {

constexpr NumberOption<double> kQueryTime{.flag = "--time", .accept = Accept::finite};

struct QueryOptions {
  SimulationFlags sim;
  WaveFlags waves;
  std::string time = "0", at, backend = "cpu";
  bool json = false;
};

// "X,Z;X,Z;...": at least one point, each two finite numbers.
Result<std::vector<std::array<double, 2>>> parse_points(const std::string& text) {
  std::vector<std::array<double, 2>> points;
  if (text.empty()) return invalid_argument("query needs --at X,Z[;X,Z...]");
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t semi = text.find(';', start);
    const std::string item =
        text.substr(start, semi == std::string::npos ? std::string::npos : semi - start);
    Result<std::vector<double>> v = parse_number_list("--at", item);
    if (!v.ok()) return v.status();
    if (v.value().size() != 2 || !std::isfinite(v.value()[0]) || !std::isfinite(v.value()[1]))
      return invalid_argument("--at = '" + excerpt(item) + "' must be X,Z (two finite numbers)");
    points.push_back({v.value()[0], v.value()[1]});
    if (semi == std::string::npos) break;
    start = semi + 1;
  }
  return points;
}

int run_query(const QueryOptions& o) {
  Result<std::vector<std::array<double, 2>>> points = parse_points(o.at);
  if (!points.ok()) return report(points.status());
  Result<double> time = parse(kQueryTime, o.time);
  if (!time.ok()) return report(time.status());
  Result<SimulationConfig> config = resolve_config(o.sim);
  if (!config.ok()) return report(config.status());
  Result<std::optional<waves::LayerParams>> layer =
      layer_params(o.waves, config.value().choppiness, time.value());
  if (!layer.ok()) return report(layer.status());
  Result<std::shared_ptr<const waves::Damping>> damping = make_damping(o.waves, config.value());
  if (!damping.ok()) return report(damping.status());
  if (Status s = add_shore_wave(o.waves, config.value(), layer.value()); !s.ok()) return report(s);
  // The world holds the layer (no objects) and hands it to the simulator.
  Result<std::unique_ptr<world::World>> world =
      world::World::make({.layer = std::move(layer).value()}, config.value());
  if (!world.ok()) return report(world.status());
  const std::shared_ptr<const waves::LocalLayer>& local = world.value()->local_layer();
  if (local != nullptr) print_warnings(*local, time.value());
  std::vector<HeightSample> out(points.value().size());
  if (o.waves.calm) {
    if (local != nullptr) heights_at(*local, time.value(), points.value(), out);
  } else {
    Result<std::unique_ptr<Simulator>> sim = make_simulator(config.value(), o.backend);
    if (!sim.ok()) return report(sim.status());
    if (Result<bool> handed = world.value()->advance_to(time.value(), *sim.value()); !handed.ok())
      return report(handed.status());
    sim.value()->set_damping(damping.value());
    sim.value()->step(time.value());
    sim.value()->heights_at(points.value(), out);
  }
  nlohmann::ordered_json x = nlohmann::ordered_json::array(), z = x, h = x;
  for (std::size_t i = 0; i < out.size(); ++i) {
    x.push_back(points.value()[i][0]);
    z.push_back(points.value()[i][1]);
    h.push_back(out[i].height_m);
  }
  if (o.json) {
    print_json({{"x", x}, {"z", z}, {"height_m", h}});
  } else {
    std::cout << "x_m z_m height_m\n";
    for (std::size_t i = 0; i < out.size(); ++i)
      std::cout << format_number(points.value()[i][0]) << " " << format_number(points.value()[i][1])
                << " " << format_number(out[i].height_m) << "\n";
  }
  return kExitOk;
}

}  // namespace

Command add_query_command(CLI::App& app) {
  auto o = std::make_shared<QueryOptions>();
  CLI::App* command = app.add_subcommand(
      "query", "Height of the surface (sea + wakes + waveforms) above points (x, z) at a time");
  add_simulation_flags(*command, o->sim);
  add_wave_flags(*command, o->waves);
  add_option(*command, kQueryTime, o->time, "simulation time, s")->capture_default_str();
  command->add_option("--at", o->at, "X,Z[;X,Z...]: the points, m");
  command->add_flag("--json", o->json, "print {\"x\": [...], \"z\": [...], \"height_m\": [...]}");
  command->add_option("--backend", o->backend, "simulation backend (see ocean info)")
      ->capture_default_str();
  return {command, [o] { return run_query(*o); }};
}

}  // namespace ocean::cli
