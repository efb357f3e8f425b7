// Shared pieces of the ocean command-line tool (see cli_common.hpp).
#include "cli_common.hpp"

#include <cmath>
#include <iostream>
#include <tuple>
#include <utility>

namespace ocean::cli {

namespace {
const std::string kNoText;
}  // namespace

std::string flag_message(const Status& status) {
  return params::with_flag_names(status.message(), kSeaStateParameters);
}

int report(const Status& status) {
  std::cerr << "ocean: error: " << flag_message(status) << "\n";
  return status.code() == ErrorCode::invalid_argument ? kExitUsage : kExitFailure;
}

void add_spectrum_flags(CLI::App& command, SpectrumFlags& f) {
  const auto doc = [](std::string_view field) {
    return std::string(sea_state_parameter(field).doc);
  };
  command.add_option("--model", f.model, name_list(kSpectrumModelNames, " | ", " | "))
      ->capture_default_str();
  command.add_option("--hs", f.hs, doc("significant_wave_height_m"));
  command.add_option("--tp", f.tp, doc("peak_period_s"));
  command.add_option("--wind-speed", f.wind_speed, doc("wind_speed_mps"));
  command.add_option("--fetch", f.fetch, doc("fetch_m"));
  command.add_option("--gamma", f.gamma, doc("gamma"));
  command.add_option("--depth", f.depth, doc("depth_m"));
  command
      .add_option("--depth-factor", f.depth_factor,
                  name_list(kDepthFactorNames, " | ", " | ") + " (tma)")
      ->capture_default_str();
  command.add_option("--gravity", f.gravity, doc("gravity_mps2"));
  command
      .add_option("--fetch-law", f.fetch_law,
                  "hasselmann (2pi*3.5 (g/U)(gF/U^2)^-0.33) | cube-root (22 (g^2/(U F))^(1/3))")
      ->capture_default_str();
  command
      .add_option("--normalization", f.normalization,
                  "JONSWAP Hs/Tp normalisation: dnv (1 - 0.287 ln gamma) | exact")
      ->capture_default_str();
  command.add_option("--phillips-amplitude", f.phillips_amplitude, doc("phillips_amplitude"));
  command.add_option("--cutoff-length", f.cutoff_length, doc("small_wave_cutoff_m"));
}

Result<FrequencySpectrumParams> to_params(const SpectrumFlags& f) {
  SpectrumInputs in{.model = f.model,
                    .depth_factor = f.depth_factor,
                    .fetch_law = f.fetch_law,
                    .normalization = f.normalization};
  // An unknown model first, then the numbers' text, as resolve() reports the rest.
  if (Result<SpectrumModel> model = parse_spectrum_model(f.model); !model.ok())
    return Status(model.status().code(), "--model: " + model.status().message());
  const std::tuple<std::string_view, const std::string*, std::optional<double>*> scalars[] = {
      {"--hs", &f.hs, &in.hs},
      {"--tp", &f.tp, &in.tp},
      {"--wind-speed", &f.wind_speed, &in.wind_speed},
      {"--fetch", &f.fetch, &in.fetch},
      {"--depth", &f.depth, &in.depth},
      {"--gravity", &f.gravity, &in.gravity},
      {"--phillips-amplitude", &f.phillips_amplitude, &in.phillips_amplitude},
      {"--cutoff-length", &f.cutoff_length, &in.cutoff_length},
      {"--gamma", f.gamma == "auto" ? &kNoText : &f.gamma, &in.gamma}};
  for (const auto& [flag, text, value] : scalars) {
    if (text->empty()) continue;
    Result<double> v = parse(NumberOption<double>{.flag = flag}, *text);
    if (!v.ok()) return v.status();
    *value = v.value();
  }
  return resolve(in);
}

void print_json(const nlohmann::ordered_json& value) {
  // A file name need not be UTF-8: such bytes print as U+FFFD rather than throw.
  std::cout << value.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
}

}  // namespace ocean::cli
