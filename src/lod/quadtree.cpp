// Quadtree selection: distance-driven subdivision over an explicit stack, 2:1 balancing, the
// subdivision map, frustum culling, neighbour flags and batching by stitching configuration.
//
// Sources: Aebi, VR Ocean, §5.2–§5.3.2 and §5.6 (eqs. 57–64, 70); R. Pajarola, "Overview of
// quadtree-based terrain triangulation and visualization" (2002) for restricted (2:1 balanced)
// quadtrees; docs/lod.md L.2–L.8.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <string>

#include "ocean/lod.hpp"

namespace ocean::lod {

namespace {

// Node of the explicit stack, packed: x in bits 0–7, y in bits 8–15, level in bits 16–19.
constexpr std::uint32_t pack(std::uint32_t x, std::uint32_t y, std::uint32_t level) {
  return x | (y << 8) | (level << 16);
}
constexpr std::uint32_t node_x(std::uint32_t n) { return n & 0xffu; }
constexpr std::uint32_t node_y(std::uint32_t n) { return (n >> 8) & 0xffu; }
constexpr std::uint32_t node_level(std::uint32_t n) { return n >> 16; }

// Index of node (x, y) of level l in the split bitmap: levels 0..L_max−1 one after the other.
std::size_t split_index(std::uint32_t x, std::uint32_t y, std::uint32_t l) {
  const std::size_t first = ((std::size_t{1} << (2 * l)) - 1) / 3;
  return first + (std::size_t{y} << l) + x;
}

std::size_t split_size(int max_level) { return ((std::size_t{1} << (2 * max_level)) - 1) / 3; }

struct Geometry {
  double corner_x, corner_z;  // world position of grid cell (0, 0)'s corner: centre − S/2
  double size;                // S
};

// L.2 (Aebi, VR Ocean, eq. 58): the world centre of node (x, y) at level l.
void node_centre(const Geometry& g, std::uint32_t x, std::uint32_t y, std::uint32_t l, double& cx,
                 double& cz, double& s) {
  s = g.size / static_cast<double>(1u << l);
  cx = g.corner_x + (x + 0.5) * s;
  cz = g.corner_z + (y + 0.5) * s;
}

// Pushes the four children in reverse order so that the lower-left one is processed first.
void push_children(std::vector<std::uint32_t>& stack, std::uint32_t n) {
  const std::uint32_t x = 2 * node_x(n), y = 2 * node_y(n), l = node_level(n) + 1;
  stack.push_back(pack(x + 1, y + 1, l));
  stack.push_back(pack(x, y + 1, l));
  stack.push_back(pack(x + 1, y, l));
  stack.push_back(pack(x, y, l));
}

// Phase 1, L.3 (Aebi, VR Ocean, eq. 57): mark every node that the squared-distance test subdivides.
void subdivide(const LodParams& p, const Geometry& g, int max_level, LodSelection& sel) {
  const double tau2 = p.quality.lod_scale * p.quality.lod_scale;
  const Vec3 v = p.camera_position_m;
  sel.stack.clear();
  sel.stack.push_back(pack(0, 0, 0));
  while (!sel.stack.empty()) {
    const std::uint32_t n = sel.stack.back();
    sel.stack.pop_back();
    const std::uint32_t l = node_level(n);
    if (static_cast<int>(l) == max_level) continue;
    double cx = 0.0, cz = 0.0, s = 0.0;
    node_centre(g, node_x(n), node_y(n), l, cx, cz, s);
    const double d2 = (cx - v.x) * (cx - v.x) + v.y * v.y + (cz - v.z) * (cz - v.z);
    if (d2 < s * s * tau2) {
      sel.split[split_index(node_x(n), node_y(n), l)] = 1;
      push_children(sel.stack, n);
    }
  }
}

// Phase 2, L.4: 2:1 balance. A split node needs its four edge neighbours of the same level to
// exist, i.e. their parents split (with all their ancestors). Levels are visited from the
// deepest up, so a split added at level l−1 is itself checked when that level is visited.
void balance(int max_level, LodSelection& sel) {
  for (int li = max_level - 1; li >= 1; --li) {
    const auto l = static_cast<std::uint32_t>(li);
    const std::uint32_t n = 1u << l;
    for (std::uint32_t y = 0; y < n; ++y) {
      for (std::uint32_t x = 0; x < n; ++x) {
        if (sel.split[split_index(x, y, l)] == 0) continue;
        const std::int64_t nx[4] = {x + 1, std::int64_t{x} - 1, x, x};
        const std::int64_t ny[4] = {y, y, y + 1, std::int64_t{y} - 1};
        for (int k = 0; k < 4; ++k) {
          if (nx[k] < 0 || ny[k] < 0 || nx[k] >= n || ny[k] >= n) continue;
          auto px = static_cast<std::uint32_t>(nx[k] / 2);
          auto py = static_cast<std::uint32_t>(ny[k] / 2);
          for (std::int64_t a = li - 1; a >= 0; --a, px /= 2, py /= 2) {
            std::uint8_t& bit = sel.split[split_index(px, py, static_cast<std::uint32_t>(a))];
            if (bit != 0) break;  // its ancestors are split already
            bit = 1;
          }
        }
      }
    }
  }
}

// Phase 3, L.5–L.6: walk the balanced tree; every leaf fills its block of the subdivision map
// and is emitted when visible. A leaf's block is written at once, which is what Aebi's
// HasRendered flag achieves by descending to the finest level with the flag set (rules 1–3).
void collect_leaves(const LodParams& p, const Geometry& g, int max_level, LodSelection& sel) {
  const double h =
      p.max_vertical_displacement_m < 0.0 ? 0.015 * p.ocean_size_m : p.max_vertical_displacement_m;
  const auto w = static_cast<std::size_t>(sel.map_width);
  sel.stack.clear();
  sel.stack.push_back(pack(0, 0, 0));
  while (!sel.stack.empty()) {
    const std::uint32_t n = sel.stack.back();
    sel.stack.pop_back();
    const std::uint32_t x = node_x(n), y = node_y(n), l = node_level(n);
    if (static_cast<int>(l) < max_level && sel.split[split_index(x, y, l)] != 0) {
      push_children(sel.stack, n);
      continue;
    }
    const std::size_t delta = std::size_t{1} << (static_cast<std::uint32_t>(max_level) - l);
    for (std::size_t row = y * delta; row < (y + 1) * delta; ++row) {
      std::memset(&sel.subdivision_map[row * w + x * delta], static_cast<int>(l), delta);
    }
    double cx = 0.0, cz = 0.0, s = 0.0;
    node_centre(g, x, y, l, cx, cz, s);
    if (p.cull) {
      const double e = 0.5 * s * p.quality.cull_scale + p.max_horizontal_displacement_m;
      if (!box_visible(p.frustum, {cx, 0.0, cz}, {e, h, e})) continue;
    }
    sel.unsorted.push_back({.centre_x_m = static_cast<float>(cx),
                            .centre_z_m = static_cast<float>(cz),
                            .size_m = static_cast<float>(s),
                            .grid_x = static_cast<std::uint8_t>(x),
                            .grid_y = static_cast<std::uint8_t>(y),
                            .level = static_cast<std::uint8_t>(l)});
  }
}

// Phase 4, L.7 (Aebi, VR Ocean, eqs. 62–64): one map cell just across each edge. Outside the map
// counts as the same level. With the tree balanced, a coarser neighbour is exactly one level
// coarser and covers the whole edge, so one sample per edge decides it.
std::uint8_t neighbour_flags(const LodSelection& sel, int max_level, const PatchInstance& pi) {
  const int w = sel.map_width;
  const int delta = 1 << (max_level - pi.level);
  const int gx = pi.grid_x * delta, gy = pi.grid_y * delta;
  const int sx[4] = {gx + delta, gx, gx - 1, gx};
  const int sy[4] = {gy, gy + delta, gy, gy - 1};
  const std::uint8_t bits[4] = {kEast, kNorth, kWest, kSouth};
  std::uint8_t flags = 0;
  for (int k = 0; k < 4; ++k) {
    if (sx[k] < 0 || sy[k] < 0 || sx[k] >= w || sy[k] >= w) continue;
    const std::uint8_t level = sel.subdivision_map[static_cast<std::size_t>(sy[k] * w + sx[k])];
    if (level < pi.level) flags = static_cast<std::uint8_t>(flags | bits[k]);
  }
  return flags;
}

void clear(LodSelection& sel) {
  sel.instances.clear();
  sel.batches.clear();
  sel.unsorted.clear();
  sel.patches_per_level.fill(0);
  sel.patches_per_config.fill(0);
}

}  // namespace

Status validate(const LodParams& p) {
  if (Status s = require_in_range("ocean_size_m", p.ocean_size_m, kMinOceanSize_m, kMaxOceanSize_m);
      !s.ok()) {
    return s;
  }
  if (Status s = validate(p.quality); !s.ok()) return s;
  for (double c : {p.camera_position_m.x, p.camera_position_m.y, p.camera_position_m.z}) {
    if (Status s = require_in_range("camera_position_m", c, -1e9, 1e9); !s.ok()) return s;
  }
  if (p.cull) {
    for (const Plane& pl : p.frustum.planes) {
      for (double c : {pl.nx, pl.ny, pl.nz, pl.d}) {
        if (Status s = require_finite("frustum", c); !s.ok()) return s;
      }
    }
  }
  if (!p.follow_camera) {
    if (Status s = require_in_range("fixed_centre_x_m", p.fixed_centre_x_m, -1e9, 1e9); !s.ok()) {
      return s;
    }
    if (Status s = require_in_range("fixed_centre_z_m", p.fixed_centre_z_m, -1e9, 1e9); !s.ok()) {
      return s;
    }
  }
  if (!(p.max_vertical_displacement_m < 0.0)) {
    if (Status s =
            require_non_negative("max_vertical_displacement_m", p.max_vertical_displacement_m);
        !s.ok()) {
      return s;
    }
  }
  return require_non_negative("max_horizontal_displacement_m", p.max_horizontal_displacement_m);
}

Status reserve_selection(LodSelection& sel, double ocean_size_m) {
  if (Status s = require_in_range("ocean_size_m", ocean_size_m, kMinOceanSize_m, kMaxOceanSize_m);
      !s.ok()) {
    return s;
  }
  const int lmax = max_level(ocean_size_m);
  const std::size_t w = std::size_t{1} << lmax;
  sel.instances.reserve(w * w);
  sel.unsorted.reserve(w * w);
  sel.batches.reserve(kConfigurations);
  sel.subdivision_map.reserve(w * w);
  sel.split.reserve(split_size(lmax));
  sel.stack.reserve(static_cast<std::size_t>(3 * kMaxLevels + 4));
  return {};
}

Status select_patches(const LodParams& p, LodSelection& sel) {
  clear(sel);
  if (Status s = validate(p); !s.ok()) return s;
  const int lmax = max_level(p.ocean_size_m);
  sel.max_level = lmax;
  sel.map_width = 1 << lmax;
  if (p.follow_camera) {  // L.9 (Aebi, VR Ocean, eq. 69)
    const double step = snap_step_m(p.ocean_size_m, p.quality.vertices);
    sel.grid_centre_x_m = snap(p.camera_position_m.x, step);
    sel.grid_centre_z_m = snap(p.camera_position_m.z, step);
  } else {
    sel.grid_centre_x_m = p.fixed_centre_x_m;
    sel.grid_centre_z_m = p.fixed_centre_z_m;
  }
  const Geometry g{sel.grid_centre_x_m - 0.5 * p.ocean_size_m,
                   sel.grid_centre_z_m - 0.5 * p.ocean_size_m, p.ocean_size_m};
  sel.split.assign(split_size(lmax), 0);
  sel.subdivision_map.resize(static_cast<std::size_t>(sel.map_width * sel.map_width));

  subdivide(p, g, lmax, sel);
  balance(lmax, sel);
  collect_leaves(p, g, lmax, sel);

  // L.8 (Aebi, VR Ocean, eq. 70): counting sort by configuration; one batch per non-empty
  // configuration.
  for (PatchInstance& pi : sel.unsorted) {
    pi.config = neighbour_flags(sel, lmax, pi);
    ++sel.patches_per_config[pi.config];
    ++sel.patches_per_level[pi.level];
  }
  std::array<std::uint32_t, kConfigurations> next{};
  std::uint32_t first = 0;
  for (std::uint32_t c = 0; c < kConfigurations; ++c) {
    next[c] = first;
    if (sel.patches_per_config[c] > 0) sel.batches.push_back({c, first, sel.patches_per_config[c]});
    first += sel.patches_per_config[c];
  }
  sel.instances.resize(sel.unsorted.size());
  for (const PatchInstance& pi : sel.unsorted) sel.instances[next[pi.config]++] = pi;
  return {};
}

}  // namespace ocean::lod
