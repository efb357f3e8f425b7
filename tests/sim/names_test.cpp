// The simulation config's enum ⇄ name tables: normal methods and blue-channel contents.
#include <gtest/gtest.h>

#include "ocean/sim.hpp"

namespace {

using namespace ocean;

TEST(Names, NormalMethodsRoundTrip) {
  for (std::size_t i = 0; i < kNormalMethodNames.size(); ++i) {
    const auto& [method, name] = kNormalMethodNames[i];
    EXPECT_EQ(static_cast<std::size_t>(method), i);
    EXPECT_EQ(to_string(method), name);
    ASSERT_TRUE(parse_normal_method(name).ok()) << name;
    EXPECT_EQ(parse_normal_method(name).value(), method);
  }
  EXPECT_EQ(parse_normal_method("fd").status().message(),
            "normals = 'fd' is unknown: must be one of central-difference, analytic, sobel");
}

TEST(Names, UnknownNormalMethodIsEchoedOnOneLine) {
  EXPECT_EQ(parse_normal_method("sobel\n").status().message(),
            "normals = 'sobel\\n' is unknown: must be one of central-difference, analytic, sobel");
}

TEST(Names, BlueChannelTable) {
  EXPECT_EQ(name_of(kBlueChannelNames, BlueChannel::foam), "foam");
  EXPECT_EQ(value_of(kBlueChannelNames, "jacobian"), BlueChannel::jacobian);
  EXPECT_EQ(name_list(kBlueChannelNames, ", ", " or "), "foam or jacobian");
}

}  // namespace
