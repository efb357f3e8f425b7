// `ocean spreading`: evaluates a directional spreading function D(θ), normalised over (−π, π].
#include <iomanip>
#include <iostream>
#include <memory>

#include "cli_common.hpp"
#include "commands.hpp"

namespace ocean::cli {

namespace {
// Spreading::make checks s and alpha and names the flags.
constexpr NumberOption<double> kS{.flag = "--s"};
constexpr NumberOption<double> kAlpha{.flag = "--alpha"};
constexpr NumberOption<double> kOmegaRatio{.flag = "--omega-ratio", .accept = Accept::positive};
constexpr NumberOption<double> kWindSpeed{
    .flag = "--wind-speed", .accept = Accept::in_range, .lo = 1e-3, .hi = 100.0};
constexpr NumberOption<double> kFetch{
    .flag = "--fetch", .accept = Accept::in_range, .lo = 1.0, .hi = 1e8};
constexpr NumberOption<double> kTheta{.flag = "--theta", .accept = Accept::finite};

struct SpreadingOptions {
  std::string model = "donelan-banner";
  std::string s, alpha, omega_ratio = "1", wind_speed, fetch, theta;
  bool symmetric = false;
  bool json = false;
};

int run_spreading(const SpreadingOptions& o) {
  Result<SpreadingModel> model = parse_spreading_model(o.model);
  if (!model.ok())
    return report(Status(model.status().code(), "--model: " + model.status().message()));
  if (o.theta.empty()) return report(invalid_argument("spreading needs --theta T1,T2,... (rad)"));
  SpreadingParams params{.model = model.value()};
  params.counter_wave_suppression = !o.symmetric;
  if (!o.s.empty()) {
    Result<double> v = parse(kS, o.s);
    if (!v.ok()) return report(v.status());
    params.s = v.value();
  }
  if (!o.alpha.empty()) {
    Result<double> v = parse(kAlpha, o.alpha);
    if (!v.ok()) return report(v.status());
    params.alpha = v.value();
  }
  Result<double> ratio = parse(kOmegaRatio, o.omega_ratio);
  if (!ratio.ok()) return report(ratio.status());
  // Peak frequency: from wind and fetch (Hasselmann 1973) when given, else a nominal 1 rad/s
  // (the ratio models depend on ω/ωp only).
  SpreadingContext context{.omega_p = 1.0};
  const bool needs_wind =
      params.model == SpreadingModel::mitsuyasu || params.model == SpreadingModel::hasselmann;
  if (o.wind_speed.empty() != o.fetch.empty()) {
    return report(invalid_argument("--wind-speed and --fetch must be given together"));
  }
  if (!o.wind_speed.empty()) {
    // Both are parsed before either is range-checked.
    Result<double> u = parse(NumberOption<double>{.flag = kWindSpeed.flag}, o.wind_speed);
    if (!u.ok()) return report(u.status());
    Result<double> f = parse(NumberOption<double>{.flag = kFetch.flag}, o.fetch);
    if (!f.ok()) return report(f.status());
    if (Status s = check(kWindSpeed, u.value(), o.wind_speed); !s.ok()) return report(s);
    if (Status s = check(kFetch, f.value(), o.fetch); !s.ok()) return report(s);
    context.wind_speed_mps = u.value();
    context.omega_p =
        jonswap_fetch_law(u.value(), f.value(), kDefaultGravity, FetchLaw::hasselmann_1973)[1];
  } else if (needs_wind) {
    return report(invalid_argument(std::string(to_string(params.model)) +
                                   " spreading needs --wind-speed MPS --fetch M"));
  }
  Result<Spreading> spreading = Spreading::make(params, context);
  if (!spreading.ok()) return report(spreading.status());
  Result<std::vector<double>> theta = parse_list(kTheta, o.theta);
  if (!theta.ok()) return report(theta.status());
  const double omega = ratio.value() * context.omega_p;
  std::vector<double> d;
  for (double t : theta.value()) d.push_back(spreading.value()(omega, t));
  if (o.json) {
    print_json({{"model", to_string(params.model)},
                {"theta", theta.value()},
                {"D", d},
                {"omega_ratio", ratio.value()},
                {"spread_parameter", spreading.value().spread_parameter(omega)}});
  } else {
    std::cout << "# " << to_string(params.model) << ", omega/omega_p = " << ratio.value()
              << ", spread parameter = " << spreading.value().spread_parameter(omega) << "\n";
    for (std::size_t i = 0; i < d.size(); ++i) {
      std::cout << std::setprecision(10) << std::setw(16) << theta.value()[i] << std::setw(20)
                << d[i] << "\n";
    }
  }
  return kExitOk;
}
}  // namespace

Command add_spreading_command(CLI::App& app) {
  auto o = std::make_shared<SpreadingOptions>();
  CLI::App* command = app.add_subcommand(
      "spreading", "Directional spreading D(theta), 1/rad, normalised over (-pi, pi]");
  command
      ->add_option("--model", o->model,
                   "power-cosine | cos2s | mitsuyasu | hasselmann | donelan-banner")
      ->capture_default_str();
  add_option(*command, kS, o->s, "exponent (power-cosine: |cos|^s; cos2s: cos^2s(theta/2))");
  add_option(*command, kAlpha, o->alpha,
             "power-cosine wind alignment in [0,1]: s = 1 + 5 alpha^2, counter-wave "
             "energy 0.01 + 0.49 (1 - alpha)^2");
  command->add_flag("--symmetric", o->symmetric,
                    "power-cosine without counter-wave suppression (Tessendorf's |k.w|^s)");
  add_option(*command, kOmegaRatio, o->omega_ratio, "omega/omega_p")->capture_default_str();
  add_option(*command, kWindSpeed, o->wind_speed, "U10, m/s (mitsuyasu, hasselmann)");
  add_option(*command, kFetch, o->fetch, "fetch, m (sets omega_p by Hasselmann 1973)");
  add_option(*command, kTheta, o->theta, "angles from the mean direction T1,T2,..., rad");
  command->add_flag("--json", o->json, "print JSON {\"theta\":[...],\"D\":[...]}");
  return {command, [o] { return run_spreading(*o); }};
}

}  // namespace ocean::cli
