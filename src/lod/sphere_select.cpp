// The quadtree LOD on the cube-sphere (docs/rendering.md R.36–R.37): per face the distance test
// of Aebi, VR Ocean, eq. 57, with the side measured on the sphere; 2:1 balancing across the
// faces' edges as within them; stitching flags from the neighbours across each edge; frustum
// and horizon culling of the leaves.
//
// This work is based on:
//   - Aebi, "VR Ocean" (2023), §5: quadtree selection, 2:1 restriction, 16 stitching
//     configurations (eqs. 57, 62–64).
//   - Cozzi & Ring, "3D Engine Design for Virtual Globes" (2011), ch. 12 (horizon culling): a
//     point at radius ρ is hidden by a ball of radius R₀ from an eye at distance d from its
//     centre when it is farther than √(d² − R₀²) + √(ρ² − R₀²) from the eye (R.37).
#include <algorithm>
#include <cmath>
#include <string>

#include "ocean/sphere.hpp"

namespace ocean::sphere {

namespace {

double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 sub(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double length(Vec3 a) { return std::sqrt(dot(a, a)); }
Vec3 on_sphere(int face, double u, double v, double r) {
  const Vec3 d = cube_to_sphere(cube_point(face, u, v));
  return {d.x * r, d.y * r, d.z * r};
}

// Node keys: face (3 bits), level (5), x (20), y (20).
std::uint64_t key(int face, int level, std::uint32_t x, std::uint32_t y) {
  return static_cast<std::uint64_t>(face) << 45 | static_cast<std::uint64_t>(level) << 40 |
         static_cast<std::uint64_t>(x) << 20 | y;
}
struct Node {
  int face, level;
  std::uint32_t x, y;
  double size() const { return 2.0 / static_cast<double>(1u << level); }
  double cu() const { return -1.0 + (x + 0.5) * size(); }
  double cv() const { return -1.0 + (y + 0.5) * size(); }
};
Node unkey(std::uint64_t k) {
  return {static_cast<int>(k >> 45), static_cast<int>((k >> 40) & 31u),
          static_cast<std::uint32_t>((k >> 20) & 0xFFFFFu),
          static_cast<std::uint32_t>(k & 0xFFFFFu)};
}

// The centre on the sphere and a radius that holds the node's displaced surface.
struct Bounds {
  Vec3 centre;
  double radius, side;
};
Bounds bounds(const Node& n, const SphereLodParams& p) {
  const double r = p.radius_m, h = n.size() / 2;
  const Vec3 c = on_sphere(n.face, n.cu(), n.cv(), r);
  double reach = 0.0, side = 0.0;
  Vec3 corners[4];
  for (int i = 0; i < 4; ++i) {
    corners[i] = on_sphere(n.face, n.cu() + ((i & 1) ? h : -h), n.cv() + ((i & 2) ? h : -h), r);
    reach = std::max(reach, length(sub(corners[i], c)));  // the corners are the farthest (R.37)
  }
  side = std::max(length(sub(corners[0], corners[1])), length(sub(corners[0], corners[2])));
  return {c, reach + p.max_vertical_displacement_m + p.max_horizontal_displacement_m, side};
}

enum class Seen : std::uint8_t { visible, outside_frustum, behind_horizon };
Seen seen(const Bounds& b, const SphereLodParams& p) {
  if (!p.cull) return Seen::visible;
  const double r0 = std::max(p.radius_m - p.max_vertical_displacement_m, 0.0);
  const double top = p.radius_m + p.max_vertical_displacement_m;
  const double d = length(p.camera_position_m);
  const double reach = std::sqrt(std::max(d * d - r0 * r0, 0.0)) + std::sqrt(top * top - r0 * r0);
  if (length(sub(b.centre, p.camera_position_m)) - b.radius > reach) return Seen::behind_horizon;
  if (!lod::box_visible(p.frustum, b.centre, {b.radius, b.radius, b.radius}))
    return Seen::outside_frustum;
  return Seen::visible;
}

// The level of the leaf holding the point of face `face` at (u, v), or `limit` + 1 when the
// node of level `limit` there is split (the neighbour is finer).
int leaf_level(const std::unordered_set<std::uint64_t>& split, int face, double u, double v,
               int limit) {
  for (int l = 0; l <= limit; ++l) {
    const double cells = static_cast<double>(1u << l);
    const auto ix = static_cast<std::uint32_t>(std::clamp((u + 1.0) * 0.5 * cells, 0.0, cells - 1));
    const auto iy = static_cast<std::uint32_t>(std::clamp((v + 1.0) * 0.5 * cells, 0.0, cells - 1));
    if (!split.contains(key(face, l, ix, iy))) return l;
  }
  return limit + 1;
}

// Where the neighbour across edge e (0 east +u, 1 north +v, 2 west, 3 south) lies: a point just
// beyond the edge's midpoint, carried onto the next face when it leaves this one.
void across(const Node& n, int e, int& face, double& u, double& v) {
  const double step = n.size() * (0.5 + 1e-3);
  const double du[4] = {step, 0, -step, 0}, dv[4] = {0, step, 0, -step};
  u = n.cu() + du[e], v = n.cv() + dv[e], face = n.face;
  if (std::abs(u) > 1.0 || std::abs(v) > 1.0) sphere_to_face(cube_point(n.face, u, v), face, u, v);
}

void split_node(const Node& n, std::unordered_set<std::uint64_t>& split,
                std::vector<std::uint64_t>& work) {
  split.insert(key(n.face, n.level, n.x, n.y));
  for (std::uint32_t c = 0; c < 4; ++c)
    work.push_back(key(n.face, n.level + 1, 2 * n.x + (c & 1u), 2 * n.y + (c >> 1)));
}

}  // namespace

Status validate(const SphereLodParams& p) {
  if (!std::isfinite(p.radius_m) || p.radius_m <= 0.0)
    return invalid_argument("radius_m must be a finite positive number of metres");
  if (Status s = lod::validate(p.quality); !s.ok()) return s;
  const Vec3 c = p.camera_position_m;
  if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z))
    return invalid_argument("camera_position_m must be finite");
  if (length(c) <= p.radius_m)
    return invalid_argument("camera_position_m is inside the planet (" +
                            std::to_string(length(c) - p.radius_m) + " m from its surface)");
  if (!std::isfinite(p.finest_patch_m) || p.finest_patch_m <= 0.0)
    return invalid_argument("finest_patch_m must be finite and positive");
  if (!std::isfinite(p.max_vertical_displacement_m) || p.max_vertical_displacement_m < 0.0 ||
      !std::isfinite(p.max_horizontal_displacement_m) || p.max_horizontal_displacement_m < 0.0)
    return invalid_argument("max_vertical/horizontal_displacement_m must be finite and >= 0");
  return {};
}

Status select_sphere_patches(const SphereLodParams& p, SphereSelection& sel) {
  sel.patches.clear(), sel.batches.clear(), sel.leaves.clear(), sel.split.clear();
  sel.culled_frustum = sel.culled_horizon = 0, sel.max_level = 0;
  if (Status s = validate(p); !s.ok()) return s;
  // Phase 1: split while the camera is nearer than τ·s (eq. 57), s > finest_patch_m and the
  // node may be seen (invisible nodes need no detail; balancing splits them where it must).
  std::vector<std::uint64_t> work;
  for (int f = 0; f < kFaces; ++f) work.push_back(key(f, 0, 0, 0));
  while (!work.empty()) {
    const Node n = unkey(work.back());
    work.pop_back();
    const Bounds b = bounds(n, p);
    const bool near = length(sub(b.centre, p.camera_position_m)) < p.quality.lod_scale * b.side;
    if (n.level < kMaxSphereLevels && near && b.side > p.finest_patch_m &&
        seen(b, p) == Seen::visible) {
      split_node(n, sel.split, work);
      sel.max_level = std::max(sel.max_level, n.level + 1);
    } else {
      sel.leaves.push_back(key(n.face, n.level, n.x, n.y));
    }
  }
  // Phase 2: 2:1 balance across every edge, the cube's included: a neighbour leaf more than one
  // level coarser than a leaf is split, and its children are checked in turn.
  work = sel.leaves;
  while (!work.empty()) {
    const std::uint64_t k = work.back();
    work.pop_back();
    const Node n = unkey(k);
    if (sel.split.contains(k)) continue;  // split since it was queued
    bool recheck = false;
    for (int e = 0; e < 4; ++e) {
      int face = 0;
      double u = 0.0, v = 0.0;
      across(n, e, face, u, v);
      const int l = leaf_level(sel.split, face, u, v, n.level);
      if (l >= n.level - 1) continue;
      const double cells = static_cast<double>(1u << l);
      const Node coarse{
          face, l, static_cast<std::uint32_t>(std::clamp((u + 1) * 0.5 * cells, 0.0, cells - 1)),
          static_cast<std::uint32_t>(std::clamp((v + 1) * 0.5 * cells, 0.0, cells - 1))};
      split_node(coarse, sel.split, work);
      recheck = true;
    }
    if (recheck) work.push_back(k);
  }
  // Phase 3: the leaves (the children of split nodes that are not split, and unsplit roots),
  // their stitching flags (eqs. 62–64) and culling.
  sel.leaves.clear();
  for (int f = 0; f < kFaces; ++f)
    if (!sel.split.contains(key(f, 0, 0, 0))) sel.leaves.push_back(key(f, 0, 0, 0));
  for (const std::uint64_t s : sel.split) {
    const Node n = unkey(s);
    for (std::uint32_t c = 0; c < 4; ++c) {
      const std::uint64_t child = key(n.face, n.level + 1, 2 * n.x + (c & 1u), 2 * n.y + (c >> 1));
      if (!sel.split.contains(child)) sel.leaves.push_back(child);
    }
  }
  std::sort(sel.leaves.begin(), sel.leaves.end());  // a selection independent of hashing
  std::vector<SpherePatch> unsorted;
  for (const std::uint64_t k : sel.leaves) {
    const Node n = unkey(k);
    const Seen s = seen(bounds(n, p), p);
    if (s == Seen::outside_frustum) ++sel.culled_frustum;
    if (s == Seen::behind_horizon) ++sel.culled_horizon;
    if (s != Seen::visible) continue;
    std::uint8_t config = 0;
    for (int e = 0; e < 4; ++e) {
      int face = 0;
      double u = 0.0, v = 0.0;
      across(n, e, face, u, v);
      if (leaf_level(sel.split, face, u, v, n.level) < n.level)
        config |= static_cast<std::uint8_t>(1u << e);  // kEast, kNorth, kWest, kSouth
    }
    unsorted.push_back({.x = n.x,
                        .y = n.y,
                        .face = static_cast<std::uint8_t>(n.face),
                        .level = static_cast<std::uint8_t>(n.level),
                        .config = config,
                        .centre_u = n.cu(),
                        .centre_v = n.cv(),
                        .size = n.size()});
  }
  // Phase 4: by configuration, one batch each (eq. 70).
  for (std::uint32_t c = 0; c < lod::kConfigurations; ++c) {
    const auto first = static_cast<std::uint32_t>(sel.patches.size());
    for (const SpherePatch& sp : unsorted)
      if (sp.config == c) sel.patches.push_back(sp);
    const auto count = static_cast<std::uint32_t>(sel.patches.size()) - first;
    if (count > 0) sel.batches.push_back({.config = c, .first = first, .count = count});
  }
  return {};
}

}  // namespace ocean::sphere
