// The hull's foam (docs/waves.md W.20–W.21), measured on the layer's own foam field (the one the
// simulator adds to the sea's foam source and the renderer draws, M.7.9, R.19) of a boat going
// straight: the trail's half width at half maximum against b(s) = B/2·(1 + s/L)^n and its
// spreading exponent fitted from it against n (Tennekes & Lumley 1972, §4.2: ⅓ behind an
// axisymmetric body); the foam across each section, which spreading keeps and only ageing
// lowers, against C₀·(B/2)·√(π/ln 2)·e^{−s/(U·T)}; the trail's length (where its centreline falls
// to 5 %) against the root of the stated law found by bisection; the waterline foam on the
// footprint's rim; bad parameters refused by name.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "ocean/waves.hpp"

namespace {

using namespace ocean::waves;

constexpr double kL = 8.0, kB = 3.0, kU = 6.0, kT = 10.0;
constexpr double kBoatX = -25.0;  // the boat's centre; heading +x, so s = kBoatX − x
constexpr int kN = 800;           // 0.25 m cells over 200 m

struct Field {
  LocalFrame frame;
  double cell = 0.0;
  // Coverage at cell (col, row).
  [[nodiscard]] double at(int col, int row) const {
    return frame.foam[static_cast<std::size_t>(row) * kN + static_cast<std::size_t>(col)];
  }
};

const Field& field() {
  static const Field f = [] {
    LayerParams p;
    p.area = {.origin_m = {-190.0, -100.0}, .size_m = 200.0, .resolution = kN,
              .edge_fraction = 0.05};
    p.wakes.push_back({.x_m = kBoatX, .z_m = 0.0, .heading_deg = 0.0, .speed_mps = kU,
                       .hull_length_m = kL, .peak_height_m = 0.0,
                       .foam = {.beam_m = kB, .lifetime_s = kT}});
    Field out;
    out.cell = p.area.size_m / kN;
    auto layer = LocalLayer::make(std::move(p));
    EXPECT_TRUE(layer.ok());
    layer.value()->evaluate(0.0, out.frame);
    return out;
  }();
  return f;
}

// The column whose centres lie s metres behind the boat (s a multiple of the cell).
int column_at(double s) {
  const double x = kBoatX - s;
  return static_cast<int>(std::lround((x - (-190.0)) / field().cell - 0.5));
}

// How far behind the boat column col's centres lie.
double s_of(int col) { return kBoatX - (-190.0 + (col + 0.5) * field().cell); }

// Half width at half maximum of the section at column col: from the centreline (rows kN/2 − 1
// and kN/2 straddle ζ = 0) outwards to where the coverage crosses half its centre value, the
// crossing placed by linear interpolation between cells.
double measured_half_width(int col) {
  const Field& f = field();
  const double target = 0.5 * f.at(col, kN / 2);
  for (int row = kN / 2; row + 1 < kN; ++row) {
    const double a = f.at(col, row), b = f.at(col, row + 1);
    if (a >= target && b < target) {
      const double zeta_a = (row - kN / 2 + 0.5) * f.cell;
      return zeta_a + f.cell * (a - target) / (a - b);
    }
  }
  return 0.0;
}

TEST(HullFoam, TrailWidensAsTheStatedPowerLaw) {
  // The centreline sample sits half a cell off ζ = 0: its value is the centre's times
  // 2^{−(cell/2b)²}, which moves the half-maximum crossing by less than 0.4 % of b for b ≥ 1.5 m;
  // linear interpolation across a 0.25 m cell of a Gaussian whose curvature scale is b errs by
  // under 1 %. Allowed: 2 % of b.
  std::vector<double> log_s, log_b;
  for (double s : {8.0, 16.0, 32.0, 64.0, 128.0}) {
    const int col = column_at(s);
    const double b = measured_half_width(col);
    const double expected = trail_half_width_m({.beam_m = kB}, kL, s_of(col));
    EXPECT_NEAR(b, expected, 0.02 * expected) << "s = " << s;
    EXPECT_NEAR(expected, 0.5 * kB * std::cbrt(1.0 + s_of(col) / kL), 1e-12);
    log_s.push_back(std::log(1.0 + s_of(col) / kL));
    log_b.push_back(std::log(b));
  }
  // Least-squares slope of log b against log(1 + s/L): the spreading exponent n = ⅓.
  const double n = static_cast<double>(log_s.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < log_s.size(); ++i) {
    sx += log_s[i];
    sy += log_b[i];
    sxx += log_s[i] * log_s[i];
    sxy += log_s[i] * log_b[i];
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  EXPECT_NEAR(slope, 1.0 / 3.0, 0.01);
  // The trail's half-angle seen from the boat at 128 m: atan(b/s) = atan(1.5·17^{1/3}/128), 1.73°.
  const int c128 = column_at(128.0);
  const double s128 = s_of(c128);
  const double half_angle = std::atan(measured_half_width(c128) / s128) * 180.0 / std::numbers::pi;
  EXPECT_NEAR(half_angle,
              std::atan(1.5 * std::cbrt(1.0 + s128 / kL) / s128) * 180.0 / std::numbers::pi, 0.05);
  EXPECT_NEAR(half_angle, 1.73, 0.01);
}

TEST(HullFoam, SpreadingKeepsTheFoamAndAgeingLowersIt) {
  // ∫ C dζ over a section = C₀·(B/2)·√(π/ln 2)·e^{−s/(U·T)} (W.21): the integral of 2^{−(ζ/b)²}
  // is b·√(π/ln 2), and the spread foam's height falls as 1/b. Midpoint sums over 0.25 m cells
  // of a Gaussian of width ≥ 1.5 m are exact to far below 1e-6 (Euler–Maclaurin).
  const Field& f = field();
  for (double wanted : {12.0, 40.0, 100.0}) {
    const int col = column_at(wanted);
    const double s = s_of(col);  // the column's own distance, within half a cell of wanted
    double sum = 0.0;
    for (int row = 0; row < kN; ++row) sum += f.at(col, row) * f.cell;
    const double expected = 0.5 * kB * std::sqrt(std::numbers::pi / std::numbers::ln2) *
                            std::exp(-s / (kU * kT));
    EXPECT_NEAR(sum, expected, 2e-3 * expected) << "s = " << s;  // float storage: 1e-7 each
  }
}

TEST(HullFoam, TrailLengthIsWhereTheLawFallsToFivePercent) {
  // The law's centreline C₀·(1 + s/L)^{−n}·e^{−s/(U·T)} = 0.05, solved by bisection.
  const auto law = [](double s) { return std::exp(-s / (kU * kT)) / std::cbrt(1.0 + s / kL); };
  double lo = 0.0, hi = 170.0;
  for (int i = 0; i < 60; ++i) ((law(0.5 * (lo + hi)) > 0.05) ? lo : hi) = 0.5 * (lo + hi);
  const double root = lo;
  EXPECT_GT(root, 100.0);
  EXPECT_LT(root, 150.0);
  // Measured: the first cell behind the boat's centre whose centreline (the two rows straddling
  // ζ = 0) is below 5 %.
  const Field& f = field();
  double measured = -1.0;
  for (int col = column_at(4.0); col >= 0; --col) {
    const double c = std::max(f.at(col, kN / 2 - 1), f.at(col, kN / 2));
    if (c < 0.05) {
      measured = s_of(col);
      break;
    }
  }
  EXPECT_NEAR(measured, root, f.cell + 0.1);
}

TEST(HullFoam, WaterlineFoamOnTheFootprintsRim) {
  // Full inside the footprint; e^{−1} at B/4 beyond its beam (abeam: d = (r − 1)·B/2, w = B/4).
  const HullFoam foam{.beam_m = kB};
  EXPECT_DOUBLE_EQ(hull_foam_coverage(foam, kL, 0.0, 0.0, 1.4), 1.0);
  EXPECT_NEAR(hull_foam_coverage(foam, kL, 0.0, 0.0, 0.5 * kB + 0.25 * kB), std::exp(-1.0), 1e-12);
  // 1 m off the bow: r = 1.25, d = 0.375 m, e^{−(0.375/0.75)²}.
  EXPECT_NEAR(hull_foam_coverage(foam, kL, 0.0, -0.5 * kL - 1.0, 0.0), std::exp(-0.25), 1e-12);
  // Nothing without a beam; the layer's field holds the rim at the boat's side.
  EXPECT_EQ(hull_foam_coverage({}, kL, kU, 10.0, 0.0), 0.0);
  const Field& f = field();
  const int col = column_at(0.0);
  const int row_side = kN / 2 + static_cast<int>(std::lround(1.5 / f.cell));  // ζ ≈ B/2
  EXPECT_GT(f.at(col, row_side), 0.9);
}

// On a turn the trail follows the track (W.21b): a boat circling at radius 60 m, its path
// recorded every 2 s. At a point of the track 30 m of arc behind it the foam is the law's for
// s = 30 m on the centreline, exactly; 30 m straight behind along its present heading, about
// 7.5 m off the track, where a straight trail would put its centreline, little foam is left.
TEST(HullFoam, OnATurnTheTrailFollowsTheTrack) {
  constexpr double kR = 60.0, kDt = 2.0, kNow = 101.0;
  const double omega = kU / kR;  // rad/s, anticlockwise seen from +y: heading turns towards +z
  KelvinWake w{.hull_length_m = kL, .peak_height_m = 0.0, .foam = {.beam_m = kB, .lifetime_s = kT}};
  for (int i = 0; i <= 60; ++i) {
    const double t = i * kDt;
    w.path.push_back({.time_s = t, .x_m = kR * std::sin(omega * t),
                      .z_m = kR * (1.0 - std::cos(omega * t))});
  }
  LayerParams p;
  p.area = {.origin_m = {-200.0, -200.0}, .size_m = 400.0, .resolution = 16, .edge_fraction = 0.05};
  p.wakes.push_back(w);
  auto layer = LocalLayer::make(std::move(p));
  ASSERT_TRUE(layer.ok()) << layer.status().message();
  // The object's position now, on the chord between the waypoints at 100 s and 102 s (pose_at).
  const WakePose pose = pose_at(w, kNow);
  // Walk 30 m back along the polyline: now → waypoint at 100 s → 98 s → ...
  std::vector<std::array<double, 2>> track{{pose.x_m, pose.z_m}};
  for (int i = 50; i >= 0; --i) track.push_back({w.path[i].x_m, w.path[i].z_m});
  double left = 30.0;
  std::array<double, 2> on_track{};
  for (std::size_t i = 0; i + 1 < track.size(); ++i) {
    const double len = std::hypot(track[i + 1][0] - track[i][0], track[i + 1][1] - track[i][1]);
    if (left <= len) {
      const double f = left / len;
      on_track = {track[i][0] + f * (track[i + 1][0] - track[i][0]),
                  track[i][1] + f * (track[i + 1][1] - track[i][1])};
      break;
    }
    left -= len;
  }
  const double expected = hull_foam_coverage(w.foam, kL, pose.speed_mps, 30.0, 0.0);
  EXPECT_NEAR(layer.value()->foam_at(on_track[0], on_track[1], kNow), expected, 1e-9);
  EXPECT_GT(expected, 0.2);
  // Straight behind along the present heading.
  const double sx = pose.x_m - 30.0 * std::cos(pose.heading_rad),
               sz = pose.z_m - 30.0 * std::sin(pose.heading_rad);
  const double off = std::hypot(sx - 0.0, sz - kR) - kR;  // from the circle, ≈ 30²/(2R)
  EXPECT_GT(off, 6.0);
  const double straight = layer.value()->foam_at(sx, sz, kNow);
  EXPECT_LT(straight, 0.05 * expected) << "the trail lies straight behind the boat, not on its track";
}

TEST(HullFoam, FootprintsFoamTheirRimAtRestAndAreValidated) {
  // A footprint (an object at rest) foams as a hull of no speed: its rim, no trail (W.20).
  LayerParams p;
  p.area = {.origin_m = {-16.0, -16.0}, .size_m = 32.0, .resolution = 128};
  p.footprints.push_back({.x_m = 2.0, .z_m = 1.0, .heading_deg = 90.0, .length_m = 4.0,
                          .foam = {.beam_m = 2.0, .coverage = 0.5}});
  auto layer = LocalLayer::make(p);
  ASSERT_TRUE(layer.ok()) << layer.status().message();
  // Heading +z: 2 m along z to the ends, 1 m along x to the sides.
  EXPECT_DOUBLE_EQ(layer.value()->foam_at(2.0, 1.0, 0.0), 0.5);
  EXPECT_NEAR(layer.value()->foam_at(2.0 + 1.0 + 0.5, 1.0, 0.0), 0.5 * std::exp(-1.0), 1e-12);
  EXPECT_NEAR(layer.value()->foam_at(2.0, 1.0 - 2.0 - 1.0, 0.0),
              0.5 * std::exp(-(0.5 * 0.5) / (0.5 * 0.5)), 1e-12);  // r = 1.5 behind: d = 0.5
  p.footprints[0].length_m = 0.0;
  auto bad = LocalLayer::make(p);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("footprints[0].length_m"), std::string::npos);
}

TEST(HullFoam, BadParametersAreRefusedByName) {
  KelvinWake w;
  w.foam.beam_m = -1.0;
  EXPECT_NE(validate(w).message().find("foam.beam_m"), std::string::npos);
  w.foam = {.beam_m = 2.0, .coverage = 1.5};
  EXPECT_NE(validate(w).message().find("foam.coverage"), std::string::npos);
  w.foam = {.beam_m = 2.0, .lifetime_s = 0.0};
  EXPECT_NE(validate(w).message().find("foam.lifetime_s"), std::string::npos);
  w.foam = {.beam_m = 2.0, .spread_exponent = std::nan("")};
  EXPECT_NE(validate(w).message().find("foam.spread_exponent"), std::string::npos);
  EXPECT_FALSE(WakeTrack::make({.foam = {.rim_width_m = -1.0}}).ok());
}

}  // namespace
