// swash.glsl — the run-up of the waves on the land (docs/rendering.md R.67; docs/waves.md
// W.40–W.43): where the damping grid holds land, the water line of the swash climbs the beach to
// Stockdon et al.'s (2006) R2% and falls back once per peak period, a thin sheet of water and foam
// over the sand, the sand wet behind it and drying after it has drained. The run-up law and the
// cycle restate src/waves/swash.cpp (waves::stockdon_runup, swash_elevation_m,
// swash_alongshore_phase); tests/render/swash_render_test.cpp compares the drawn water line with
// them.
#ifndef OCEAN_RENDER_SWASH_GLSL
#define OCEAN_RENDER_SWASH_GLSL

#include "damping.glsl"
#include "far_noise.h"

// The steepest foreshore the law is applied at (waves::kMaxForeshoreSlope).
const float kMaxForeshoreSlope = 0.2;
// The film left behind the backwash drains into the sand with this e-folding time, s; the sand
// below the run-up stays damp at kDampSand of the wetness of a fresh film. Chosen values.
const float kSwashDrainTime_s = 2.0;
const float kDampSand = 0.5;

// (W.41) waves::stockdon_runup: (set-up, swash S, R2%, run-down), m, for H0, L0 and β_f.
vec4 stockdon_runup(float h0_m, float l0_m, float foreshore_slope) {
  if (!(h0_m > 0.0) || !(l0_m > 0.0)) return vec4(0.0);
  float beta = clamp(abs(foreshore_slope), 0.0, kMaxForeshoreSlope);
  float hl = h0_m * l0_m;
  float setup = 0.35 * beta * sqrt(hl);
  float swash = sqrt(hl * (0.563 * beta * beta + 0.004));
  return vec4(setup, swash, 1.1 * (setup + 0.5 * swash), setup - 0.5 * swash);
}

// (W.42) waves::swash_elevation_m: the water line's elevation at `phase` of the cycle.
float swash_elevation(vec4 runup, float phase) {
  float p = fract(phase);
  return runup.w + (runup.z - runup.w) * 4.0 * p * (1.0 - p);
}

// (W.43) waves::swash_alongshore_phase, (x, z) from the damping grid's corner.
float swash_alongshore_phase(vec2 p, float l0_m) {
  if (!(l0_m > 0.0)) return 0.0;
  const float kTwoPi = 6.28318531;
  return 0.35 * sin(kTwoPi * dot(vec2(0.8, 0.6), p) / (1.7 * l0_m)) +
         0.15 * sin(kTwoPi * dot(vec2(-0.5, 0.866), p) / (1.1 * l0_m) + 1.9);
}

// Value noise in [0, 1] on a unit lattice (the far field's integer hash), bilinear with a
// smoothstep fade: the swash's foam patches.
float swash_noise(vec2 p) {
  vec2 i = floor(p), f = p - i;
  f = f * f * (3.0 - 2.0 * f);
  ivec2 c = ivec2(i);
  float a = float(far_hash(uint(c.x) ^ far_hash(uint(c.y))) >> 8u) / 16777216.0;
  float b = float(far_hash(uint(c.x + 1) ^ far_hash(uint(c.y))) >> 8u) / 16777216.0;
  float d = float(far_hash(uint(c.x) ^ far_hash(uint(c.y + 1))) >> 8u) / 16777216.0;
  float e = float(far_hash(uint(c.x + 1) ^ far_hash(uint(c.y + 1))) >> 8u) / 16777216.0;
  return mix(mix(a, b, f.x), mix(d, e, f.x), f.y);
}

struct Swash {
  bool on;          // a swash is drawn here (land, a sea with a period and a height)
  float runup_m;    // R2%: the top of the swash zone
  float covered;    // 1 under the sheet
  float sheet_m;    // the sheet's thickness, m
  float foam;       // the sheet's foam coverage
  float wet;        // the sand's wetness: 1 fresh film, kDampSand damp, 0 dry
  float film;       // the water film's share of the surface: 1 under the sheet, draining behind
};

// The swash over land of height `height_m` above the mean sea level at xz (R.67); footprint_m
// the pixel's width on the ground, over which the foam's patches are filtered.
Swash swash_at(vec2 xz, float height_m, float footprint_m) {
  Swash s = Swash(false, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
  float l0 = u.damping.swash_wavelength_m;
  if (!(l0 > 0.0) || !(u.hs_m > 0.0)) return s;
  // The foreshore slope: the grid's heights' mean gradient over ±0.05·L0 (a few metres, within
  // the swash zone; at least a cell): a slope on the scale of the swash, and over the many cells
  // that make the half floats' rounding of the heights negligible in it.
  float e = max(u.damping.size_m / max(u.damping.resolution, 1.0), 0.05 * l0);
  vec2 grad = -vec2(grid_depth_at(xz + vec2(e, 0.0)) - grid_depth_at(xz - vec2(e, 0.0)),
                    grid_depth_at(xz + vec2(0.0, e)) - grid_depth_at(xz - vec2(0.0, e))) /
              (2.0 * e);  // ∇h, h = −d
  float beta = length(grad);
  vec4 r = stockdon_runup(u.hs_m, l0, beta);
  s.on = true;
  s.runup_m = r.z;
  if (height_m >= r.z) return s;  // above the run-up: dry sand
  // The phase where this point's line down the slope meets the shore (h = 0, one Newton step
  // along ∇h, at most L0 away), so the phase varies along the shore and not across it.
  vec2 shore = xz;
  if (beta > 1e-4) shore -= grad * min(height_m / (beta * beta), l0 / max(beta, 1e-6));
  float phase = fract(u.damping.swash_phase +
                      swash_alongshore_phase(shore - u.damping.origin_m, l0));
  float level = swash_elevation(r, phase);
  float range = max(r.z - r.w, 1e-4);
  if (height_m < level) {  // under the sheet: the bore's remnant
    s.covered = 1.0;
    float depth = level - height_m;
    s.sheet_m = min(0.3 * depth, 0.1);  // a lens thinning to its tip, a few cm deep
    // Foam: a line along the running tip, patches behind it (drawn in a frame that moves with
    // the tip: across the shore the distance behind it, (level − h)/β), fewer as the backwash
    // drains; a tenth at least, the sheet's aerated water.
    float tip = exp(-depth / (0.04 * range));
    float draining = phase < 0.5 ? 1.0 : 1.0 - 1.4 * (phase - 0.5);
    vec2 up = beta > 1e-4 ? grad / beta : vec2(1.0, 0.0);
    vec2 p = 1.5 * (xz - u.damping.origin_m - up * dot(up, xz - u.damping.origin_m) -
                    up * (depth / max(beta, 0.02)));
    // Each octave fades to its mean where its cells are under 4 pixels wide (as R.13's).
    vec2 fade = clamp(2.0 - 4.0 * footprint_m * vec2(1.5, 4.65), 0.0, 1.0);
    float noise = 0.65 * mix(0.5, swash_noise(p), fade.x) + 0.35 * mix(0.5, swash_noise(3.1 * p), fade.y);
    float patches = smoothstep(0.45, 0.8, noise);
    s.foam = max(max(0.85 * tip, 0.7 * patches * exp(-depth / (0.5 * range))) * draining, 0.1);
    s.wet = s.film = 1.0;
    return s;
  }
  // Uncovered since the sheet went below this height at phase (1 + √(1 − q))/2 (W.42 solved for
  // the falling side): the film drains with kSwashDrainTime_s.
  float q = clamp((height_m - r.w) / range, 0.0, 1.0);
  float left = 0.5 * (1.0 + sqrt(1.0 - q));
  float period_s = sqrt(6.28318531 * l0 / 9.81);
  s.film = exp(-fract(phase - left) * period_s / kSwashDrainTime_s);
  // The damp band fades over the top tenth of the swash zone rather than ending on a line.
  s.wet = mix(kDampSand, 1.0, s.film) * (1.0 - smoothstep(r.z - 0.1 * range, r.z, height_m));
  return s;
}

#endif
