// `ocean dispersion`: wavenumber, frequency and group velocity from the finite-depth
// dispersion relation.
#include <iomanip>
#include <iostream>
#include <memory>

#include "cli_common.hpp"
#include "commands.hpp"

namespace ocean::cli {

namespace {
// Dispersion::make checks depth and gravity and names the flags.
constexpr NumberOption<double> kDepth{.flag = "--depth"};
constexpr NumberOption<double> kGravity{.flag = "--gravity"};
constexpr NumberOption<double> kK{.flag = "--k", .accept = Accept::non_negative};
constexpr NumberOption<double> kDispersionOmega{.flag = "--omega", .accept = Accept::non_negative};

struct DispersionOptions {
  std::string depth, gravity, k, omega;
  bool capillary = false;
  bool json = false;
};

int run_dispersion(const DispersionOptions& o) {
  if (o.k.empty() == o.omega.empty()) {
    return report(invalid_argument("dispersion needs exactly one of --k K1,... or --omega W1,..."));
  }
  DispersionParams params;
  if (!o.depth.empty()) {
    Result<double> v = parse(kDepth, o.depth);
    if (!v.ok()) return report(v.status());
    params.depth_m = v.value();
  }
  if (!o.gravity.empty()) {
    Result<double> v = parse(kGravity, o.gravity);
    if (!v.ok()) return report(v.status());
    params.gravity_mps2 = v.value();
  }
  if (o.capillary) params.capillarity_m3ps2 = kSeaWaterCapillarity;
  Result<Dispersion> dispersion = Dispersion::make(params);
  if (!dispersion.ok()) return report(dispersion.status());
  const Dispersion& d = dispersion.value();
  const bool from_k = !o.k.empty();
  Result<std::vector<double>> input = from_k ? parse_list(kK, o.k) : parse_list(kDispersionOmega, o.omega);
  if (!input.ok()) return report(input.status());
  // Only values inside the dispersion's domain (docs/math.md M.2.5), where k, ω, both
  // velocities and the wavelength are all finite and positive.
  for (double v : input.value()) {
    const Status s =
        from_k ? Dispersion::check_wavenumber(kK.flag, v) : d.check_omega(kDispersionOmega.flag, v);
    if (!s.ok()) return report(s);
  }
  std::vector<double> k, omega, cg;
  for (double v : input.value()) {
    k.push_back(from_k ? v : d.wavenumber(v));
    omega.push_back(from_k ? d.omega(v) : v);
    cg.push_back(d.group_velocity(k.back()));
  }
  if (o.json) {
    nlohmann::ordered_json out{{"k", k}, {"omega", omega}, {"group_velocity", cg}};
    std::vector<double> wavelength, phase_velocity;
    for (double kk : k) {
      wavelength.push_back(2.0 * kPi / kk);
      phase_velocity.push_back(d.phase_velocity(kk));
    }
    out["wavelength_m"] = wavelength;
    out["phase_velocity"] = phase_velocity;
    print_json(out);
  } else {
    std::cout << std::setw(16) << "k_rad_m" << std::setw(16) << "omega_rad_s" << std::setw(16)
              << "group_vel_m_s"
              << "\n";
    for (std::size_t i = 0; i < k.size(); ++i) {
      std::cout << std::setprecision(10) << std::setw(16) << k[i] << std::setw(16) << omega[i]
                << std::setw(16) << cg[i] << "\n";
    }
  }
  return kExitOk;
}
}  // namespace

Command add_dispersion_command(CLI::App& app) {
  auto o = std::make_shared<DispersionOptions>();
  CLI::App* command = app.add_subcommand(
      "dispersion",
      "Finite-depth dispersion omega^2 = (g k + T k^3) tanh(k h): k <-> omega, group velocity");
  add_option(*command, kDepth, o->depth, "water depth, m (default: deep water)");
  add_option(*command, kGravity, o->gravity, "gravitational acceleration, m/s^2 (default 9.81)");
  add_option(*command, kK, o->k, "wavenumbers K1,K2,..., rad/m, each in [1e-200, 1e200]");
  add_option(*command, kDispersionOmega, o->omega,
             "angular frequencies W1,W2,..., rad/s, each in [omega(1e-200), omega(1e200)]");
  command->add_flag("--capillary", o->capillary, "include sea-water surface tension");
  command->add_flag("--json", o->json, "print JSON {\"k\",\"omega\",\"group_velocity\"}");
  return {command, [o] { return run_dispersion(*o); }};
}

}  // namespace ocean::cli
