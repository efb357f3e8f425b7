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

Result<Hull> boat_hull(double length_m, double beam_m, double depth_m) {
  if (Status s = positive_size("boat length", length_m); !s.ok()) return s;
  if (Status s = positive_size("boat beam", beam_m); !s.ok()) return s;
  if (Status s = positive_size("boat depth", depth_m); !s.ok()) return s;
  // Stations along x; at each a half-elliptical section under a flat deck (B.6): half-breadth
  // b(u) = B/2·(1 − u²) towards the bow (u = 2x/L > 0) and B/2·(1 − 0.3u²) towards the transom
  // stern, keel depth D·(1 − 0.5·u⁴) (the keel rises at the ends).
  constexpr int kStations = 24, kSection = 12;
  const auto half_breadth = [&](double u) {
    return 0.5 * beam_m * (u > 0.0 ? std::max(1.0 - u * u, 0.0) : 1.0 - 0.3 * u * u);
  };
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
  return mesh.centred();
}

}  // namespace ocean::bodies
