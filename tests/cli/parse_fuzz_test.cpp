// Randomised (fuzz) tests of the command line's input parsers: any string gives either values
// or one clear error, never a crash, a NaN or a silent partial parse.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "cli_common.hpp"

namespace {

std::string random_text(std::mt19937_64& rng, std::string_view alphabet, int max_length) {
  std::uniform_int_distribution<int> length(0, max_length);
  std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1);
  std::string s(static_cast<std::size_t>(length(rng)), ' ');
  for (char& c : s) c = alphabet[pick(rng)];
  return s;
}

TEST(ParseFuzz, NumberListsParseFullyOrFailWithFlagName) {
  std::mt19937_64 rng(20261123);
  constexpr std::string_view kAlphabet = "0123456789,.,-+eEnaif x\t";
  for (int i = 0; i < 200000; ++i) {
    const std::string text = random_text(rng, kAlphabet, 24);
    const auto r = ocean::cli::parse_number_list("--omega", text);
    if (r.ok()) {
      ASSERT_FALSE(r.value().empty()) << text;
      // Every comma-separated item was consumed: one value per item.
      ASSERT_EQ(r.value().size(),
                static_cast<std::size_t>(std::count(text.begin(), text.end(), ',')) + 1)
          << text;
      for (double v : r.value()) ASSERT_FALSE(std::isnan(v)) << text;
    } else {
      ASSERT_EQ(r.status().code(), ocean::ErrorCode::invalid_argument);
      ASSERT_EQ(r.status().message().rfind("--omega", 0), 0u) << r.status().message();
      ASSERT_EQ(r.status().message().find('\n'), std::string::npos);
    }
  }
}

TEST(ParseFuzz, ArbitraryBytesNeverCrash) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> byte(0, 255);
  for (int i = 0; i < 50000; ++i) {
    std::string text(static_cast<std::size_t>(i % 40), '\0');
    for (char& c : text) c = static_cast<char>(byte(rng));
    const auto r = ocean::cli::parse_number(std::string_view("--hs"), text);
    if (r.ok()) {
      ASSERT_FALSE(std::isnan(r.value()));
    }
  }
}

// Random spectrum flag sets: either valid parameters that build a spectrum with finite
// non-negative values, or an invalid_argument naming a flag.
TEST(ParseFuzz, SpectrumFlagCombinations) {
  std::mt19937_64 rng(99);
  const char* models[] = {"pierson-moskowitz", "jonswap", "tma", "phillips", "bogus"};
  const char* numbers[] = {"",     "",    "0", "-1", "nan", "inf",
                           "1e-9", "0.5", "3", "12", "1e5", "1e300"};
  std::uniform_int_distribution<std::size_t> m(0, 4);
  std::uniform_int_distribution<std::size_t> n(0, std::size(numbers) - 1);
  for (int i = 0; i < 20000; ++i) {
    ocean::cli::SpectrumFlags f;
    f.model = models[m(rng)];
    f.hs = numbers[n(rng)];
    f.tp = numbers[n(rng)];
    f.wind_speed = numbers[n(rng)];
    f.fetch = numbers[n(rng)];
    f.gamma = numbers[n(rng)];
    f.depth = numbers[n(rng)];
    const auto params = ocean::cli::to_params(f);
    if (!params.ok()) {
      ASSERT_EQ(params.status().code(), ocean::ErrorCode::invalid_argument);
      continue;
    }
    const auto spectrum = ocean::FrequencySpectrum::make(params.value());
    if (!spectrum.ok()) {
      ASSERT_EQ(spectrum.status().code(), ocean::ErrorCode::invalid_argument);
      ASSERT_FALSE(spectrum.status().message().empty());
      continue;
    }
    for (double w : {0.1, 0.5, 1.0, 3.0, 30.0}) {
      const double s = spectrum.value()(w);
      ASSERT_TRUE(std::isfinite(s) && s >= 0.0)
          << f.model << " hs=" << f.hs << " tp=" << f.tp << " U=" << f.wind_speed << " w=" << w;
    }
  }
}

}  // namespace
