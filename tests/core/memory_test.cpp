// Large-array storage: alignment, sizes either side of the huge-page threshold, and frames.
#include "ocean/memory.hpp"

#include <gtest/gtest.h>

#include <cstdint>

#include "ocean/sim.hpp"

namespace {

std::uintptr_t address(const void* p) { return reinterpret_cast<std::uintptr_t>(p); }

TEST(LargeVector, AlignedToCacheLinesAndHugePages) {
  constexpr std::size_t kMiB = std::size_t{1} << 20;
  for (std::size_t bytes : {std::size_t{4}, std::size_t{4000}, kMiB - 4, kMiB, 3 * kMiB + 4}) {
    ocean::LargeVector<float> v(bytes / sizeof(float));
    EXPECT_EQ(address(v.data()) % 64, 0u) << bytes;
    if (bytes >= kMiB) {
      EXPECT_EQ(address(v.data()) % (2 * kMiB), 0u) << bytes;
    }
    // Value-initialised and writable end to end.
    for (float x : v) ASSERT_EQ(x, 0.0f);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = float(i % 1000);
    EXPECT_EQ(v.back(), float((v.size() - 1) % 1000));
  }
  ocean::LargeVector<std::uint16_t> grow;
  for (int i = 0; i < 700000; ++i) grow.push_back(std::uint16_t(i));  // crosses the threshold
  EXPECT_EQ(grow[654321], std::uint16_t(654321));
  EXPECT_EQ(address(grow.data()) % 64, 0u);
}

TEST(LargeVector, FrameArraysStartOnCacheLines) {
  ocean::SimulationConfig config;
  config.resolution = 64;
  ocean::Frame frame;
  ocean::allocate_frame(config, frame);
  for (const ocean::CascadeFrame& c : frame.cascades) {
    EXPECT_EQ(address(c.displacement.data()) % 64, 0u);
    EXPECT_EQ(address(c.displacement_half.data()) % 64, 0u);
    EXPECT_EQ(address(c.normal.data()) % 64, 0u);
    EXPECT_EQ(address(c.jacobian.data()) % 64, 0u);
    EXPECT_EQ(address(c.foam.data()) % 64, 0u);
    EXPECT_EQ(address(c.packed_mips.data()) % 64, 0u);
  }
}

}  // namespace
