// The LOD quality presets' name table.
#include <gtest/gtest.h>

#include "ocean/lod.hpp"

namespace {

using namespace ocean::lod;

TEST(Names, QualityPresetsRoundTrip) {
  for (std::size_t i = 0; i < kQualityPresetNames.size(); ++i) {
    const auto& [preset, name] = kQualityPresetNames[i];
    EXPECT_EQ(static_cast<std::size_t>(preset), i);
    EXPECT_EQ(preset_name(preset), name);
    ASSERT_TRUE(parse_preset(name).ok()) << name;
    EXPECT_EQ(parse_preset(name).value(), preset);
  }
  EXPECT_EQ(parse_preset("extreme").status().message(),
            "preset = extreme is not a preset: must be low, medium, high or ultra");
}

TEST(Names, UnknownPresetIsEchoedOnOneLine) {
  EXPECT_EQ(parse_preset("high\r").status().message(),
            "preset = high\\r is not a preset: must be low, medium, high or ultra");
}

}  // namespace
