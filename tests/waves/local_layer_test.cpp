// The local layer's identities: a steady wake moves with its object without changing, turns with
// its heading, is mirror-symmetric about the track and zero ahead of the object; its horizontal
// displacement is the project's choppy sign; the soft edge; bad parameters; warnings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "ocean/waves.hpp"

namespace {

using ocean::waves::KelvinWake;
using ocean::waves::LayerParams;
using ocean::waves::LocalLayer;

constexpr double kLayerPi = std::numbers::pi;

// A 10 m boat at 4 m/s (Fr = 0.40) heading +x from (60, 0) at t = 0, in a 160 m area of 256²
// with a hard edge: the identities below are the pattern's own, not its soft edge's (W.9b).
LayerParams boat(double heading_deg = 0.0) {
  LayerParams p;
  p.area = {.origin_m = {-80.0, -80.0}, .size_m = 160.0, .resolution = 256, .edge_fraction = 0.0};
  p.wakes.push_back({.x_m = 60.0 * std::cos(heading_deg * kLayerPi / 180),
                     .z_m = 60.0 * std::sin(heading_deg * kLayerPi / 180),
                     .heading_deg = heading_deg,
                     .speed_mps = 4.0,
                     .hull_length_m = 10.0,
                     .peak_height_m = 0.5});
  return p;
}

std::unique_ptr<LocalLayer> make(LayerParams p) {
  auto layer = LocalLayer::make(std::move(p));
  EXPECT_TRUE(layer.ok()) << layer.status().message();
  return std::move(layer).value();
}

TEST(KelvinWake, SteadyWakeMovesWithItsObjectUnchanged) {
  const auto layer = make(boat());
  const double dt = 0.7, shift = 4.0 * dt;
  double largest = 0.0;
  for (double x = -40.0; x <= 40.0; x += 3.1) {
    for (double z = -30.0; z <= 30.0; z += 2.7) {
      const auto a = layer->displacement_at(x, z, 0.0);
      const auto b = layer->displacement_at(x + shift, z, dt);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-9) << x << ", " << z;
      largest = std::max(largest, std::abs(a[1]));
    }
  }
  EXPECT_GT(largest, 0.05);  // the comparison saw the wake, not an empty field
}

// An area the wake trails into from far behind its object (W.7): its heights and displacements
// are those a layer holding the object gives at the same points, on the same cells (0.39 m). The
// area lies 150–175 m behind a boat at Fr = 0.3, six times its own side: a table reaching twice
// the side behind the object would give it no wake at all.
TEST(KelvinWake, AnAreaFarBehindItsObjectSeesTheWakeOfALayerHoldingIt) {
  const KelvinWake wake{
      .x_m = 190.0, .z_m = 0.0, .heading_deg = 0.0, .speed_mps = 2.9714, .hull_length_m = 10.0};
  LayerParams holding;
  holding.area = {
      .origin_m = {-10.0, -100.0}, .size_m = 200.0, .resolution = 512, .edge_fraction = 0.0};
  holding.wakes = {wake};
  LayerParams far = holding;
  far.area = {.origin_m = {15.0, -5.0}, .size_m = 25.0, .resolution = 64, .edge_fraction = 0.0};
  const auto whole = make(holding), part = make(far);
  double largest = 0.0, differs = 0.0;
  for (double x = 15.5; x < 40.0; x += 0.37) {
    for (double z = -4.5; z < 20.0; z += 0.41) {
      const auto a = whole->displacement_at(x, z, 0.0), b = part->displacement_at(x, z, 0.0);
      for (int k = 0; k < 3; ++k) differs = std::max(differs, std::abs(a[k] - b[k]));
      largest = std::max(largest, std::abs(a[1]));
    }
  }
  EXPECT_GT(largest, 0.02);        // the wake is there, 150–175 m behind (peak 0.2 m)
  EXPECT_LT(differs, 1e-6 * 0.2);  // float rounding of the tables (normalised to 1)
}

TEST(KelvinWake, TurnsWithItsHeading) {
  const auto east = make(boat(0.0));
  const auto north = make(boat(90.0));
  for (double x = -40.0; x <= 40.0; x += 5.3) {
    for (double z = -30.0; z <= 30.0; z += 4.1) {
      const auto a = east->displacement_at(x, z, 0.0);
      const auto b = north->displacement_at(-z, x, 0.0);  // (x, z) turned by +90°
      EXPECT_NEAR(a[1], b[1], 1e-6);
      EXPECT_NEAR(a[0], b[2], 1e-6);   // Dx turns into Dz
      EXPECT_NEAR(a[2], -b[0], 1e-6);  // Dz turns into −Dx
    }
  }
}

TEST(KelvinWake, MirrorSymmetricAboutTheTrackAndZeroAhead) {
  const auto layer = make(boat());
  for (double x = -60.0; x <= 55.0; x += 2.9) {
    for (double z = 0.5; z <= 40.0; z += 3.3) {
      const auto left = layer->displacement_at(x, z, 0.0);
      const auto right = layer->displacement_at(x, -z, 0.0);
      EXPECT_NEAR(left[1], right[1], 1e-6);
      EXPECT_NEAR(left[0], right[0], 1e-6);
      EXPECT_NEAR(left[2], -right[2], 1e-6);
    }
  }
  for (double z = -30.0; z <= 30.0; z += 1.0) {
    const auto ahead = layer->displacement_at(60.5, z, 0.0);
    EXPECT_EQ(ahead[1], 0.0);
  }
}

TEST(KelvinWake, PeakHeightIsTheParameter) {
  const auto layer = make(boat());
  ocean::waves::LocalFrame frame;
  layer->evaluate(0.0, frame);
  double peak = 0.0;
  for (std::size_t i = 1; i < frame.displacement.size(); i += 3)
    peak = std::max(peak, std::abs(static_cast<double>(frame.displacement[i])));
  EXPECT_LE(peak, 0.5 * (1 + 1e-6));
  EXPECT_GE(peak, 0.5 * 0.9);  // sampled at cell centres, not at the table's nodes
}

// Along the track the transverse waves are plane waves along x: for h = A·cos(k·x) the project's
// displacement is Dx = −λ·A·sin(k·x) = (λ/k)·∂h/∂x (docs/math.md M.7.2).
TEST(KelvinWake, DisplacementSharpensCrestsLikeTheSea) {
  LayerParams p = boat();
  p.choppiness = 1.0;
  const auto layer = make(p);
  const double k0 = 9.81 / 16.0, dx = 0.01;
  double dot = 0.0, norm_d = 0.0, norm_h = 0.0;
  for (double x = 0.0; x >= -50.0; x -= 0.37) {
    const double d = layer->displacement_at(x, 0.0, 0.0)[0];
    const double slope = (layer->displacement_at(x + dx, 0.0, 0.0)[1] -
                          layer->displacement_at(x - dx, 0.0, 0.0)[1]) /
                         (2 * dx);
    dot += d * slope / k0;
    norm_d += d * d;
    norm_h += slope * slope / (k0 * k0);
  }
  EXPECT_GT(dot / std::sqrt(norm_d * norm_h), 0.9);
}

TEST(LocalArea, SoftEdgeIsZeroOnTheBorderAndOneInside) {
  const ocean::waves::LocalArea a{.origin_m = {10.0, 20.0}, .size_m = 100.0, .resolution = 64};
  EXPECT_EQ(ocean::waves::edge_weight(a, 10.0, 50.0), 0.0);
  EXPECT_EQ(ocean::waves::edge_weight(a, 60.0, 120.0), 0.0);
  EXPECT_EQ(ocean::waves::edge_weight(a, 9.0, 50.0), 0.0);
  EXPECT_EQ(ocean::waves::edge_weight(a, 60.0, 70.0), 1.0);
  EXPECT_NEAR(ocean::waves::edge_weight(a, 15.0, 70.0), 0.5, 1e-12);  // half the 10 m band
  const auto c = ocean::waves::cell_centre(a, 0, 63);
  EXPECT_DOUBLE_EQ(c[0], 10.0 + 0.5 * 100.0 / 64);
  EXPECT_DOUBLE_EQ(c[1], 20.0 + 63.5 * 100.0 / 64);
}

// No seam where an explicit square ends (W.9b): the wake of docs/rendering.md's pictures,
// `--kelvin-wake -120,0,0,6,40 --local-area -350,-200,400 --local-resolution 512` at t = 20 s,
// with the square's default soft edge (a tenth of its side). Its transverse waves are
// 2πU²/g = 23.06 m long, so the wakes fade over 4 of them, 92.2 m (0.2306 of the side), and
// across the square's own edge band (the outer 40 m, where the layer meets the sea) the layer
// changes no faster than the sea's own surface: its largest slope there (central differences on
// its grid) stays below half the rms slope along one direction of a clean sea at the calm
// preset's 4 m/s wind, √((0.003 + 5.12e-3·4)/2) = 0.108 (Cox & Munk 1954, JOSA 44(11), eq. 3),
// while the wake inside is steeper than that sea. With the wakes under the square's own 40 m edge
// the band's largest slope was 0.144.
TEST(LocalArea, AnExplicitSquaresWakeFadesIntoTheSeaWithoutASeam) {
  LayerParams p;
  p.area = {.origin_m = {-350.0, -200.0}, .size_m = 400.0, .resolution = 512};
  p.wakes.push_back(
      {.x_m = -120.0, .z_m = 0.0, .heading_deg = 0.0, .speed_mps = 6.0, .hull_length_m = 40.0});
  const auto layer = make(p);
  const double wavelength = 2.0 * kLayerPi * 36.0 / 9.81;
  EXPECT_NEAR(layer->wake_edge_fraction(), 4.0 * wavelength / 400.0, 1e-12);
  ocean::waves::LocalFrame frame;
  layer->evaluate(20.0, frame);
  const int n = p.area.resolution;
  const double cell = p.area.size_m / n, band = p.area.edge_fraction * p.area.size_m;
  const auto h = [&](int c, int r) {
    return static_cast<double>(frame.displacement[3 * (static_cast<std::size_t>(r) * n + c) + 1]);
  };
  double band_max = 0.0, inside_max = 0.0;
  for (int r = 1; r + 1 < n; ++r) {
    for (int c = 1; c + 1 < n; ++c) {
      const double g =
          std::hypot(h(c + 1, r) - h(c - 1, r), h(c, r + 1) - h(c, r - 1)) / (2 * cell);
      const double d = cell * (std::min({c, r, n - 1 - c, n - 1 - r}) + 0.5);
      double& m = d < band ? band_max : inside_max;
      m = std::max(m, g);
    }
  }
  const double sea_slope = std::sqrt((0.003 + 5.12e-3 * 4.0) / 2.0);
  std::printf("largest slope in the edge band %.4f, inside %.4f, sea rms %.4f\n", band_max,
              inside_max, sea_slope);
  EXPECT_GT(inside_max, sea_slope);  // the wake itself is steep enough to see
  EXPECT_LT(band_max, 0.5 * sea_slope);
  // The object 50 m from the square's front, inside the wakes' edge: the layer says so.
  const auto warned = layer->warnings(20.0);
  ASSERT_EQ(warned.size(), 1u);
  EXPECT_NE(warned[0].find("within the wakes' 92.2 m soft edge"), std::string::npos) << warned[0];
}

// The wakes' edge is 4 transverse wavelengths up to a quarter side, never narrower than the
// area's own; a hard edge asked for (edge_fraction 0) stays hard for the wakes too.
TEST(LocalArea, TheWakesEdgeSpansTheirWaves) {
  LayerParams p = boat();  // λ = 2π·4²/9.81 = 10.25 m, side 160 m
  EXPECT_EQ(make(p)->wake_edge_fraction(), 0.0);
  p.area.edge_fraction = 0.1;
  EXPECT_EQ(make(p)->wake_edge_fraction(), 0.25);  // 41 m capped at 40 m
  p.area.size_m = 400.0;
  EXPECT_NEAR(make(p)->wake_edge_fraction(), 4.0 * 2.0 * kLayerPi * 16.0 / 9.81 / 400.0, 1e-15);
  p.area.edge_fraction = 0.3;
  EXPECT_EQ(make(p)->wake_edge_fraction(), 0.3);
}

TEST(LocalLayer, BadParametersNameTheField) {
  const auto fails = [](LayerParams p, const std::string& says) {
    const auto layer = LocalLayer::make(std::move(p));
    ASSERT_FALSE(layer.ok()) << says;
    EXPECT_EQ(layer.status().code(), ocean::ErrorCode::invalid_argument);
    EXPECT_NE(layer.status().message().find(says), std::string::npos) << layer.status().message();
  };
  LayerParams p = boat();
  p.wakes[0].speed_mps = std::nan("");
  fails(p, "wakes[0].speed_mps");
  p = boat();
  p.wakes[0].speed_mps = -3.0;
  fails(p, "wakes[0].speed_mps = -3");
  p = boat();
  p.wakes[0].hull_length_m = -1.0;
  fails(p, "wakes[0].hull_length_m");
  p = boat();
  p.area.size_m = 0.0;
  fails(p, "local_area.size_m = 0");
  p = boat();
  p.area.resolution = 8;
  fails(p, "local_area.resolution = 8");
  p = boat();
  p.wakes[0].path = {{.time_s = 1.0}, {.time_s = 1.0, .x_m = 3.0}};
  fails(p, "waypoint times must increase");
  p = boat();
  p.waveforms.push_back({});
  fails(p, "waveforms[0]");
}

TEST(LocalLayer, WarnsAboutAnObjectOutsideTheArea) {
  LayerParams p = boat();
  EXPECT_TRUE(make(p)->warnings(0.0).empty());
  p.wakes[0].x_m = 500.0;
  const auto w = make(p)->warnings(0.0);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("outside the local area"), std::string::npos) << w[0];
}

TEST(KelvinWake, PathGivesPositionHeadingAndSpeed) {
  KelvinWake w;
  w.path = {{.time_s = 0.0, .x_m = 0.0, .z_m = 0.0},
            {.time_s = 10.0, .x_m = 0.0, .z_m = 50.0},
            {.time_s = 20.0, .x_m = 30.0, .z_m = 50.0}};
  const auto a = ocean::waves::pose_at(w, 4.0);
  EXPECT_DOUBLE_EQ(a.z_m, 20.0);
  EXPECT_DOUBLE_EQ(a.speed_mps, 5.0);
  EXPECT_NEAR(a.heading_rad, kLayerPi / 2, 1e-15);
  const auto b = ocean::waves::pose_at(w, 25.0);  // extrapolated along the last segment
  EXPECT_DOUBLE_EQ(b.x_m, 45.0);
  EXPECT_DOUBLE_EQ(b.speed_mps, 3.0);
}

}  // namespace
