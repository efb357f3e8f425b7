// The spectrum module's enum ⇄ name tables: every row round-trips through to_string and the
// parsers, the tables are in enum order, and unknown names are refused with the list of names.
#include <gtest/gtest.h>

#include "ocean/spectrum.hpp"

namespace {

using namespace ocean;

template <class E, std::size_t N>
void expect_enum_order(const std::array<EnumName<E>, N>& table) {
  for (std::size_t i = 0; i < N; ++i) EXPECT_EQ(static_cast<std::size_t>(table[i].value), i);
}

TEST(Names, SpectrumModelsRoundTrip) {
  expect_enum_order(kSpectrumModelNames);
  for (const auto& [model, name] : kSpectrumModelNames) {
    EXPECT_EQ(to_string(model), name);
    ASSERT_TRUE(parse_spectrum_model(name).ok()) << name;
    EXPECT_EQ(parse_spectrum_model(name).value(), model);
  }
  const Status bad = parse_spectrum_model("JONSWAP").status();
  EXPECT_EQ(bad.code(), ErrorCode::invalid_argument);
  EXPECT_EQ(bad.message(),
            "model = 'JONSWAP' is unknown: must be one of pierson-moskowitz, jonswap, tma, "
            "phillips");
}

TEST(Names, SpreadingModelsRoundTrip) {
  expect_enum_order(kSpreadingModelNames);
  for (const auto& [model, name] : kSpreadingModelNames) {
    EXPECT_EQ(to_string(model), name);
    ASSERT_TRUE(parse_spreading_model(name).ok()) << name;
    EXPECT_EQ(parse_spreading_model(name).value(), model);
  }
  EXPECT_EQ(parse_spreading_model("cos").status().message(),
            "spreading model = 'cos' is unknown: must be one of power-cosine, cos2s, mitsuyasu, "
            "hasselmann, donelan-banner");
}

// A name is echoed as ocean::excerpt writes it: a control character in a user's text cannot
// break the one-line message (found by tests/fuzz/cli_parse_fuzz.cpp through --model).
TEST(Names, UnknownNamesAreEchoedOnOneLine) {
  EXPECT_EQ(parse_spectrum_model("jon\rswap").status().message(),
            "model = 'jon\\rswap' is unknown: must be one of pierson-moskowitz, jonswap, tma, "
            "phillips");
  EXPECT_EQ(parse_spreading_model("cos\n2s").status().message(),
            "spreading model = 'cos\\n2s' is unknown: must be one of power-cosine, cos2s, "
            "mitsuyasu, hasselmann, donelan-banner");
}

TEST(Names, SeaStateOptionTables) {
  expect_enum_order(kFetchLawNames);
  expect_enum_order(kDepthFactorNames);
  expect_enum_order(kJonswapNormalizationNames);
  EXPECT_EQ(name_of(kFetchLawNames, FetchLaw::cube_root), "cube-root");
  EXPECT_EQ(value_of(kDepthFactorNames, "thompson-vincent"), DepthFactor::thompson_vincent);
  EXPECT_EQ(value_of(kJonswapNormalizationNames, "DNV"), std::nullopt);
  EXPECT_EQ(name_list(kFetchLawNames, ", ", " or ", "\""), "\"hasselmann\" or \"cube-root\"");
  EXPECT_EQ(name_list(kSpectrumModelNames, " | ", " | "),
            "pierson-moskowitz | jonswap | tma | phillips");
}

}  // namespace
