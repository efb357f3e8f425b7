// The roles of the bands (docs/math.md M.7.8): a shade-only band keeps its shading and leaves
// the surface where the other bands put it; a displace-only band moves the surface and leaves the
// shading flat. Checked against the same simulation with every band "both", by exact identities.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "ocean/backends.hpp"

namespace {

using ocean::BandRole;

ocean::SimulationConfig config_with(std::vector<BandRole> roles) {
  ocean::SimulationConfig c;
  c.resolution = 32;
  c.cascade_patch_sizes_m = {120.0, 29.0};
  c.choppiness = 1.3;
  c.seed = 11;
  c.band_roles = std::move(roles);
  return c;
}

std::unique_ptr<ocean::Simulator> stepped(std::vector<BandRole> roles) {
  auto sim = ocean::make_simulator(config_with(std::move(roles)), "cpu");
  EXPECT_TRUE(sim.ok()) << sim.status().message();
  sim.value()->step(0.0);
  sim.value()->step(2.5);
  return std::move(sim).value();
}

// World points spread over several cells of both cascades.
std::vector<std::array<double, 2>> points() {
  std::vector<std::array<double, 2>> p;
  for (int i = 0; i < 25; ++i) p.push_back({-40.0 + 7.3 * i, 13.0 - 5.1 * i});
  return p;
}

bool all_zero(const auto& values) {
  return std::all_of(values.begin(), values.end(), [](auto v) { return v == 0; });
}

TEST(BandRoles, ShadeOnlyBandKeepsItsShadingAndDoesNotMoveTheSurface) {
  const auto both = stepped({});
  const auto shade_high = stepped({BandRole::both, BandRole::shade});
  const auto shade_low = stepped({BandRole::shade, BandRole::both});
  const ocean::CascadeFrame& full = both->frame().cascades[1];
  const ocean::CascadeFrame& shaded = shade_high->frame().cascades[1];
  EXPECT_TRUE(all_zero(shaded.displacement));
  EXPECT_TRUE(all_zero(shaded.displacement_half));
  EXPECT_FALSE(all_zero(full.displacement));
  EXPECT_TRUE(std::equal(shaded.normal.begin(), shaded.normal.end(), full.normal.begin()));
  EXPECT_TRUE(std::equal(shaded.jacobian.begin(), shaded.jacobian.end(), full.jacobian.begin()));
  EXPECT_TRUE(std::equal(shaded.foam.begin(), shaded.foam.end(), full.foam.begin()));
  EXPECT_TRUE(
      std::equal(shaded.packed_mips.begin(), shaded.packed_mips.end(), full.packed_mips.begin()));
  // Each band's displacement is in exactly one of the two split surfaces: their sum is the full
  // surface, to the last bit (the zero band adds exactly 0).
  for (const auto& [x, z] : points()) {
    const auto a = shade_high->displacement_at(x, z);
    const auto b = shade_low->displacement_at(x, z);
    const auto sum = both->displacement_at(x, z);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(a[k] + b[k], sum[k]) << x << ", " << z;
  }
}

TEST(BandRoles, DisplaceOnlyBandMovesTheSurfaceAndShadesFlat) {
  const auto both = stepped({});
  const auto displaced = stepped({BandRole::both, BandRole::displace});
  const ocean::CascadeFrame& full = both->frame().cascades[1];
  const ocean::CascadeFrame& moved = displaced->frame().cascades[1];
  EXPECT_TRUE(
      std::equal(moved.displacement.begin(), moved.displacement.end(), full.displacement.begin()));
  for (std::size_t i = 0; i < moved.jacobian.size(); ++i) {
    ASSERT_EQ(moved.jacobian[i], 1.0f);
    ASSERT_EQ(moved.foam[i], 0.0f);
    ASSERT_EQ(moved.normal[3 * i + 0], 0.0f);
    ASSERT_EQ(moved.normal[3 * i + 1], 1.0f);
    ASSERT_EQ(moved.normal[3 * i + 2], 0.0f);
  }
  // Every packed texel, every mip: normal x and z at the middle code 128 (eq. 50: ⌊0.5·255 +
  // 0.5⌋), no foam in blue.
  for (std::uint32_t texel : moved.packed_mips) {
    ASSERT_EQ(texel & 0xffu, 128u);
    ASSERT_EQ((texel >> 8) & 0xffu, 128u);
    ASSERT_EQ((texel >> 16) & 0xffu, 0u);
  }
  EXPECT_FALSE(
      std::equal(moved.packed_mips.begin(), moved.packed_mips.end(), full.packed_mips.begin()));
  // The cascade the role leaves alone is the full simulation's, and so are the heights.
  EXPECT_TRUE(std::equal(displaced->frame().cascades[0].packed_mips.begin(),
                         displaced->frame().cascades[0].packed_mips.end(),
                         both->frame().cascades[0].packed_mips.begin()));
  const std::vector<std::array<double, 2>> xz = points();
  std::vector<ocean::HeightSample> h_both(xz.size()), h_moved(xz.size());
  both->heights_at(xz, h_both);
  displaced->heights_at(xz, h_moved);
  for (std::size_t q = 0; q < xz.size(); ++q) EXPECT_EQ(h_moved[q].height_m, h_both[q].height_m);
}

TEST(BandRoles, NamesParseAndACountOtherThanTheCascadesIsRefused) {
  auto roles = ocean::parse_band_roles("displace,both,shade");
  ASSERT_TRUE(roles.ok()) << roles.status().message();
  EXPECT_EQ(roles.value(),
            (std::vector<BandRole>{BandRole::displace, BandRole::both, BandRole::shade}));
  auto bad = ocean::parse_band_roles("both,shiny");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("'shiny'"), std::string::npos) << bad.status().message();
  EXPECT_FALSE(ocean::parse_band_roles("both,").ok());
  ocean::Status s = ocean::validate(config_with({BandRole::shade}));
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("one per cascade"), std::string::npos) << s.message();
}

}  // namespace
