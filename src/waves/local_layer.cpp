// src/waves/local_layer.cpp — the local layer: validation, one Kelvin table per distinct (U, L)
// made up front (or shared with an earlier layer that has it, W.17), and the per-frame
// composition of wakes (tables moved and turned to each object's pose) and waveforms under the
// soft edge (W.7–W.10, the wakes' W.9b); a wake on a path laid along its track (W.21c).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "kelvin_table.hpp"
#include "ocean/waves.hpp"

namespace ocean::waves {

struct LocalLayer::Impl {
  /// Immutable once made, so layers share them (make's tables_from).
  std::vector<std::shared_ptr<const detail::KelvinTable>> tables;
  std::size_t computed = 0;  ///< how many of them make() computed
  /// Per wake: the tables of its speeds (one, or one per path segment speed).
  std::vector<std::vector<std::size_t>> wake_tables;
  /// Per wake and each of its tables: the pattern's peak height, m (peak_height_m, W.24, 0.02·L).
  std::vector<std::vector<double>> wake_amplitudes;
  /// Michell's scale c of W.24 per (hull, U, L, g), kept for layers remade from this one.
  struct Scale {
    std::shared_ptr<const ThinHull> hull;
    double speed_mps, hull_length_m, gravity_mps2, c;
  };
  std::vector<Scale> scales;
  /// The wakes' soft edge as a fraction of the side (W.9b): at least the area's own, wide enough
  /// for kWakeEdgeWavelengths of the longest transverse wave, at most kWakeEdgeMaxFraction.
  double wake_edge_fraction = 0.0;
};

namespace {

Status named(const std::string& prefix, const Status& s) {
  return s.ok() ? s : Status{s.code(), prefix + s.message()};
}

// The speeds a wake moves at: its own, or each path segment's.
std::vector<double> speeds_of(const KelvinWake& w) {
  if (w.path.size() < 2) return {w.speed_mps};
  std::vector<double> speeds;
  for (std::size_t i = 1; i < w.path.size(); ++i)
    speeds.push_back(pose_at(w, 0.5 * (w.path[i - 1].time_s + w.path[i].time_s)).speed_mps);
  return speeds;
}

// A wake's pose at one time with what the per-cell sum needs.
struct Placed {
  const detail::KelvinTable* table = nullptr;
  double x = 0.0, z = 0.0, cos_h = 1.0, sin_h = 0.0, amplitude_m = 0.0, fade_m = 0.0;
  double speed_mps = 0.0;
};

}  // namespace

LocalLayer::~LocalLayer() = default;

std::size_t LocalLayer::table_count() const { return impl_->tables.size(); }

std::size_t LocalLayer::tables_computed() const { return impl_->computed; }

double LocalLayer::wake_edge_fraction() const { return impl_->wake_edge_fraction; }

namespace {

// Speeds equal to 1e-6 share a table: a path at constant speed gives segment speeds that differ
// in their last bits (a circle of 5° chords, 400 of them, made 400 tables). A table that reaches
// at least as far serves.
bool same_table(const detail::KelvinTable& t, const detail::KelvinTableSpec& want) {
  return std::abs(t.speed_mps() - want.speed_mps) <= 1e-6 * want.speed_mps &&
         t.hull_length_m() == want.hull_length_m && t.gravity_mps2() == want.gravity_mps2 &&
         t.requested_spacing_m() == want.spacing_m &&
         t.length_m() - t.fade_m() >= want.length_m - want.fade_m;
}

// Whether the area meets the wedge |ζ| ≤ 0.5·s + w0, s ≥ 0 (26.6°, beyond the cusp's Airy tail,
// widened by the table's fringe w0) of a straight-course object at t = 0: two convex regions are
// apart exactly when their projections on one of their edges' normals are (separating axes).
bool meets_wedge(const std::array<std::array<double, 2>, 4>& corners, double w0) {
  const auto apart = [&](double ns, double nz) {  // along (ns, nz) in (s, ζ)
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& [cs, cz] : corners) {
      lo = std::min(lo, ns * cs + nz * cz);
      hi = std::max(hi, ns * cs + nz * cz);
    }
    // The wedge's projection: its front corners (0, ±w0) and its edges' directions (2, ±1).
    double w_lo = std::min(nz * w0, -nz * w0), w_hi = std::max(nz * w0, -nz * w0);
    for (const double side : {1.0, -1.0}) {
      const double along = 2.0 * ns + side * nz;
      if (along > 0.0) w_hi = std::numeric_limits<double>::infinity();
      if (along < 0.0) w_lo = -std::numeric_limits<double>::infinity();
    }
    return hi < w_lo || lo > w_hi;
  };
  const double c = corners[1][0] - corners[0][0], d = corners[1][1] - corners[0][1];
  return !(apart(1.0, 0.0) || apart(-0.5, 1.0) || apart(-0.5, -1.0) || apart(-d, c) || apart(c, d));
}

// How far behind its object a wake's table reaches (W.7): twice the area's side, or, for an
// object farther away whose wake meets the area at t = 0, to the farthest of the area's corners
// behind it (for a path, the farthest corner from any waypoint) and a fade more, in steps of a
// quarter side (a layer remade as a distant object moves on shares the table until it has gone a
// quarter side farther). The fade at its end: a tenth of it, at most a quarter side.
std::array<double, 2> table_length(const KelvinWake& w, const LocalArea& area, double gravity) {
  const double x0 = area.origin_m[0], z0 = area.origin_m[1], side = area.size_m;
  const std::array<std::array<double, 2>, 4> corners{
      {{x0, z0}, {x0 + side, z0}, {x0 + side, z0 + side}, {x0, z0 + side}}};
  double reach = 0.0;
  if (w.path.empty()) {
    const WakePose p = pose_at(w, 0.0);
    const double c = std::cos(p.heading_rad), sn = std::sin(p.heading_rad);
    std::array<std::array<double, 2>, 4> local{};  // (s, ζ) of the corners
    for (std::size_t i = 0; i < 4; ++i) {
      const double dx = corners[i][0] - p.x_m, dz = corners[i][1] - p.z_m;
      local[i] = {-(dx * c + dz * sn), -dx * sn + dz * c};
      reach = std::max(reach, local[i][0]);
    }
    const double wavelength = 2.0 * std::numbers::pi * p.speed_mps * p.speed_mps / gravity;
    if (!meets_wedge(local, 2.0 * wavelength + w.hull_length_m)) reach = 0.0;
  } else {
    for (const Waypoint& p : w.path)
      for (const auto& [x, z] : corners) reach = std::max(reach, std::hypot(x - p.x_m, z - p.z_m));
  }
  const double step = 0.25 * side;
  const double length = std::max(2.0 * side, step * std::ceil((reach + step) / step));
  return {length, std::min(0.1 * length, step)};
}

// (W.24) The factor c that makes the table's amplitude function c·A(θ) carry Michell's wave
// resistance of the wake's hull at the table's speed: (π/2)·ρ·U²·c²·∫A²cos³θ dθ = R.
double michell_scale(LocalLayer::Impl& impl, const KelvinWake& w, const detail::KelvinTable& t) {
  for (const LocalLayer::Impl::Scale& s : impl.scales) {
    if (s.hull == w.thin_hull && s.speed_mps == t.speed_mps() &&
        s.hull_length_m == t.hull_length_m() && s.gravity_mps2 == t.gravity_mps2())
      return s.c;
  }
  const double u = t.speed_mps();
  const double r = michell_resistance_per_density(*w.thin_hull, u, t.gravity_mps2());
  const double e = detail::KelvinTable::pattern_energy({.speed_mps = u,
                                                        .hull_length_m = t.hull_length_m(),
                                                        .gravity_mps2 = t.gravity_mps2()});
  const double c = e > 0.0 ? std::sqrt(r / (0.5 * std::numbers::pi * u * u * e)) : 0.0;
  impl.scales.push_back({w.thin_hull, u, t.hull_length_m(), t.gravity_mps2(), c});
  return c;
}

}  // namespace

Result<std::unique_ptr<LocalLayer>> LocalLayer::make(LayerParams params,
                                                     const LocalLayer* tables_from) {
  if (Status s = validate(params.area); !s.ok()) return s;
  if (Status s = require_finite("choppiness", params.choppiness); !s.ok()) return s;
  if (Status s = require_non_negative("choppiness", params.choppiness); !s.ok()) return s;
  if (Status s = require_positive("gravity_mps2", params.gravity_mps2); !s.ok()) return s;
  for (std::size_t i = 0; i < params.wakes.size(); ++i) {
    if (Status s = validate(params.wakes[i]); !s.ok())
      return named("wakes[" + std::to_string(i) + "].", s);
  }
  for (std::size_t i = 0; i < params.waveforms.size(); ++i) {
    if (Status s = validate(params.waveforms[i]); !s.ok())
      return named("waveforms[" + std::to_string(i) + "].", s);
  }
  for (std::size_t i = 0; i < params.footprints.size(); ++i) {
    if (Status s = validate(params.footprints[i]); !s.ok())
      return named("footprints[" + std::to_string(i) + "].", s);
  }
  std::unique_ptr<LocalLayer> layer(new LocalLayer());
  layer->impl_ = std::make_unique<Impl>();
  Impl& impl = *layer->impl_;
  // Each wake's speeds, with its table's reach; wakes of one (U, L) share the longest reach.
  std::vector<std::vector<detail::KelvinTableSpec>> wanted;
  for (const KelvinWake& w : params.wakes) {
    std::vector<detail::KelvinTableSpec>& specs = wanted.emplace_back();
    for (double speed : speeds_of(w)) {
      const auto [length, fade] = table_length(w, params.area, params.gravity_mps2);
      specs.push_back({.speed_mps = speed,
                       .hull_length_m = w.hull_length_m,
                       .gravity_mps2 = params.gravity_mps2,
                       .spacing_m = params.area.size_m / params.area.resolution,
                       .length_m = length,
                       .fade_m = fade});
    }
  }
  for (auto& specs : wanted) {
    for (detail::KelvinTableSpec& spec : specs) {
      for (const auto& other : wanted) {
        for (const detail::KelvinTableSpec& o : other) {
          if (std::abs(o.speed_mps - spec.speed_mps) <= 1e-6 * spec.speed_mps &&
              o.hull_length_m == spec.hull_length_m && o.length_m > spec.length_m) {
            spec.length_m = o.length_m;
            spec.fade_m = o.fade_m;
          }
        }
      }
    }
  }
  if (tables_from != nullptr) impl.scales = tables_from->impl_->scales;
  for (std::size_t w = 0; w < wanted.size(); ++w) {
    const auto& specs = wanted[w];
    std::vector<std::size_t> mine;
    for (const detail::KelvinTableSpec& spec : specs) {
      std::size_t found = impl.tables.size();
      for (std::size_t t = 0; t < impl.tables.size(); ++t) {
        if (same_table(*impl.tables[t], spec)) found = t;
      }
      if (found == impl.tables.size()) {
        std::shared_ptr<const detail::KelvinTable> table;
        if (tables_from != nullptr) {
          for (const auto& t : tables_from->impl_->tables)
            if (same_table(*t, spec)) table = t;
        }
        if (table == nullptr) {
          table = std::make_shared<const detail::KelvinTable>(detail::KelvinTable::make(spec));
          ++impl.computed;
        }
        impl.tables.push_back(std::move(table));
      }
      mine.push_back(found);
    }
    // (W.24) Each table's peak height for this wake.
    const KelvinWake& wake = params.wakes[w];
    std::vector<double> amplitudes;
    for (std::size_t t : mine) {
      const detail::KelvinTable& table = *impl.tables[t];
      if (wake.peak_height_m) {
        amplitudes.push_back(*wake.peak_height_m);
      } else if (wake.thin_hull != nullptr) {
        amplitudes.push_back(michell_scale(impl, wake, table) * table.raw_peak());
      } else {
        amplitudes.push_back(kDefaultPeakHeightPerLength * wake.hull_length_m);
      }
    }
    impl.wake_tables.push_back(std::move(mine));
    impl.wake_amplitudes.push_back(std::move(amplitudes));
  }
  // (W.9b) The wakes' soft edge: a square with a soft edge of its own (edge_fraction > 0) fades
  // each wake over at least kWakeEdgeWavelengths of its longest (transverse) wave, so that the
  // pattern's envelope changes slowly against its waves, and at most over kWakeEdgeMaxFraction
  // of the side; never over less than the area's own edge. A hard edge (0) stays hard.
  impl.wake_edge_fraction = params.area.edge_fraction;
  if (params.area.edge_fraction > 0.0) {
    double longest = 0.0;
    for (const auto& t : impl.tables) longest = std::max(longest, t->transverse_wavelength_m());
    impl.wake_edge_fraction = std::max(
        params.area.edge_fraction,
        std::min(kWakeEdgeWavelengths * longest / params.area.size_m, kWakeEdgeMaxFraction));
  }
  layer->params_ = std::move(params);
  return layer;
}

namespace {

Placed place(const KelvinWake& w, const std::vector<std::size_t>& tables,
             const std::vector<double>& amplitudes,
             const std::vector<std::shared_ptr<const detail::KelvinTable>>& all, double t) {
  const WakePose pose = pose_at(w, t);
  Placed p{.x = pose.x_m,
           .z = pose.z_m,
           .cos_h = std::cos(pose.heading_rad),
           .sin_h = std::sin(pose.heading_rad),
           .amplitude_m = amplitudes.front(),
           .fade_m = w.fade_length_m,
           .speed_mps = pose.speed_mps};
  p.table = all[tables.front()].get();
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const detail::KelvinTable* table = all[tables[i]].get();
    if (std::abs(table->speed_mps() - pose.speed_mps) <
        std::abs(p.table->speed_mps() - pose.speed_mps)) {
      p.table = table;
      p.amplitude_m = amplitudes[i];
    }
  }
  return p;
}

// (W.21b) The track an object on a path has left at time t, as pieces: the polyline from the
// placed position back through the waypoints already passed, newest first, continued straight
// beyond the oldest; without a path, the straight line of the heading. Each piece runs from
// (ax, az) backwards against the unit travel direction (ux, uz), `length` long (infinite: a
// ray), starting s0 metres behind the object; the first, `ahead`, runs forwards along the
// heading (s negative). Made once per placement, read for every point; with `reach`, the
// waypoints more than that far back along it are left out (a wake's table ends there, W.21c).
struct TrackPiece {
  double ax = 0.0, az = 0.0, ux = 1.0, uz = 0.0, length = 0.0, s0 = 0.0;
  bool ahead = false;
};

// Calls f(piece) for each piece of the track, newest first.
template <class F>
void for_each_piece(const KelvinWake& w, const Placed& p, double t, double reach, F&& f) {
  const double inf = std::numeric_limits<double>::infinity();
  f(TrackPiece{p.x, p.z, p.cos_h, p.sin_h, inf, 0.0, true});
  double ax = p.x, az = p.z, ux = p.cos_h, uz = p.sin_h, s0 = 0.0;
  if (w.path.size() >= 2) {
    for (std::size_t i = w.path.size(); i-- > 0;) {
      const Waypoint& q = w.path[i];
      if (!(q.time_s < t)) continue;  // not yet passed
      if (s0 > reach) break;          // beyond what the caller reads: the ray below ends it
      const double len = std::hypot(ax - q.x_m, az - q.z_m);
      if (len < 1e-9) continue;
      ux = (ax - q.x_m) / len, uz = (az - q.z_m) / len;
      f(TrackPiece{ax, az, ux, uz, len, s0, false});
      s0 += len, ax = q.x_m, az = q.z_m;
    }
  }
  f(TrackPiece{ax, az, ux, uz, inf, s0, false});  // beyond the oldest point passed
}

std::vector<TrackPiece> track_of(const KelvinWake& w, const Placed& p, double t,
                                 double reach = std::numeric_limits<double>::infinity()) {
  std::vector<TrackPiece> pieces;
  for_each_piece(w, p, t, reach, [&](const TrackPiece& k) { pieces.push_back(k); });
  return pieces;
}

// Where (x, z) lies along a track: s the arc length behind the object to the track's nearest
// point, ζ the distance from that point to the left of the travel there, and (ux, uz) the unit
// travel direction there.
struct TrackPoint {
  double s = 0.0, zeta = 0.0, ux = 1.0, uz = 0.0;
};

// Keeps in `out` the nearer of what it holds, `best` metres away, and (x, z)'s nearest point on k.
void nearer(const TrackPiece& k, double x, double z, double& best, TrackPoint& out) {
  const double dx = x - k.ax, dz = z - k.az;
  double u = k.ahead ? dx * k.ux + dz * k.uz : -(dx * k.ux + dz * k.uz);  // metres along it
  u = std::clamp(u, 0.0, k.length);
  const double qx = k.ahead ? k.ax + u * k.ux : k.ax - u * k.ux,
               qz = k.ahead ? k.az + u * k.uz : k.az - u * k.uz;
  const double d = std::hypot(x - qx, z - qz);
  if (d < best) {
    best = d;
    out = {k.ahead ? k.s0 - u : k.s0 + u, -(x - qx) * k.uz + (z - qz) * k.ux, k.ux, k.uz};
  }
}

TrackPoint track_point(const std::vector<TrackPiece>& track, double x, double z) {
  double best = std::numeric_limits<double>::infinity();
  TrackPoint out;
  for (const TrackPiece& k : track) nearer(k, x, z, best, out);
  return out;
}

std::array<double, 2> track_coordinates(const std::vector<TrackPiece>& track, double x, double z) {
  const TrackPoint q = track_point(track, x, z);
  return {q.s, q.zeta};
}

// Adds one placed wake's table value at (s, ζ) in its frame, whose travel direction is (ux, uz),
// to (Dx, h, Dz).
void add_wake_at(const Placed& p, double choppiness, double s, double zeta, double ux, double uz,
                 std::array<double, 3>& d) {
  const std::array<double, 3> v = p.table->sample(s, zeta);
  if (v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0) return;
  const double a = p.amplitude_m * (p.fade_m > 0.0 ? std::exp(-s / p.fade_m) : 1.0);  // (W.8)
  d[1] += a * v[0];
  // D_s points backwards (−travel), D_ζ to the left (travel turned +90°).
  const double c = choppiness * a;
  d[0] += c * (-v[1] * ux - v[2] * uz);
  d[2] += c * (-v[1] * uz + v[2] * ux);
}

// Adds one placed wake at world (x, z) to (Dx, h, Dz) in the frame of its present heading.
void add_wake(const Placed& p, double choppiness, double x, double z, std::array<double, 3>& d) {
  const double dx = x - p.x, dz = z - p.z;
  const double s = -(dx * p.cos_h + dz * p.sin_h);   // metres behind the object
  const double zeta = -dx * p.sin_h + dz * p.cos_h;  // metres to its left
  add_wake_at(p, choppiness, s, zeta, p.cos_h, p.sin_h, d);
}

// Whether a wake's pattern follows its track (W.21c): a wake on a path.
bool on_path(const KelvinWake& w) { return w.path.size() >= 2; }

// One hull's foam at world (x, z) (W.20–W.21), in the frame of its track (W.21b).
double hull_foam(const KelvinWake& w, const Placed& p, const std::vector<TrackPiece>& track,
                 double x, double z) {
  const auto [s, zeta] = track_coordinates(track, x, z);
  return hull_foam_coverage(w.foam, w.hull_length_m, p.speed_mps, s, zeta);
}

// The footprints' waterline foam at world (x, z) (W.20).
double footprint_foam(const std::vector<Footprint>& footprints, double x, double z) {
  double c = 0.0;
  for (const Footprint& f : footprints) {
    const double h = f.heading_deg * std::numbers::pi / 180.0;
    const double dx = x - f.x_m, dz = z - f.z_m;
    const double cos_h = std::cos(h), sin_h = std::sin(h);
    c = std::max(c, hull_foam_coverage(f.foam, f.length_m, 0.0, -(dx * cos_h + dz * sin_h),
                                       -dx * sin_h + dz * cos_h));
  }
  return c;
}

// The waveforms' height at world (x, z).
double waveforms_at(const std::vector<Waveform>& waveforms, double x, double z, double time_s) {
  double h = 0.0;
  for (const Waveform& w : waveforms) h += waveform_height(w, x, z, time_s);
  return h;
}

// (W.9b) The wakes' soft-edge weight at world (x, z): the area's own where the two edges agree.
double wake_weight(const LocalArea& area, double wake_edge_fraction, double weight, double x,
                   double z) {
  if (wake_edge_fraction == area.edge_fraction) return weight;
  LocalArea wide = area;
  wide.edge_fraction = wake_edge_fraction;
  return edge_weight(wide, x, z);
}

// The layer's (Dx, h, Dz) from the wakes' sum d and the waveforms' height h: the wakes under
// their soft edge (W.9b), the waveforms under the area's (W.9).
void finish(std::array<double, 3>& d, double h, double weight, double wake_weight) {
  for (double& v : d) v *= wake_weight;
  d[1] += weight * h;
}

}  // namespace

double LocalLayer::foam_at(double x, double z, double time_s) const {
  const double weight = edge_weight(params_.area, x, z);
  if (weight == 0.0) return 0.0;
  double c = footprint_foam(params_.footprints, x, z);
  for (std::size_t i = 0; i < params_.wakes.size(); ++i) {
    const KelvinWake& w = params_.wakes[i];
    if (w.foam.beam_m > 0.0) {
      const Placed p =
          place(w, impl_->wake_tables[i], impl_->wake_amplitudes[i], impl_->tables, time_s);
      c = std::max(c, hull_foam(w, p, track_of(w, p, time_s), x, z));
    }
  }
  return weight * c;
}

std::array<double, 3> LocalLayer::displacement_at(double x, double z, double time_s) const {
  std::array<double, 3> d{0.0, 0.0, 0.0};
  const double weight = edge_weight(params_.area, x, z);
  if (weight == 0.0) return d;
  for (std::size_t i = 0; i < params_.wakes.size(); ++i) {
    const KelvinWake& w = params_.wakes[i];
    const Placed p =
        place(w, impl_->wake_tables[i], impl_->wake_amplitudes[i], impl_->tables, time_s);
    if (on_path(w)) {
      double best = std::numeric_limits<double>::infinity();
      TrackPoint q;
      for_each_piece(w, p, time_s, p.table->length_m(),
                     [&](const TrackPiece& k) { nearer(k, x, z, best, q); });
      add_wake_at(p, params_.choppiness, q.s, q.zeta, q.ux, q.uz, d);
    } else {
      add_wake(p, params_.choppiness, x, z, d);
    }
  }
  finish(d, waveforms_at(params_.waveforms, x, z, time_s), weight,
         wake_weight(params_.area, impl_->wake_edge_fraction, weight, x, z));
  return d;
}

void LocalLayer::evaluate(double time_s, LocalFrame& out) const {
  const LocalArea& area = params_.area;
  const auto n = static_cast<std::size_t>(area.resolution);
  out.time_s = time_s;
  out.area = area;
  out.displacement.assign(3 * n * n, 0.0f);
  out.foam.assign(n * n, 0.0f);
  std::vector<Placed> placed;
  std::vector<std::vector<TrackPiece>> tracks;
  for (std::size_t i = 0; i < params_.wakes.size(); ++i) {
    placed.push_back(place(params_.wakes[i], impl_->wake_tables[i], impl_->wake_amplitudes[i], impl_->tables, time_s));
    // The foam's track reaches as far as the foam does; a pattern's, as far as its table.
    tracks.push_back(track_of(params_.wakes[i], placed.back(), time_s,
                              params_.wakes[i].foam.beam_m > 0.0
                                  ? std::numeric_limits<double>::infinity()
                                  : placed.back().table->length_m()));
  }
  for (std::size_t row = 0; row < n; ++row) {
    for (std::size_t col = 0; col < n; ++col) {
      const auto [x, z] = cell_centre(area, static_cast<int>(col), static_cast<int>(row));
      const double weight = edge_weight(area, x, z);
      if (weight == 0.0) continue;
      std::array<double, 3> d{0.0, 0.0, 0.0};
      double foam = footprint_foam(params_.footprints, x, z);
      for (std::size_t i = 0; i < placed.size(); ++i) {
        const KelvinWake& w = params_.wakes[i];
        const bool foams = w.foam.beam_m > 0.0;
        if (!on_path(w)) add_wake(placed[i], params_.choppiness, x, z, d);
        if (!on_path(w) && !foams) continue;
        // One nearest point on the track serves the pattern (W.21c) and the foam (W.21b).
        const TrackPoint q = track_point(tracks[i], x, z);
        if (on_path(w)) add_wake_at(placed[i], params_.choppiness, q.s, q.zeta, q.ux, q.uz, d);
        if (foams) {
          foam = std::max(
              foam, hull_foam_coverage(w.foam, w.hull_length_m, placed[i].speed_mps, q.s, q.zeta));
        }
      }
      finish(d, waveforms_at(params_.waveforms, x, z, time_s), weight,
             wake_weight(area, impl_->wake_edge_fraction, weight, x, z));
      float* cell = out.displacement.data() + 3 * (row * n + col);
      for (std::size_t k = 0; k < 3; ++k) cell[k] = static_cast<float>(d[k]);
      out.foam[row * n + col] = static_cast<float>(weight * foam);
    }
  }
}

std::vector<std::string> LocalLayer::warnings(double time_s) const {
  const LocalArea& a = params_.area;
  const auto inside = [&](double x, double z) {
    return x >= a.origin_m[0] && x <= a.origin_m[0] + a.size_m && z >= a.origin_m[1] &&
           z <= a.origin_m[1] + a.size_m;
  };
  std::string box("[");
  box.append(format_number(a.origin_m[0])).append(", ");
  box.append(format_number(a.origin_m[0] + a.size_m)).append("] x [");
  box.append(format_number(a.origin_m[1])).append(", ");
  box.append(format_number(a.origin_m[1] + a.size_m)).append("]");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < params_.wakes.size(); ++i) {
    const WakePose p = pose_at(params_.wakes[i], time_s);
    const std::string name = "wake " + std::to_string(i + 1);
    if (!inside(p.x_m, p.z_m)) {
      out.push_back(name + " at (" + format_number(p.x_m) + ", " + format_number(p.z_m) +
                    ") is outside the local area " + box + " at t = " + format_number(time_s) +
                    " s; only what trails into the area shows");
    } else if (const double band = impl_->wake_edge_fraction * a.size_m,
               in = std::min({p.x_m - a.origin_m[0], a.origin_m[0] + a.size_m - p.x_m,
                              p.z_m - a.origin_m[1], a.origin_m[1] + a.size_m - p.z_m});
               in < band) {
      const auto tenth = [](double v) { return format_number(std::round(10.0 * v) / 10.0); };
      out.push_back(name + " at (" + format_number(p.x_m) + ", " + format_number(p.z_m) + ") is " +
                    tenth(in) + " m inside the local area's border, within the wakes' " +
                    tenth(band) + " m soft edge at t = " + format_number(time_s) +
                    " s; its waves near the hull are weakened");
    }
    for (std::size_t t : impl_->wake_tables[i]) {
      const detail::KelvinTable& table = *impl_->tables[t];
      if (table.unresolved()) {
        out.push_back(name + ": its waves (" + format_number(table.transverse_wavelength_m()) +
                      " m) are shorter than the local grid resolves (3 cells of " +
                      format_number(table.spacing_m()) + " m); it is left out");
      } else if (table.transverse_wavelength_m() < 9.0 * table.spacing_m()) {
        // The cusp waves, 2/3 of the transverse wavelength, fall in the taper below 6 cells (W.5).
        out.push_back(name + ": its cusp waves (" +
                      format_number(2.0 / 3.0 * table.transverse_wavelength_m()) +
                      " m) are shorter than 6 cells of the local grid (" +
                      format_number(table.spacing_m()) +
                      " m) and are weakened: the wake looks narrower than Kelvin's 19.5°; a finer "
                      "grid shows them");
      }
    }
  }
  for (std::size_t i = 0; i < params_.waveforms.size(); ++i) {
    const Waveform& w = params_.waveforms[i];
    if (!inside(w.x_m, w.z_m)) {
      out.push_back("waveform " + std::to_string(i + 1) + " centred at (" + format_number(w.x_m) +
                    ", " + format_number(w.z_m) + ") is outside the local area " + box);
    }
  }
  return out;
}

}  // namespace ocean::waves
