// underwater.glsl — the sea seen from below (docs/rendering.md R.50–R.52): which side of the
// surface a point or a pixel's near-plane point lies on, the underside of the waves (the sky
// refracted inside Snell's window, total internal reflection beyond the critical angle) and the
// fog of the water's own light along a path through it (Beer–Lambert with absorption and
// scattering).
//
// Sources: Snell's law and the critical angle arcsin(1/n), n = 1.333; the unpolarised Fresnel
// equations (Hecht, "Optics", 2002, §4.6) for the window's transmittance; the n² law of radiance
// across an interface (Mobley, "Light and Water", 1994: L/n² is invariant along a ray); Beer–Lambert
// attenuation with the absorption of pure water (Pope & Fry 1997) and the scattering of clear
// ocean water (Morel 1988).
#ifndef OCEAN_RENDER_UNDERWATER_GLSL
#define OCEAN_RENDER_UNDERWATER_GLSL

#include "planet.glsl"
#include "local_layer.glsl"
#include "damping.glsl"

const float kUnderwaterIor = 1.333;

// The displacement ocean.vert gives the mesh vertex at the undisplaced point xz near the camera
// (R.9, R.10, R.19, R.24; the far field and the hex tiles begin beyond D_min and are left out).
// The weights follow the vertex shader's so the waterline meets the drawn surface.
vec3 surface_displacement(vec2 xz) {
  vec3 d = vec3(0.0);
  vec2 rel = xz - u.grid_centre_m;
  float border = max(abs(rel.x), abs(rel.y));
  float border_weight = clamp((0.5 * u.ocean_size_m - border) / u.border_fade_m, 0.0, 1.0);
  if (border_weight > 0.0 && u.local.calm < 0.5) {
    DampingSample damping = damping_at(xz);
    float dist = length(vec3(xz.x, 0.0, xz.y) - u.camera_pos_m);
    float spacing = max(2.0 * dist / (u.lod_scale * u.vertices), 1e-3);
    for (int c = 0; c < int(u.cascade_count); ++c) {
      float w = clamp(2.0 - 4.0 * spacing / u.cascades[c].wavelength_m, 0.0, 1.0);
      if (w <= 0.0) continue;
      vec3 plain = textureLod(displacement_map, vec3(cascade_uv(xz, c), float(c)), 0.0).xyz;
      d += w * band_weight(damping, c) * plain;
    }
    d *= border_weight;
  }
  return d + local_displacement(xz);
}

// The surface's height above the camera's tangent plane at the displaced point xz (R.50): the
// undisplaced point found by fixed-point iteration x₀ ← xz − D(x₀) (the horizontal
// displacement's slope stays below one where the surface does not fold).
float surface_height(vec2 xz) {
  vec2 x0 = xz;
  for (int i = 0; i < 4; ++i) x0 = xz - surface_displacement(x0).xz;
  return surface_displacement(x0).y - curvature_drop(x0);
}

bool under_surface(vec3 p) { return p.y < surface_height(p.xz); }

// How far the drawn mesh may stray from the exact surface, at most, m: an eye farther than this
// from the surface lies on the same side of the mesh.
const float kMeshMargin_m = 1.0;

// The eye's height above the exact surface at its own position, m.
float eye_above_surface() { return u.camera_pos_m.y - surface_height(u.camera_pos_m.xz); }

// Whether the camera's ray along v, one that meets no part of the drawn surface (the sky pass's
// pixels), runs in the water (R.50). Such a ray stays on one side of the surface, so the side
// where it leaves the drawn sea, at the skirt's outer edge E, is the side it started on: under
// the sea there, y_c + E·v_y/|v_xz| < −E²/(2R). Unlike a height query at the near plane, this
// agrees with the drawn mesh wherever the mesh strays from the exact surface, so the waterline
// shows neither a gap to the sky nor a bar of water.
bool ray_stays_in_water(vec3 v) {
  if (u.sphere.enabled > 0.5) return false;  // the sphere's camera is above its sea (R.30–R.38)
  // An eye deeper than the mesh strays sees the sky only through the hairline cracks where the
  // skirt meets the patches.
  float eye = eye_above_surface();
  if (abs(eye) > kMeshMargin_m) return eye < 0.0;
  float across = length(v.xz), E = u.underwater.skirt_extent_m;
  if (across * E < 1e-3 * abs(v.y)) return v.y < 0.0;  // (near) vertical
  float end_y = u.camera_pos_m.y + E * v.y / across;
  return end_y < -E * E * u.planet.inv_two_radius_per_m;
}

// Whether the camera sees this fragment of the water's surface from below. A height field is
// first met from the side the eye is on, so away from the surface the eye's side decides; near
// it the drawn triangle does: the eye lies below its plane (the normal from the screen-space
// derivatives of the position, exact for a flat triangle, turned up). Call in uniform control
// flow.
bool seen_from_below(vec3 p) {
  vec3 n = cross(dFdx(p), dFdy(p));
  n *= n.y < 0.0 ? -1.0 : 1.0;
  float eye = eye_above_surface();
  if (abs(eye) > kMeshMargin_m) return eye < 0.0;
  return dot(u.camera_pos_m - p, n) < 0.0;
}

// The radiance of an endless path through the water seen at a depth z along the unit
// direction v (R.51): looking down, the water body's light of R.11 just below the surface,
// L∞ = ρ·E/π, dimmed as the downwelling light is, by e^{−a·z} (the diffuse attenuation taken
// as the absorption); brighter towards the light above, by kUnderwaterRise^(1 + v_y): the
// light under water comes mostly from above (a chosen shape, threefold from the nadir to the
// horizon and again to the zenith).
const float kUnderwaterRise = 3.0;
vec3 water_path_radiance(float depth_m, vec3 v) {
  float mu_s = max(u.sun_dir.y, 0.0);
  vec3 e = u.sun_ground * mu_s * (1.0 - fresnel_schlick(mu_s)) + u.sky_ambient;
  vec3 nadir = u.water_colour * e / PI * exp(-u.underwater.absorption_per_m * max(depth_m, 0.0));
  return nadir * pow(kUnderwaterRise, 1.0 + clamp(v.y, -1.0, 1.0));
}

// The eye's depth below the mean sea level, m (≥ 0): where the fog's light is taken.
float eye_depth() { return max(-u.camera_pos_m.y, 0.0); }

// Radiance L0 seen r metres away along v (from the seen point towards the camera: −v is the
// view direction) through the water (R.51).
vec3 water_fog(vec3 radiance, float r, vec3 v) {
  vec3 t = exp(-(u.underwater.absorption_per_m + u.underwater.scattering_per_m) * r);
  return radiance * t + water_path_radiance(eye_depth(), -v) * (1.0 - t);
}

// The bed's depth below the mean sea level at xz, m (R.52): the bathymetry's where the damping
// grid (R.24) covers the point, `flat_depth_m` elsewhere.
float bed_depth_at(vec2 xz, float flat_depth_m) {
  if (u.damping.resolution > 0.0) {
    vec2 uv = (xz - u.damping.origin_m) / u.damping.size_m;
    if (all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0))))
      return max(textureLod(damping_map, vec3(uv, 2.0), 0.0).x, 0.0);  // land: the bed at once
  }
  return flat_depth_m;
}

// Irradiance on a bed `depth_m` down (R.23): the sun refracted into the water (its path 1/μ_w
// longer than the depth) and the sky, attenuated vertically.
vec3 bed_irradiance(float depth_m) {
  vec3 a = u.underwater.absorption_per_m;
  float mu_s = max(u.sun_dir.y, 0.0);
  float sin_w = sqrt(max(1.0 - mu_s * mu_s, 0.0)) / kUnderwaterIor;
  float mu_w = sqrt(1.0 - sin_w * sin_w);
  return u.sun_ground * mu_s * (1.0 - fresnel_schlick(mu_s)) * exp(-a * depth_m / mu_w) +
         u.sky_ambient * exp(-a * depth_m);
}

// e^{x} − 1, by its series near 0 (GLSL has no expm1).
float expm1_safe(float x) { return abs(x) < 1e-4 ? x + 0.5 * x * x : exp(x) - 1.0; }

// ∫_{s0}^{s1} e^{−κ·s} ds per channel, exact (s1 may be large where κ > 0).
vec3 exp_segment(vec3 kappa, float s0, float s1) {
  vec3 out_ = vec3(0.0);
  for (int c = 0; c < 3; ++c) {
    float k = kappa[c];
    out_[c] = abs(k) * (s1 - s0) < 1e-4 ? exp(-k * s0) * (s1 - s0)
                                         : (exp(-k * s0) - exp(-k * s1)) / k;
  }
  return out_;
}

// --- caustics (R.65) ---------------------------------------------------------------------------
// Mirrors caustic_spacing_m and caustic_irradiance (ocean/underwater.hpp, src/render/caustics.cpp):
// the sun refracted at the cascades' normals, a lattice on the surface mapped by its rays to a
// plane `depth` below the mean level, the irradiance there its triangles' area ratio.
const float kCausticTilt = 0.06;
const float kCausticMinSpacing_m = 0.03;
const int kCausticHalfWidth = 3;  // the bed's gather: 7 × 7 lattice points
const int kShaftHalfWidth = 2;    // the light shafts' (R.66): 5 × 5 at each of their samples

float caustic_spacing_m(float depth_m, int half_width) {
  return max(kCausticMinSpacing_m, max(depth_m, 0.0) * kCausticTilt / (float(half_width) - 1.5));
}

// The surface gradient s (normal ∝ (s_x, 1, s_z)) of the cascades at the undisplaced point xz,
// each cascade's normals averaged over the lattice spacing (the mip whose texels are that wide),
// damped as the shading damps them (R.24). The calm surface (set_calm) has none.
vec2 caustic_slope(vec2 xz, float spacing_m, DampingSample damping) {
  vec2 s = vec2(0.0);
  int cascades = u.local.calm > 0.5 ? 0 : int(u.cascade_count);
  for (int c = 0; c < cascades; ++c) {
    // A cascade whose waves are shorter than two cells averages to no slope over a cell.
    if (u.cascades[c].wavelength_m < 2.0 * spacing_m) continue;
    float texel = u.cascades[c].patch_size_m / u.cascades[c].resolution;
    float lod = clamp(log2(spacing_m / texel), 0.0, u.cascades[c].coarsest_mip);
    vec2 n = textureLod(normal_map, vec3(cascade_uv(xz, c), float(c)), lod).xy * 2.0 - 1.0;
    s += band_weight(damping, c) * n / sqrt(max(1.0 - dot(n, n), 0.05));
  }
  return s;
}

// Where the sun's ray refracted at the normal N meets the plane `depth_m` down, from the
// surface point (the surface taken at the mean level).
vec2 caustic_offset(vec3 N, float depth_m) {
  vec3 t = refract(-u.sun_dir, N, 1.0 / kUnderwaterIor);
  return depth_m * t.xz / max(-t.y, 1e-6);
}

// The irradiance a triangle of three photons (landing point xy, flux weight z) gives xz, over a
// flat surface's, times the surface triangle's doubled area: the vertices' mean weight over the
// doubled area it lands on where xz lies inside it (folded ones by magnitude), else 0; and
// whether it does (y).
vec2 caustic_triangle(vec3 a, vec3 b, vec3 c, vec2 xz) {
  float area2 = cross(vec3(b.xy - a.xy, 0.0), vec3(c.xy - a.xy, 0.0)).z;
  vec3 e = vec3(cross(vec3(b.xy - a.xy, 0.0), vec3(xz - a.xy, 0.0)).z,
                cross(vec3(c.xy - b.xy, 0.0), vec3(xz - b.xy, 0.0)).z,
                cross(vec3(a.xy - c.xy, 0.0), vec3(xz - c.xy, 0.0)).z);
  if (area2 < 0.0) {
    area2 = -area2;
    e = -e;
  }
  if (!(area2 > 0.0) || min(e.x, min(e.y, e.z)) < 0.0) return vec2(0.0);
  return vec2((a.z + b.z + c.z) / (3.0 * area2), 1.0);
}

// The sun's irradiance on the horizontal plane `depth_m` down at xz over a flat surface's
// (R.65): the lattice x_k = δ·k of (2·half_width + 1)² points around where the flat surface's
// ray to xz starts, each mapped by its refracted ray to x_k + o_k with the flux weight
// w_k = (N_k·L)/(N_k,y·L_y); every cell's two triangles that land over xz add their flux over
// the area they land on. 1 under a flat surface, 1 on average under waves; at most
// kCausticMaxIrradiance.
const float kCausticMaxIrradiance = 100.0;
const int kCausticMaxSide = 2 * kCausticHalfWidth + 1;
float caustic_irradiance(vec2 xz, float depth_m, int half_width) {
  vec3 L = u.sun_dir;
  if (L.y <= 0.0 || u.local.calm > 0.5 || depth_m <= 0.0) return 1.0;
  float delta = caustic_spacing_m(depth_m, half_width);
  DampingSample damping = damping_at(xz);
  vec2 k0 = round((xz - caustic_offset(vec3(0.0, 1.0, 0.0), depth_m)) / delta);
  int side = 2 * half_width + 1;
  vec3 photon[kCausticMaxSide * kCausticMaxSide];
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      vec2 x = (k0 + vec2(i - half_width, j - half_width)) * delta;
      vec2 s = caustic_slope(x, delta, damping);
      vec3 N = normalize(vec3(s.x, 1.0, s.y));
      float w = max(dot(N, L), 0.0) / (N.y * L.y);
      photon[j * side + i] = vec3(x + caustic_offset(N, depth_m), w);
    }
  float sum = 0.0;
  bool covered = false;
  for (int j = 0; j + 1 < side; ++j)
    for (int i = 0; i + 1 < side; ++i) {
      vec3 a = photon[j * side + i], b = photon[j * side + i + 1];
      vec3 c = photon[(j + 1) * side + i], d = photon[(j + 1) * side + i + 1];
      vec2 abd = caustic_triangle(a, b, d, xz), adc = caustic_triangle(a, d, c, xz);
      covered = covered || abd.y > 0.0 || adc.y > 0.0;
      sum += abd.x + adc.x;
    }
  // A point no landed triangle of the block covers lies where rays deflected beyond the block
  // land: it takes the mean, 1, rather than a hole.
  return covered ? min(sum * delta * delta, kCausticMaxIrradiance) : 1.0;
}

// Irradiance on a bed `depth_m` down at xz (R.23, R.65): the sun's part focused by the waves.
// `footprint_m` is how far apart the pixel's neighbours see the bed: where it nears the
// lattice's spacing the pattern is finer than the pixel and fades to its mean, 1, as the sand's
// ripples do (seen from above through the waves, the refracted view rays scatter by more).
vec3 bed_irradiance_at(vec2 xz, float depth_m, float footprint_m) {
  vec3 sky = u.sky_ambient * exp(-u.underwater.absorption_per_m * depth_m);
  float fade = clamp(2.0 - 4.0 * footprint_m / caustic_spacing_m(depth_m, kCausticHalfWidth),
                     0.0, 1.0);
  float C = fade > 0.0 ? caustic_irradiance(xz, depth_m, kCausticHalfWidth) : 1.0;
  return (bed_irradiance(depth_m) - sky) * (1.0 + fade * (C - 1.0)) + sky;
}

// --- light shafts (R.66) -----------------------------------------------------------------------
// Henyey–Greenstein's phase function with the mean cosine of ocean particles, g = 0.924 (Petzold
// 1972, in Mobley 1994); mirrors henyey_greenstein_phase (ocean/underwater.hpp).
const float kWaterPhaseG = 0.924;
float water_phase(float cos_theta) {
  float g = kWaterPhaseG, d = 1.0 + g * g - 2.0 * g * cos_theta;
  return (1.0 - g * g) / (4.0 * PI * d * sqrt(d));
}

// The sunlight scattered once towards the eye along the path from `eye` (in the water) along
// the unit direction `dir` over r metres (R.66): ∫₀^r b·p(θ)·E⊥·e^{−a·z(s)/μ_w}·C(s)·e^{−c·s} ds,
// E⊥ the refracted beam's irradiance just below the surface, z(s) the depth along the path, C
// the caustics there. The path is cut into kShaftSamples pieces that each hold an equal share of
// the attenuation's integral (green), each integrated exactly for its exponential and weighted
// by the caustics at its middle: under a flat surface (C = 1) the sum is the closed form
// b·p·E⊥·e^{−a·z_e/μ_w}·(1 − e^{−κ·r})/κ, κ = c − a·v_y/μ_w (sun_single_scattering).
const int kShaftSamples = 6;
vec3 sunlit_water(vec3 eye, vec3 dir, float r) {
  vec3 L = u.sun_dir;
  if (L.y <= 0.0 || u.underwater.scattering_per_m <= 0.0) return vec3(0.0);
  vec3 t0 = refract(-L, vec3(0.0, 1.0, 0.0), 1.0 / kUnderwaterIor);
  float mu_w = -t0.y;
  vec3 e_perp = u.sun_ground * L.y * (1.0 - fresnel_schlick(L.y)) / mu_w;
  vec3 a = u.underwater.absorption_per_m;
  float b = u.underwater.scattering_per_m;
  vec3 kappa = a + b - a * dir.y / mu_w;
  float z_e = max(-eye.y, 0.0);
  vec3 scale = b * water_phase(dot(t0, -dir)) * e_perp * exp(-a * z_e / mu_w);
  // Equal shares of the green channel's ∫₀^r e^{−κ s} ds: s_k = −ln(1 − k·F/K)/κ, F = 1 − e^{−κr}.
  float kg = max(kappa.g, 1e-6);
  float whole = -expm1_safe(-kg * r);
  vec3 sum = vec3(0.0);
  float s0 = 0.0;
  for (int k = 1; k <= kShaftSamples; ++k) {
    float share = whole * float(k) / float(kShaftSamples);
    float s1 = k == kShaftSamples ? r : -log(max(1.0 - share, 1e-30)) / kg;
    float mid = -log(max(1.0 - whole * (float(k) - 0.5) / float(kShaftSamples), 1e-30)) / kg;
    vec3 X = eye + mid * dir;
    float C = caustic_irradiance(X.xz, max(-X.y, 0.0), kShaftHalfWidth);
    sum += C * exp_segment(kappa, s0, s1);
    s0 = s1;
  }
  return scale * sum;
}

// The length of the path from `eye` under the sea along v, one that meets no surface, to the
// seabed (R.52), m, and the bed's depth there; kEndlessPath_m where it meets none.
const float kEndlessPath_m = 1e6;
float path_to_bed(vec3 eye, vec3 v, out float depth) {
  depth = OCEAN_RENDER_DEEP_M;
  if (u.underwater.bed_enabled < 0.5 || v.y > -1e-4) return kEndlessPath_m;
  float flat_depth = u.underwater.bed_albedo_depth.a;
  depth = bed_depth_at(eye.xz, flat_depth);
  float t = max(eye.y + depth, 0.0) / -v.y;
  depth = bed_depth_at(eye.xz + t * v.xz, flat_depth);  // once more where it lands
  t = max(eye.y + depth, 0.0) / -v.y;
  return depth >= OCEAN_RENDER_DEEP_M ? kEndlessPath_m : t;
}

// What a ray from `eye` under the sea along v, one that meets no surface, sees (R.51, R.52): the
// seabed where it reaches one (uniform albedo: the sand's ripples are left out) lit through the
// waves' caustics (R.65), through the water's fog, or the water's own light.
// `caustics`: false for a ray the waves have reflected (R.50's total internal reflection), whose
// directions they scramble at a pixel's scale: the pattern would turn into noise there.
vec3 seen_under_water(vec3 eye, vec3 v, bool caustics) {
  vec3 deep = water_path_radiance(eye_depth(), v);
  float depth;
  float t = path_to_bed(eye, v, depth);
  if (t >= kEndlessPath_m) return deep;
  // Straight rays from the eye: the pattern is not scrambled as through the waves from above
  // (and this runs in non-uniform control flow, without screen derivatives).
  vec3 bed = u.underwater.bed_albedo_depth.rgb *
             bed_irradiance_at(eye.xz + t * v.xz, depth, caustics ? 0.0 : 1e9) / PI;
  return water_fog(bed, t, -v);
}

// The camera's own path of r metres through the water along the view direction `dir` (R.51,
// R.66): the fog over what lies at its end, and the sunlight the path scatters towards the eye.
vec3 seen_through_water(vec3 radiance, float r, vec3 dir) {
  return water_fog(radiance, r, -dir) + sunlit_water(eye_position(), dir, r);
}

// Water-to-air transmittance of the unpolarised Fresnel equations at the cosine cos_i of the
// angle of incidence in the water (R.50): 1 − (r_s² + r_p²)/2 with n = 1.333, falling to zero at
// the critical angle (its slope there is infinite, an edge sharper than any pixel) and zero
// beyond it (total internal reflection). Mirrors water_to_air_transmittance (ocean/underwater.hpp).
float water_to_air_transmittance(float cos_i) {
  float ci = clamp(cos_i, 0.0, 1.0), n = kUnderwaterIor;
  float sin_t_sq = n * n * (1.0 - ci * ci);
  if (sin_t_sq >= 1.0) return 0.0;
  float ct = sqrt(1.0 - sin_t_sq);
  float r_s = (n * ci - ct) / (n * ci + ct), r_p = (n * ct - ci) / (n * ct + ci);
  return 1.0 - 0.5 * (r_s * r_s + r_p * r_p);
}

// The transmittance box-filtered over a pixel (R.50): the mean over [cos_i − w/2, cos_i + w/2],
// w the pixel's spread of cos_i (its fwidth), by the midpoint rule on kWindowTaps points. The
// transmittance is continuous (zero at the critical angle), so the mean moves smoothly with the
// footprint: no pixel jumps from sky to mirror, and no level is skipped.
const int kWindowTaps = 8;
float window_transmittance(float cos_i, float width) {
  float sum = 0.0;
  for (int k = 0; k < kWindowTaps; ++k)
    sum += water_to_air_transmittance(cos_i + width * ((float(k) + 0.5) / float(kWindowTaps) - 0.5));
  return sum / float(kWindowTaps);
}

// The underside of the surface at P seen from the camera below (R.50): N the surface's upward
// normal, V towards the camera, cos_width the pixel's spread of dot(V, N) (fwidth, taken in
// uniform control flow). The ray from the water refracts into the air when it meets the surface
// within the critical angle (Snell's window), carrying the sky's radiance times n²·T; the rest,
// 1 − T, is reflected, and beyond the critical angle total internal reflection returns the
// water's own light alone.
vec3 underside_radiance(vec3 P, vec3 N, vec3 V, float cos_width, float foam) {
  vec3 n_water = -N;  // the normal on the camera's side
  float cos_i = dot(V, n_water);
  if (cos_i < 1e-3) n_water = normalize(n_water + (1e-3 - cos_i) * V);  // bent back, as above
  cos_i = max(cos_i, 1e-3);
  // Total internal reflection: the water below, or the seabed, mirrored.
  vec3 depth_light = seen_under_water(P, reflect(-V, n_water), false);
  float T = window_transmittance(cos_i, cos_width);
  // The refracted ray (Snell's law), held at grazing beyond the critical angle, where the filtered
  // transmittance of a pixel across the edge still looks through it.
  float n = kUnderwaterIor;
  float cos_t = sqrt(max(1.0 - n * n * (1.0 - cos_i * cos_i), 0.0));
  vec3 refracted = normalize(-n * V + (n * cos_i - cos_t) * n_water);
  vec3 c = T * n * n * sky_radiance(refracted) + (1.0 - T) * depth_light;
  // Foam seen from below: a bright diffuse layer lit from above through itself.
  vec3 foam_light =
      0.5 * u.foam_brightness * water_path_radiance(0.0, vec3(0.0, -1.0, 0.0)) /
      max(u.water_colour, vec3(1e-3));
  return mix(c, min(foam_light, vec3(1e3)), clamp(foam, 0.0, 1.0) * 0.5);
}

#endif
