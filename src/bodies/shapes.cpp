// The built-in hulls: a subdivided box, a buoy (closed cylinder) and a procedural boat, each
// closed, wound counter-clockwise seen from outside and centred on its centre of volume.
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include "body_math.hpp"
#include "ocean/bodies.hpp"

namespace ocean::bodies {

namespace {

// Builds a mesh from triangles given by positions, merging equal positions (exact comparison:
// the shapes compute shared vertices by the same expression) so that neighbours share indices.
class MeshBuilder {
 public:
  // Adds triangle (a, b, c), flipped if needed so that its normal points along `outward`.
  void triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& outward) {
    wound(a, b, c, dot(cross(sub(b, a), sub(c, a)), outward) < 0.0);
  }
  // Adds triangle (a, b, c) as given, or (a, c, b) when `flip`; skips a degenerate one (a
  // collapsed ring at a boat's bow), which closes the mesh without it.
  void wound(const Vec3& a, const Vec3& b, const Vec3& c, bool flip) {
    if (norm(cross(sub(b, a), sub(c, a))) == 0.0) return;
    const std::uint32_t ia = index(a), ib = index(b), ic = index(c);
    if (ia == ib || ib == ic || ia == ic) return;
    hull_.triangles.push_back(flip ? std::array{ia, ic, ib} : std::array{ia, ib, ic});
  }
  // A quad a-b-c-d as two triangles.
  void quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& outward) {
    triangle(a, b, c, outward);
    triangle(a, c, d, outward);
  }
  // The finished hull, moved to its centre of volume.
  Hull centred() { return translated(std::move(hull_), mass_properties(hull_).centroid_m); }
  // The finished mesh as built.
  Hull raw() { return std::move(hull_); }
  // A convex block from its 8 corners (bottom face 0–3, top face 4–7, each in order round the
  // face, corner i + 4 above corner i), every face wound outwards from the block's centre.
  void block(const std::array<Vec3, 8>& c) {
    Vec3 centre{};
    for (const Vec3& p : c) centre = add(centre, scale(p, 0.125));
    const auto face = [&](int a, int b, int d, int e) {
      const Vec3 mid = scale(add(add(c[a], c[b]), add(c[d], c[e])), 0.25);
      quad(c[a], c[b], c[d], c[e], sub(mid, centre));
    };
    face(0, 1, 2, 3);
    face(4, 5, 6, 7);
    for (int i = 0; i < 4; ++i) face(i, (i + 1) % 4, (i + 1) % 4 + 4, i + 4);
  }

 private:
  std::uint32_t index(const Vec3& p) {
    auto [it, inserted] = lookup_.try_emplace(p, static_cast<std::uint32_t>(hull_.vertices.size()));
    if (inserted) hull_.vertices.push_back(p);
    return it->second;
  }
  Hull hull_;
  std::map<Vec3, std::uint32_t> lookup_;
};

Status positive_size(const char* name, double value) { return require_positive(name, value); }

}  // namespace

Result<Hull> box_hull(const Vec3& size_m, int subdivisions) {
  static constexpr const char* kNames[3] = {"box size x", "box size y", "box size z"};
  for (std::size_t i = 0; i < 3; ++i)
    if (Status s = positive_size(kNames[i], size_m[i]); !s.ok()) return s;
  if (subdivisions < 1 || subdivisions > 64)
    return invalid_argument("box subdivisions = " + std::to_string(subdivisions) +
                            " is out of range: [1, 64]");
  MeshBuilder mesh;
  const int n = subdivisions;
  const auto coord = [&](std::size_t axis, int i) { return size_m[axis] * (i / double(n) - 0.5); };
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const std::size_t u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (double side : {-0.5, 0.5}) {
      Vec3 outward{};
      outward[axis] = side;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const auto corner = [&](int a, int b) {
            Vec3 p{};
            p[axis] = size_m[axis] * side;
            p[u] = coord(u, a);
            p[v] = coord(v, b);
            return p;
          };
          mesh.quad(corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1),
                    outward);
        }
    }
  }
  return mesh.centred();
}

Result<Hull> buoy_hull(double radius_m, double height_m, int segments) {
  if (Status s = positive_size("buoy radius", radius_m); !s.ok()) return s;
  if (Status s = positive_size("buoy height", height_m); !s.ok()) return s;
  if (segments < 3 || segments > 256)
    return invalid_argument("buoy segments = " + std::to_string(segments) +
                            " is out of range: [3, 256]");
  MeshBuilder mesh;
  const double top = height_m / 2, bottom = -height_m / 2;
  const auto rim = [&](int i, double y) {
    const double a = 2.0 * std::numbers::pi * (i % segments) / segments;
    return Vec3{radius_m * std::cos(a), y, radius_m * std::sin(a)};
  };
  for (int i = 0; i < segments; ++i) {
    const Vec3 mid = scale(add(rim(i, 0.0), rim(i + 1, 0.0)), 0.5);
    mesh.quad(rim(i, bottom), rim(i + 1, bottom), rim(i + 1, top), rim(i, top), mid);
    mesh.triangle(Vec3{0.0, top, 0.0}, rim(i, top), rim(i + 1, top), Vec3{0.0, 1.0, 0.0});
    mesh.triangle(Vec3{0.0, bottom, 0.0}, rim(i, bottom), rim(i + 1, bottom), Vec3{0.0, -1.0, 0.0});
  }
  return mesh.centred();
}

namespace {

Status check_boat(double length_m, double beam_m, double depth_m) {
  if (Status s = positive_size("boat length", length_m); !s.ok()) return s;
  if (Status s = positive_size("boat beam", beam_m); !s.ok()) return s;
  return positive_size("boat depth", depth_m);
}

// The deck's half-breadth at u = 2x/L (B.6): B/2·(1 − u²) towards the bow, B/2·(1 − 0.3u²)
// towards the transom.
double deck_half_breadth(double beam_m, double u) {
  return 0.5 * beam_m * (u > 0.0 ? std::max(1.0 - u * u, 0.0) : 1.0 - 0.3 * u * u);
}

// The boat's hull as built, its deck at y = 0, before it is centred.
MeshBuilder boat_mesh(double length_m, double beam_m, double depth_m) {
  // Stations along x; at each a half-elliptical section under a flat deck (B.6): half-breadth
  // b(u) = B/2·(1 − u²) towards the bow (u = 2x/L > 0) and B/2·(1 − 0.3u²) towards the transom
  // stern, keel depth D·(1 − 0.5·u⁴) (the keel rises at the ends).
  constexpr int kStations = 24, kSection = 12;
  const auto half_breadth = [&](double u) { return deck_half_breadth(beam_m, u); };
  const auto point = [&](int station, int k) {
    const double u = -1.0 + 2.0 * station / kStations;
    const double b = half_breadth(u), d = depth_m * (1.0 - 0.5 * u * u * u * u);
    // k = 0: starboard deck, kSection: port deck; the port half mirrors the starboard half
    // bit for bit, so that the collapsed bow ring merges into one line.
    const int side = std::min(k, kSection - k);
    const double theta = std::numbers::pi * side / kSection;
    const double z = b * std::cos(theta);
    return Vec3{0.5 * length_m * u, -d * std::sin(theta), side == k ? z : -z};
  };
  MeshBuilder mesh;
  // Every strip runs the same way round the section: one winding for all, taken from the keel
  // strip amidships, whose outward normal is −y.
  const int keel = kSection / 2, mid = kStations / 2;
  const bool flip = cross(sub(point(mid, keel + 1), point(mid, keel)),
                          sub(point(mid + 1, keel + 1), point(mid, keel)))[1] > 0.0;
  for (int s = 0; s < kStations; ++s)
    for (int k = 0; k <= kSection; ++k) {  // k = kSection → 0 closes the ring: the deck
      const int k1 = (k + 1) % (kSection + 1);
      const Vec3 a = point(s, k), b = point(s, k1), c = point(s + 1, k1), d = point(s + 1, k);
      mesh.wound(a, b, c, flip);
      mesh.wound(a, c, d, flip);
    }
  for (int end : {0, kStations}) {  // transom and bow: fans over the section polygons
    const Vec3 outward{end == 0 ? -1.0 : 1.0, 0.0, 0.0};
    for (int k = 1; k < kSection; ++k)
      mesh.triangle(point(end, 0), point(end, k), point(end, k + 1), outward);
  }
  return mesh;
}

}  // namespace

Result<Hull> boat_hull(double length_m, double beam_m, double depth_m) {
  if (Status s = check_boat(length_m, beam_m, depth_m); !s.ok()) return s;
  return boat_mesh(length_m, beam_m, depth_m).centred();
}

Result<BoatTopside> boat_topside(double length_m, double beam_m, double depth_m) {
  if (Status s = check_boat(length_m, beam_m, depth_m); !s.ok()) return s;
  const Vec3 origin = mass_properties(boat_mesh(length_m, beam_m, depth_m).raw()).centroid_m;
  const double L = length_m, B = beam_m, D = depth_m;
  // Proportions of a small motor launch, as fractions of L, B and D.
  const double plank = 0.03 * D, rail = 0.25 * D, wall = 0.02 * B, inset = 0.04 * B;
  constexpr int kStations = 24;
  const auto x_at = [&](int i) { return 0.5 * L * (-1.0 + 2.0 * i / kStations); };
  const auto b_at = [&](int i) { return deck_half_breadth(B, -1.0 + 2.0 * i / kStations); };
  MeshBuilder deck, bulwark, cabin, windows;
  for (int i = 0; i < kStations; ++i) {
    const double x0 = x_at(i), x1 = x_at(i + 1);
    const double b0 = b_at(i), b1 = b_at(i + 1);
    // The deck's planking, inset from the sheer; a station whose breadth is gone is skipped.
    const double d0 = std::max(b0 - inset, 0.0), d1 = std::max(b1 - inset, 0.0);
    if (d0 > 0.0 || d1 > 0.0) {
      deck.block({Vec3{x0, 0.0, -d0}, Vec3{x1, 0.0, -d1}, Vec3{x1, 0.0, d1}, Vec3{x0, 0.0, d0},
                  Vec3{x0, plank, -d0}, Vec3{x1, plank, -d1}, Vec3{x1, plank, d1},
                  Vec3{x0, plank, d0}});
    }
    // The bulwark on each side, a thin wall along the sheer.
    for (double side : {-1.0, 1.0}) {
      const double o0 = side * b0, o1 = side * b1;
      const double i0 = side * std::max(b0 - wall, 0.0), i1 = side * std::max(b1 - wall, 0.0);
      if (b0 <= wall && b1 <= wall) continue;
      bulwark.block({Vec3{x0, 0.0, i0}, Vec3{x1, 0.0, i1}, Vec3{x1, 0.0, o1}, Vec3{x0, 0.0, o0},
                     Vec3{x0, rail, i0}, Vec3{x1, rail, i1}, Vec3{x1, rail, o1},
                     Vec3{x0, rail, o0}});
    }
  }
  // The transom's rail across the stern.
  const double bs = b_at(0);
  bulwark.block({Vec3{-0.5 * L, 0.0, -bs}, Vec3{-0.5 * L + wall, 0.0, -bs},
                 Vec3{-0.5 * L + wall, 0.0, bs}, Vec3{-0.5 * L, 0.0, bs}, Vec3{-0.5 * L, rail, -bs},
                 Vec3{-0.5 * L + wall, rail, -bs}, Vec3{-0.5 * L + wall, rail, bs},
                 Vec3{-0.5 * L, rail, bs}});
  // The cabin amidships: walls 0.3·B from the centreline, 0.9·D high, its front raked back as a
  // windscreen; the roof overhangs nothing (a plain block).
  const double c_aft = -0.22 * L, c_fore = 0.12 * L, rake = 0.06 * L;
  const double cw = 0.3 * B, ch = plank + 0.9 * D, roof_w = 0.27 * B;
  cabin.block({Vec3{c_aft, plank, -cw}, Vec3{c_fore, plank, -cw}, Vec3{c_fore, plank, cw},
               Vec3{c_aft, plank, cw}, Vec3{c_aft, ch, -roof_w}, Vec3{c_fore - rake, ch, -roof_w},
               Vec3{c_fore - rake, ch, roof_w}, Vec3{c_aft, ch, roof_w}});
  // Windows: thin dark panes standing 1 cm proud of the windscreen and of both sides.
  const double w_lo = plank + 0.45 * D, w_hi = ch - 0.1 * D, t = 0.01;
  const auto along_front = [&](double y) {  // the windscreen's x and half width at height y
    const double f = (y - plank) / (ch - plank);
    return std::array<double, 2>{c_fore - f * rake, cw + f * (roof_w - cw)};
  };
  {
    const auto lo = along_front(w_lo), hi = along_front(w_hi);
    const double wl = 0.85 * lo[1], wh = 0.85 * hi[1];
    windows.block({Vec3{lo[0], w_lo, -wl}, Vec3{lo[0] + t, w_lo, -wl}, Vec3{lo[0] + t, w_lo, wl},
                   Vec3{lo[0], w_lo, wl}, Vec3{hi[0], w_hi, -wh}, Vec3{hi[0] + t, w_hi, -wh},
                   Vec3{hi[0] + t, w_hi, wh}, Vec3{hi[0], w_hi, wh}});
  }
  for (double side : {-1.0, 1.0}) {
    const double a = c_aft + 0.1 * L, f = c_fore - rake - 0.04 * L;
    const auto wall_z = [&](double y) {
      return side * (cw + (y - plank) / (ch - plank) * (roof_w - cw));
    };
    const double zl = wall_z(w_lo), zh = wall_z(w_hi), o = side * t;
    windows.block({Vec3{a, w_lo, zl}, Vec3{f, w_lo, zl}, Vec3{f, w_lo, zl + o}, Vec3{a, w_lo, zl + o},
                   Vec3{a, w_hi, zh}, Vec3{f, w_hi, zh}, Vec3{f, w_hi, zh + o},
                   Vec3{a, w_hi, zh + o}});
  }
  return BoatTopside{.deck = translated(deck.raw(), origin),
                     .bulwark = translated(bulwark.raw(), origin),
                     .cabin = translated(cabin.raw(), origin),
                     .windows = translated(windows.raw(), origin)};
}

}  // namespace ocean::bodies
