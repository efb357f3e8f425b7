// The sea-state parameter table (ocean/spectrum.hpp) drives the library's own range checks, and
// resolve() gives the default wind sea of default_sea_state(); ocean/parameters.hpp's messages.
#include "ocean/parameters.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "ocean/sim.hpp"
#include "ocean/spectrum.hpp"

namespace {

using ocean::FrequencySpectrum;
using ocean::FrequencySpectrumParams;
using ocean::SpectrumInputs;

// The table's closed range is exactly the range FrequencySpectrum::make accepts: the bounds pass,
// the next doubles outside them fail with a message naming the field.
void expect_range_is_the_check(std::string_view field, FrequencySpectrumParams base,
                               double FrequencySpectrumParams::*member) {
  const ocean::params::ParameterDoc& p = ocean::sea_state_parameter(field);
  for (const double v : {p.lo, p.hi}) {
    FrequencySpectrumParams q = base;
    q.*member = v;
    EXPECT_TRUE(FrequencySpectrum::make(q).ok()) << field << " = " << v;
  }
  for (const double v : {std::nextafter(p.lo, -1e300), std::nextafter(p.hi, 1e300)}) {
    FrequencySpectrumParams q = base;
    q.*member = v;
    const auto made = FrequencySpectrum::make(q);
    ASSERT_FALSE(made.ok()) << field << " = " << v;
    EXPECT_EQ(made.status().message().rfind(std::string(field) + " = ", 0), 0u)
        << made.status().message();
  }
}

TEST(SeaStateParameters, TheTableIsTheLibrarysRange) {
  const FrequencySpectrumParams hs_form{.model = ocean::SpectrumModel::jonswap,
                                        .significant_wave_height_m = 2.0,
                                        .peak_period_s = 9.0};
  FrequencySpectrumParams wind_form{
      .model = ocean::SpectrumModel::jonswap, .wind_speed_mps = 12.0, .fetch_m = 5e4};
  expect_range_is_the_check("significant_wave_height_m", hs_form,
                            &FrequencySpectrumParams::significant_wave_height_m);
  expect_range_is_the_check("peak_period_s", hs_form, &FrequencySpectrumParams::peak_period_s);
  expect_range_is_the_check("wind_speed_mps", wind_form, &FrequencySpectrumParams::wind_speed_mps);
  expect_range_is_the_check("fetch_m", wind_form, &FrequencySpectrumParams::fetch_m);
  expect_range_is_the_check("gamma", wind_form, &FrequencySpectrumParams::gamma);
  expect_range_is_the_check("gravity_mps2", wind_form, &FrequencySpectrumParams::gravity_mps2);
}

TEST(SeaStateParameters, FlagsReplaceFieldsInMessages) {
  EXPECT_EQ(ocean::params::with_flag_names("fetch_m = 0 is out of range, see --gamma and gamma",
                                           ocean::kSeaStateParameters),
            "--fetch = 0 is out of range, see --gamma and --gamma");
  // Only whole words: "my_fetch_m" and "fetch_mx" are other names.
  EXPECT_EQ(ocean::params::with_flag_names("my_fetch_m fetch_mx", ocean::kSeaStateParameters),
            "my_fetch_m fetch_mx");
}

TEST(SeaStateParameters, KeywordsReplaceFieldsAndFlagsInMessages) {
  using ocean::params::with_keyword_names;
  EXPECT_EQ(with_keyword_names("significant_wave_height_m and peak_period_s must be given together",
                               ocean::kSeaStateParameters),
            "hs and tp must be given together");
  EXPECT_EQ(with_keyword_names("--cutoff-length = -1 is out of range; see --gamma",
                               ocean::kSeaStateParameters),
            "cutoff_length = -1 is out of range; see gamma");
  // A placeholder after a flag becomes the value of an assignment; other words do not.
  EXPECT_EQ(with_keyword_names("needs --wind-speed MPS --fetch M, or --k K1,... (--depth the)",
                               ocean::kSeaStateParameters),
            "needs wind_speed=MPS fetch=M, or k=K1,... (depth the)");
  // Not a flag: inside a word, after a hyphen, or "--" alone.
  EXPECT_EQ(with_keyword_names("a--b x---y -- z --", ocean::kSeaStateParameters),
            "a--b x---y -- z --");
}

TEST(SeaStateParameters, NothingGivenIsTheDefaultSeaOfTheSimulation) {
  const FrequencySpectrumParams p = ocean::resolve(SpectrumInputs{}).value();
  const FrequencySpectrumParams sim = ocean::default_sea_state().wind_sea.spectrum;
  EXPECT_EQ(p.model, sim.model);
  EXPECT_EQ(p.wind_speed_mps, sim.wind_speed_mps);
  EXPECT_EQ(p.fetch_m, sim.fetch_m);
  // Pierson–Moskowitz takes no fetch; a given fetch is kept.
  EXPECT_TRUE(std::isnan(ocean::resolve({.model = "pierson-moskowitz"}).value().fetch_m));
  EXPECT_EQ(ocean::resolve({.fetch = 3e4}).value().fetch_m, 3e4);
  // Hs/Tp given: no default wind.
  EXPECT_TRUE(std::isnan(ocean::resolve({.hs = 2.0, .tp = 8.0}).value().wind_speed_mps));
}

TEST(SeaStateParameters, ResolveNamesTheFlags) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(ocean::resolve({.hs = nan, .tp = 3.0}).status().message(),
            "--hs = nan is out of range: must be a finite number");
  EXPECT_EQ(ocean::resolve({.model = "tma"}).status().message(),
            "tma needs --depth (water depth, m)");
  EXPECT_EQ(ocean::resolve({.fetch_law = "linear"}).status().message(),
            "--fetch-law = 'linear' is unknown: must be hasselmann or cube-root");
  EXPECT_EQ(ocean::resolve({.model = "x"}).status().message().rfind("--model: ", 0), 0u);
}

TEST(NumberParameters, OneMessageForm) {
  constexpr ocean::params::NumberOption<double> kWidth{
      .flag = "--width", .accept = ocean::params::Accept::integer_in_range, .lo = 1, .hi = 16384};
  EXPECT_EQ(ocean::params::parse(kWidth, "-3").status().message(),
            "--width = -3 is out of range: must be an integer in [1, 16384]");
  EXPECT_EQ(ocean::params::parse(kWidth, "12x").status().message(),
            "--width = '12x' is not a number");
  EXPECT_EQ(ocean::params::parse(kWidth, "640").value(), 640.0);
  constexpr ocean::params::NumberOption<double> kFps{.flag = "--fps",
                                                     .accept = ocean::params::Accept::in_range,
                                                     .lo = 1e-3,
                                                     .hi = 1e4,
                                                     .unit = "Hz"};
  EXPECT_EQ(ocean::params::check(kFps, 0.0, "0").message(),
            "--fps = 0 is out of range: must be in [0.001, 10000] Hz");
}

}  // namespace
