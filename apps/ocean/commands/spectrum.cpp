// `ocean spectrum`: evaluates a one-sided frequency spectrum S(ω) as JSON or a table, and draws
// the sea-state figure.
#include <iomanip>
#include <iostream>
#include <memory>

#include "cli_common.hpp"
#include "commands.hpp"
#include "output_name.hpp"
#include "sea_state_figure.hpp"

namespace ocean::cli {

namespace {
constexpr NumberOption<double> kOmega{.flag = "--omega", .accept = Accept::non_negative};

struct SpectrumOptions {
  SpectrumFlags sea;
  std::string omega;
  bool json = false;
  std::string plot_path;
};

int run_spectrum(const SpectrumOptions& o) {
  if (o.omega.empty() && o.plot_path.empty()) {
    return report(invalid_argument("spectrum needs --omega W1,W2,... or --plot FILE.png"));
  }
  if (!o.plot_path.empty()) {
    if (Status s = check_output_name("--plot", o.plot_path); !s.ok()) return report(s);
  }
  Result<FrequencySpectrumParams> params = to_params(o.sea);
  if (!params.ok()) return report(params.status());
  Result<FrequencySpectrum> spectrum = FrequencySpectrum::make(params.value());
  if (!spectrum.ok()) return report(spectrum.status());
  std::vector<double> omega;
  if (!o.omega.empty()) {
    Result<std::vector<double>> list = parse_list(kOmega, o.omega);
    if (!list.ok()) return report(list.status());
    omega = std::move(list).value();
  }
  if (!o.plot_path.empty()) {
    Result<plot::Figure> figure = make_sea_state_figure(params.value());
    if (!figure.ok()) return report(figure.status());
    if (Status s = plot::write_png(figure.value(), o.plot_path); !s.ok()) return report(s);
    std::cerr << "ocean: wrote " << o.plot_path << "\n";
  }
  if (omega.empty()) return kExitOk;
  const FrequencySpectrum& s = spectrum.value();
  std::vector<double> values;
  for (double w : omega) values.push_back(s(w));
  if (o.json) {
    print_json({{"model", to_string(s.params().model)},
                {"omega", omega},
                {"S", values},
                {"peak_omega", s.peak_omega()},
                {"peak_period_s", 2.0 * kPi / s.peak_omega()},
                {"gamma", s.gamma()},
                {"hs_m", s.hs_m()}});
  } else {
    std::cout << "# " << to_string(s.params().model) << ": Hs = " << s.hs_m()
              << " m, peak omega = " << s.peak_omega() << " rad/s\n";
    std::cout << std::setw(14) << "omega_rad_s" << std::setw(20) << "S_m2_s_per_rad"
              << "\n";
    for (std::size_t i = 0; i < omega.size(); ++i) {
      std::cout << std::setw(14) << omega[i] << std::setw(20) << std::setprecision(10) << values[i]
                << "\n";
    }
  }
  return kExitOk;
}
}  // namespace

Command add_spectrum_command(CLI::App& app) {
  auto options = std::make_shared<SpectrumOptions>();
  CLI::App* command =
      app.add_subcommand("spectrum", "Evaluate a one-sided wave spectrum S(omega), m^2 s/rad");
  add_spectrum_flags(*command, options->sea);
  add_option(*command, kOmega, options->omega, "angular frequencies W1,W2,..., rad/s");
  command->add_flag("--json", options->json, "print JSON {\"omega\":[...],\"S\":[...]}");
  command->add_option("--plot", options->plot_path,
                      "draw the sea-state figure (spectra, spreading, depth, dispersion) to a PNG");
  return {command, [options] { return run_spectrum(*options); }};
}

}  // namespace ocean::cli
