// float ↔ half conversion: IEEE-754 binary16 reference values, exhaustive round trips, and
// round-to-nearest-even against the compiler's own _Float16 conversion.
#include "ocean/half.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>

namespace {

// IEEE Std 754-2008 binary16 encodings.
TEST(Half, ReferenceEncodings) {
  EXPECT_EQ(ocean::float_to_half(0.0f), 0x0000);
  EXPECT_EQ(ocean::float_to_half(-0.0f), 0x8000);
  EXPECT_EQ(ocean::float_to_half(1.0f), 0x3c00);
  EXPECT_EQ(ocean::float_to_half(-2.0f), 0xc000);
  EXPECT_EQ(ocean::float_to_half(65504.0f), 0x7bff);               // largest finite
  EXPECT_EQ(ocean::float_to_half(65520.0f), 0x7c00);               // ties to even → inf
  EXPECT_EQ(ocean::float_to_half(std::ldexp(1.0f, -14)), 0x0400);  // smallest normal
  EXPECT_EQ(ocean::float_to_half(std::ldexp(1.0f, -24)), 0x0001);  // smallest subnormal
  EXPECT_EQ(ocean::float_to_half(std::ldexp(1.0f, -25)), 0x0000);  // ties to even → 0
  EXPECT_EQ(ocean::float_to_half(0.1f), 0x2e66);
  EXPECT_EQ(ocean::float_to_half(1.0f / 3.0f), 0x3555);
  EXPECT_EQ(ocean::float_to_half(INFINITY), 0x7c00);
  EXPECT_TRUE(std::isnan(ocean::half_to_float(ocean::float_to_half(NAN))));
}

TEST(Half, EveryHalfRoundTrips) {
  for (std::uint32_t h = 0; h < 0x10000u; ++h) {
    const auto bits = static_cast<std::uint16_t>(h);
    const float f = ocean::half_to_float(bits);
    if (std::isnan(f)) continue;
    EXPECT_EQ(ocean::float_to_half(f), bits) << std::hex << h;
  }
}

TEST(Half, RoundsLikeTheCompiler) {
  std::mt19937 rng(1);
  for (int i = 0; i < 1000000; ++i) {
    // Random floats across the half range, including subnormals and overflow.
    const float f =
        std::bit_cast<float>(static_cast<std::uint32_t>(0x30000000u + (rng() % 0x18000000u))) *
        ((rng() & 1u) ? -1.0f : 1.0f);
    __extension__ const _Float16 reference = static_cast<_Float16>(f);
    ASSERT_EQ(ocean::float_to_half(f), std::bit_cast<std::uint16_t>(reference)) << f;
  }
}

}  // namespace
