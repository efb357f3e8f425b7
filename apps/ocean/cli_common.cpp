// Shared pieces of the ocean command-line tool (see cli_common.hpp).
#include "cli_common.hpp"

#include <cmath>
#include <iostream>
#include <tuple>
#include <utility>

namespace ocean::cli {

namespace {
// Library parameter names and the flags that set them, so messages speak the user's language.
constexpr std::pair<std::string_view, std::string_view> kFlagNames[] = {
    {"significant_wave_height_m", "--hs"},
    {"peak_period_s", "--tp"},
    {"wind_speed_mps", "--wind-speed"},
    {"fetch_m", "--fetch"},
    {"gamma", "--gamma"},
    {"depth_m", "--depth"},
    {"gravity_mps2", "--gravity"},
    {"phillips_amplitude", "--phillips-amplitude"},
    {"small_wave_cutoff_m", "--cutoff-length"},
    {"alpha", "--alpha"},
};

const std::string kNoText;

// "<flag> = '<text>' is unknown: must be a or b".
template <class E, std::size_t N>
Result<E> parse_name(std::string_view flag, const std::array<EnumName<E>, N>& table,
                     const std::string& text) {
  if (std::optional<E> value = value_of(table, text)) return *value;
  return invalid_argument(std::string(flag) + " = '" + excerpt(text) + "' is unknown: must be " +
                          name_list(table, ", ", " or "));
}

bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string with_flag_names(std::string message) {
  for (const auto& [field, flag] : kFlagNames) {
    std::size_t pos = 0;
    while ((pos = message.find(field, pos)) != std::string::npos) {
      const std::size_t end = pos + field.size();
      // Not already a flag: "--gamma" stays as it is.
      const bool starts = pos == 0 || !(is_word_char(message[pos - 1]) || message[pos - 1] == '-');
      const bool ends = end == message.size() || !is_word_char(message[end]);
      if (starts && ends) {
        message.replace(pos, field.size(), flag);
        pos += flag.size();
      } else {
        pos = end;
      }
    }
  }
  return message;
}
}  // namespace

std::string flag_message(const Status& status) { return with_flag_names(status.message()); }

int report(const Status& status) {
  std::cerr << "ocean: error: " << flag_message(status) << "\n";
  return status.code() == ErrorCode::invalid_argument ? kExitUsage : kExitFailure;
}

void add_spectrum_flags(CLI::App& command, SpectrumFlags& f) {
  command.add_option("--model", f.model, name_list(kSpectrumModelNames, " | ", " | "))
      ->capture_default_str();
  command.add_option("--hs", f.hs, "significant wave height Hs, m (with --tp)");
  command.add_option("--tp", f.tp, "peak period Tp, s (with --hs)");
  command.add_option("--wind-speed", f.wind_speed,
                     "wind speed, m/s: U10 (U19.5 for pierson-moskowitz)");
  command.add_option("--fetch", f.fetch, "fetch, m (jonswap/tma from wind)");
  command.add_option("--gamma", f.gamma, "JONSWAP peak enhancement, >= 1, or 'auto'");
  command.add_option("--depth", f.depth, "water depth, m (tma)");
  command
      .add_option("--depth-factor", f.depth_factor,
                  name_list(kDepthFactorNames, " | ", " | ") + " (tma)")
      ->capture_default_str();
  command.add_option("--gravity", f.gravity, "gravitational acceleration, m/s^2 (default 9.81)");
  command
      .add_option("--fetch-law", f.fetch_law,
                  "hasselmann (2pi*3.5 (g/U)(gF/U^2)^-0.33) | cube-root (22 (g^2/(U F))^(1/3))")
      ->capture_default_str();
  command
      .add_option("--normalization", f.normalization,
                  "JONSWAP Hs/Tp normalisation: dnv (1 - 0.287 ln gamma) | exact")
      ->capture_default_str();
  command.add_option("--phillips-amplitude", f.phillips_amplitude,
                     "Phillips amplitude A (dimensionless; default: Hs of Pierson-Moskowitz)");
  command.add_option("--cutoff-length", f.cutoff_length,
                     "Phillips small-wave cutoff length l, m (factor exp(-k^2 l^2))");
}

Result<FrequencySpectrumParams> to_params(const SpectrumFlags& f) {
  FrequencySpectrumParams p;
  Result<SpectrumModel> model = parse_spectrum_model(f.model);
  if (!model.ok()) return Status(model.status().code(), "--model: " + model.status().message());
  p.model = model.value();
  // Any number but NaN: FrequencySpectrum::make checks the values and names the flags.
  const std::tuple<std::string_view, const std::string*, double*> scalars[] = {
      {"--hs", &f.hs, &p.significant_wave_height_m},
      {"--tp", &f.tp, &p.peak_period_s},
      {"--wind-speed", &f.wind_speed, &p.wind_speed_mps},
      {"--fetch", &f.fetch, &p.fetch_m},
      {"--depth", &f.depth, &p.depth_m},
      {"--gravity", &f.gravity, &p.gravity_mps2},
      {"--phillips-amplitude", &f.phillips_amplitude, &p.phillips_amplitude},
      {"--cutoff-length", &f.cutoff_length, &p.small_wave_cutoff_m},
      {"--gamma", f.gamma == "auto" ? &kNoText : &f.gamma, &p.gamma}};
  for (const auto& [flag, text, value] : scalars) {
    if (text->empty()) continue;
    Result<double> v = parse(NumberOption<double>{.flag = flag}, *text);
    if (!v.ok()) return v.status();
    *value = v.value();
  }
  Result<DepthFactor> depth_factor =
      parse_name("--depth-factor", kDepthFactorNames, f.depth_factor);
  if (!depth_factor.ok()) return depth_factor.status();
  p.depth_factor = depth_factor.value();
  Result<FetchLaw> fetch_law = parse_name("--fetch-law", kFetchLawNames, f.fetch_law);
  if (!fetch_law.ok()) return fetch_law.status();
  p.fetch_law = fetch_law.value();
  Result<JonswapNormalization> normalization =
      parse_name("--normalization", kJonswapNormalizationNames, f.normalization);
  if (!normalization.ok()) return normalization.status();
  p.normalization = normalization.value();
  if (f.hs.empty() && f.tp.empty() && f.wind_speed.empty()) {
    // The default sea state: a fresh breeze over a long fetch.
    p.wind_speed_mps = 10.0;
    if (p.model == SpectrumModel::jonswap || p.model == SpectrumModel::tma) {
      if (f.fetch.empty()) p.fetch_m = 100e3;
    }
  }
  if (p.model == SpectrumModel::tma && f.depth.empty()) {
    return invalid_argument("tma needs --depth (water depth, m)");
  }
  return p;
}

void print_json(const nlohmann::ordered_json& value) {
  // A file name need not be UTF-8: such bytes print as U+FFFD rather than throw.
  std::cout << value.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
}

}  // namespace ocean::cli
