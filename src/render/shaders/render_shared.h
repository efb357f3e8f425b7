// render_shared.h — the renderer's uniform layouts, push constants, bindings and limits, shared
// by the C++ renderer (src/render) and its GLSL shaders (one source of truth, after zeux/niagara;
// the compute side does the same with src/backends/vulkan/shaders/ocean_shared.h). Included by
// both languages: keep to #define constants and structs of 32-bit scalars and vectors laid out so
// that std140 (uniform block) and std430 (push constants) equal the C++ layout — every vec3 is
// followed by one float, every group of scalars fills 16 bytes; the static_asserts below check
// the offsets the shaders see.
#ifndef OCEAN_RENDER_SHARED_H
#define OCEAN_RENDER_SHARED_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
namespace ocean::render::shader {
using uint = std::uint32_t;
struct vec2 {
  float x, y;
};
struct vec3 {
  float x, y, z;
};
struct vec4 {
  float x, y, z, w;
};
struct mat4 {
  float m[16];  // column-major, as GLSL
};
#endif

// Limits. OCEAN_RENDER_MAX_CASCADES mirrors validate(SimulationConfig).
#define OCEAN_RENDER_MAX_CASCADES 8
// The most short waves drawn as detail normals (R.62): SimulationPlan::short_waves' 16 × 3.
#define OCEAN_RENDER_MAX_RIPPLES 48
// The foam's drift footprint (R.11, docs/waves.md W.31): taps at ages (j + ½)·S·τ/K, j < K.
#define OCEAN_RENDER_FOAM_STREAK_TAPS 16
#define OCEAN_RENDER_FOAM_STREAK_SPAN 4.0
// The sines of the field that places whitecaps as patches (R.11b).
#define OCEAN_RENDER_WHITECAP_WAVES 48
// PatchInstance::level of the horizon skirt's single instance (patches use 0 … lod::kMaxLevels).
#define OCEAN_RENDER_SKIRT_LEVEL 255u
// Triangles of the hex-tiled cascade lookups per cascade period (R.14): a point and the point
// one period away always lie in different tiles.
#define OCEAN_RENDER_HEX_TILES 3.0
// FrameUniforms::debug_view
#define OCEAN_RENDER_DEBUG_SHADED 0.0
#define OCEAN_RENDER_DEBUG_LOD_COLOURS 1.0
#define OCEAN_RENDER_DEBUG_NORMALS 2.0

// Set 0 of the scene pipelines (sky, ocean, wireframe).
#define OCEAN_RENDER_BINDING_FRAME 0         // FrameUniforms, std140, host-written each frame
#define OCEAN_RENDER_BINDING_DISPLACEMENT 1  // sampler2DArray RGBA16F (Dx, h, Dz, 0), per cascade
#define OCEAN_RENDER_BINDING_NORMAL 2        // sampler2DArray RGBA8 (n_x, n_z, foam, smoothness)
#define OCEAN_RENDER_BINDING_SKY_LUT 3       // sampler2D sky radiance, u azimuth, v √elevation
#define OCEAN_RENDER_BINDING_ENVIRONMENT 4   // sampler2D RGBA32F equirectangular radiance (R.17)
#define OCEAN_RENDER_BINDING_LOCAL 5         // sampler2DArray RGBA16F: (Dx, h, Dz); (Δs, Δf)
#define OCEAN_RENDER_BINDING_DAMPING 6       // sampler2DArray RGBA16F: band weights 0-3, 4-7; depth
#define OCEAN_RENDER_BINDING_REFLECTION 7    // sampler2D RGBA16F: objects mirrored in y = 0 (R.53)
#define OCEAN_RENDER_BINDING_FAR_MAP 8  // sampler2DArray RGBA16F: (h, sx, sz, sx² + sz²), mips
#define OCEAN_RENDER_SCENE_BINDINGS 9
// The far field's map pass (compute, R.13b): the frame's float3 map in, less the octaves the map
// does not resolve (push constants: the noise's FarNoiseMapParams, those octaves' amplitudes
// set, the others 0), mip 0 of the image out.
#define OCEAN_RENDER_FAR_BINDING_SOURCE 0  // storage buffer, float3 (h, ∂h/∂x, ∂h/∂z) per texel
#define OCEAN_RENDER_FAR_BINDING_IMAGE 1  // image2DArray rgba16f, level 0
#define OCEAN_RENDER_FAR_TILE 8           // workgroup side
// The deepest water the damping texture holds, m: deeper is deep water for every band.
#define OCEAN_RENDER_DEEP_M 1000.0
// Set 0 of the tone-map pipeline.
#define OCEAN_RENDER_BINDING_HDR 0  // sampler2D, the linear HDR image

// One cascade as the shaders see it (docs/rendering.md R.9, R.5).
struct CascadeUniforms {
  float patch_size_m;  // L
  float resolution;    // N
  float wavelength_m;  // λ, the dominant wavelength the mesh must carry
  float coarsest_mip;  // log2 N: the level of the 1×1 mip
};

// The far field (docs/rendering.md R.13–R.14): VR-GIS FFT+Perlin's noise octaves fitted to
// cascade 0's statistics, blended in between D_min and D_max, and the hex-tiled cascade lookups
// there.
struct FarFieldUniforms {
  vec4 cell_m;          // lattice spacing of octaves 0, 1, 2 (w unused)
  vec4 amplitude_m;     // amplitude of octaves 0, 1, 2 (w unused)
  vec4 slope_variance;  // σx² + σz² each octave carries (w unused): what a faded octave leaves
  float near_m;         // D_min: nearer, the simulation alone
  float far_m;          // D_max: farther, the far field alone
  float enabled;        // 0: no far field (before configure), 1: on
  float far_pad;
};

// One octave of the far field's noise at the frame's origin O and time t (R.13a, R.13b): the
// lattice coordinate (O − v_o·t)/s_o split on the CPU in double precision into whole cells
// (wrapped modulo 2³², as the lattice's indices) and the rest, as the noise map's texels are.
struct FarOctaveUniforms {
  float rest_u;  // fractional part along x, [0, 1)
  float rest_v;  // the same along z
  uint cells_u;  // whole cells along x (two's complement)
  uint cells_v;  // the same along z
};

// The far field's per-frame noise map (R.13b): which octaves it holds, where its window lies and
// how it hands over.
struct FarMapUniforms {
  vec4 in_map;         // x, y, z: 1 where octave 0, 1, 2 is read from the map, 0 where per pixel
  vec2 origin_m;       // world (x, z) of texel (0, 0) relative to the frame's origin O
  float size_m;        // side S of the window: texel (col, row) at origin + (col, row)·S/N
  float resolution;    // N texels per side; 0: no map (the analytic noise everywhere)
  float fade_texels;   // the map fades into the analytic noise over this many outer texels
  float coarsest_mip;  // the last level of the image's mip chain
  float map_pad0, map_pad1;
};

// Large worlds and the planet's curvature (docs/rendering.md R.15, R.16). Every position the
// shaders see is relative to the frame's origin O (the quadtree's centre, chosen in double
// precision on the CPU), so floats stay small however far the camera is from the world's origin.
struct PlanetUniforms {
  float inv_two_radius_per_m;  // 1/(2R) of the curvature drop d²/(2R) (R.15); 0: flat
  float inv_radius_per_m;      // 1/R: the tilt of the surface's up vector per metre (R.15)
  float planet_pad0, planet_pad1;
};
// Cascade c's reading of O: O/L_c wrapped to [0, M_c) periods (R.16); xy used, zw unused.
#define OCEAN_RENDER_ORIGIN_WRAP_M 131072.0

// The HDR environment map (docs/rendering.md R.17).
struct EnvironmentUniforms {
  float scale;  // multiplies the map's radiance (sky_brightness); 0: the analytic sky instead
  float environment_pad0, environment_pad1, environment_pad2;
};

// The local layer (ocean/waves.hpp, docs/rendering.md R.19): wakes and waveforms over a square
// world area, added to the cascades; its texture array holds, at the cells' centres, the layer's
// (Dx, h, Dz) (layer 0) and its change to the shading, (Δs_x, Δs_z, Δf) (layer 1).
struct LocalLayerUniforms {
  vec2 origin_m;     // (x0, z0): the area's corner of smallest x and z
  float size_m;      // side of the area
  float resolution;  // N cells per side; 0: no layer
  float calm;        // 1: the cascades are not drawn, only the layer (a calm sea)
  float local_pad0, local_pad1, local_pad2;
};

// The damping of the bands (docs/waves.md W.12–W.13, docs/rendering.md R.24): per-band weights
// and the depth baked on a square world grid; weight 1 and deep water outside it.
struct DampingUniforms {
  vec2 origin_m;             // (x0, z0)
  float size_m;              // side
  float resolution;          // N cells per side; 0: no damping
  vec3 absorption_per_m;     // pure water's absorption, RGB (R.24)
  float swash_phase;         // the swash's phase at the frame's time, fract(t/T_p), cycles (R.67)
  vec3 bottom_albedo;        // the seabed's reflectance seen through shallow water, RGB
  float swash_wavelength_m;  // L0 = g·T_p²/(2π) of the swash (W.40); 0: no swash drawn
};

// The sea on a sphere (docs/rendering.md R.30–R.38): positions relative to the camera in the
// local axes (east, up, north) of the surface point the view names; cascade_origin[c].xyz then
// holds the camera's planet-centred position over L_c, wrapped (R.38).
struct SphereUniforms {
  vec4 local_from_planet[3];  // rows: east, up, north in planet axes (w unused)
  float radius_m;             // R
  float enabled;              // 1: sphere mode
  // The sun's irradiance above the air (ShadingParams::sun_irradiance) and the camera's height
  // above the sphere, m (R.8c); the planet's centre relative to the camera, in the view's local
  // axes, is the w of local_from_planet's rows.
  float sun_top;
  float camera_altitude_m;
};

// One eye of a stereo frame drawn in one pass (docs/rendering.md R.25): what the mono fields
// view_proj and camera_pos_m hold for a single camera, per view index.
struct EyeUniforms {
  mat4 view_proj;          // the eye's lod::view_projection relative to the origin (R.16)
  mat4 inverse_view_proj;  // its inverse (the sky's view rays)
  vec4 camera_pos_m;       // the eye relative to the origin; w unused
  // The motion vectors of the eye (R.26, R.61), the OCEAN_MOTION_MULTIVIEW shaders': the eye a
  // frame ago relative to this frame's origin, and a far point's current clip → previous clip.
  mat4 previous_view_proj;
  mat4 sky_reprojection;
};

// The water below the surface (docs/rendering.md R.50–R.52): its absorption (the seabed's, pure
// water) and scattering, which make the fog a camera under the sea looks through.
struct UnderwaterUniforms {
  vec3 absorption_per_m;   // a per channel, RGB
  float scattering_per_m;  // b, every channel
  float skirt_extent_m;    // E: the outer half-extent of the drawn sea, from the camera
  float bed_enabled;       // 1: View::seabed is drawn, seen from below too (R.52)
  float underwater_pad1, underwater_pad2;
  vec4 bed_albedo_depth;  // the seabed's albedo (rgb) and flat depth, m (a)
};

// The waves shorter than the finest cascade drawn near the eye (R.62; SurfaceDescription::
// short_waves): per wave (k_x, k_z, a·k, phase at the frame's origin and time), by increasing k.
struct RippleUniforms {
  vec4 waves[OCEAN_RENDER_MAX_RIPPLES];
  float count;  // waves in use; 0: none drawn
  float ripple_pad0, ripple_pad1, ripple_pad2;
};

// The sea's whitecaps as patches (R.11b): the sines of a Gaussian field g of unit variance, per
// sine (k_x, k_z, amplitude, phase at the quadtree's centre and the frame's time); count 0 draws each
// cascade's breaking probability as it is.
struct WhitecapUniforms {
  vec4 waves[OCEAN_RENDER_WHITECAP_WAVES];
  float count;
  float whitecap_pad0, whitecap_pad1, whitecap_pad2;
};

// Everything per frame, one uniform buffer (std140).
struct FrameUniforms {
  mat4 view_proj;  // lod::view_projection of the camera, column-major
  vec3 camera_pos_m;
  float fov_y_rad;  // vertical field of view
  vec3 sun_dir;     // unit vector towards the sun
  // The share of the pixel's footprint (its screen derivatives) that the shading filters over:
  // 1, or 1/4 with temporal anti-aliasing, whose 16 jittered frames sample the pixel as a
  // 4 × 4 grid does (R.61).
  float footprint_scale;
  vec3 sun_ground;  // sun irradiance at sea level on a plane facing the sun, RGB
  float sun_ground_pad;
  vec3 sky_ambient;  // sky irradiance on a horizontal plane, RGB
  float sky_ambient_pad;
  vec3 water_colour;    // single-scattering albedo of the water body, RGB
  float crest_scatter;  // gain of the light through thin crests
  float foam_brightness;
  float roughness;          // α0: √ of the slope variance of the waves below the finest cascade
  float fog_density_per_m;  // ρ of the horizon fog (R.8)
  float map_base_normal_length;  // |n| a level-0 texel of the normal map stores (R.5)
  vec2 grid_centre_m;   // world x, z of the quadtree's centre
  float ocean_size_m;   // side S of the quadtree square
  float border_fade_m;  // width over which the displacement fades out at the border (R.10)
  float lod_scale;      // τ
  float vertices;       // V, quads per patch side
  float debug_view;     // OCEAN_RENDER_DEBUG_*
  float cascade_count;  // cascades to sample; 0 before any simulation input
  float hs_m;           // significant wave height Hs of the configured sea
  // 1: the cascades' foam is each the sea's breaking probability (FoamSource::breaking), mixed
  // by foam_weights; 0: each cascade's own ramp, united (R.11).
  float foam_weighted;
  // The projection's sub-pixel offset this frame, NDC (temporal anti-aliasing, R.61; 0 without):
  // view_proj holds it, the motion vectors (R.26) leave it out.
  float jitter_ndc_x, jitter_ndc_y;
  CascadeUniforms cascades[OCEAN_RENDER_MAX_CASCADES];
  FarFieldUniforms far_field;
  PlanetUniforms planet;
  vec4 cascade_origin[OCEAN_RENDER_MAX_CASCADES];
  EnvironmentUniforms environment;
  LocalLayerUniforms local;
  DampingUniforms damping;
  SphereUniforms sphere;
  EyeUniforms eyes[2];  // stereo (OCEAN_MULTIVIEW shaders) only: eye 0 left, 1 right
  UnderwaterUniforms underwater;
  FarOctaveUniforms far_octaves[3];  // the noise's lattice at O and t (R.13b)
  FarMapUniforms far_map;            // the per-frame map (R.13b)
  vec4 foam_weights[OCEAN_RENDER_MAX_CASCADES / 4];  // cascade c's at [c / 4][c % 4] (R.11)
  // The air between the eye and the water (R.8b): Rayleigh extinction at sea level (rgb, 1/m)
  // and its scale height (w, m; 0: no aerial perspective); the haze's extinction (x), scale
  // height (y), Henyey–Greenstein g (z) and the sky's brightness (w).
  vec4 air_rayleigh;
  vec4 air_mie;
  RippleUniforms ripples;  // the short waves near the eye (R.62)
  // The foam's drift over its e-folding time (W.29–W.31): xy = u_d·τ along the wind, (x, z) m;
  // zero draws each cascade's foam where the map holds it. zw unused.
  vec4 foam_streak;
  WhitecapUniforms whitecaps;  // the sea's whitecaps as patches (R.11b)
};

// Push constants of the sky pass (std430).
struct SkyPush {
  mat4 inverse_view_proj;
};

// Push constants of the tone-map pass (std430).
struct TonemapPush {
  float exposure;
};

#ifdef __cplusplus
// The offsets std140 gives the block's members.
static_assert(offsetof(FrameUniforms, camera_pos_m) == 64);
static_assert(offsetof(FrameUniforms, sun_dir) == 80);
static_assert(offsetof(FrameUniforms, sun_ground) == 96);
static_assert(offsetof(FrameUniforms, sky_ambient) == 112);
static_assert(offsetof(FrameUniforms, water_colour) == 128);
static_assert(offsetof(FrameUniforms, foam_brightness) == 144);
static_assert(offsetof(FrameUniforms, grid_centre_m) == 160);
static_assert(offsetof(FrameUniforms, lod_scale) == 176);
static_assert(offsetof(FrameUniforms, hs_m) == 192);
static_assert(offsetof(FrameUniforms, cascades) == 208);
static_assert(sizeof(CascadeUniforms) == 16);
static_assert(offsetof(FrameUniforms, far_field) == 208 + 16 * OCEAN_RENDER_MAX_CASCADES);
static_assert(sizeof(FarFieldUniforms) == 64);
static_assert(offsetof(FrameUniforms, planet) == 272 + 16 * OCEAN_RENDER_MAX_CASCADES);
static_assert(sizeof(PlanetUniforms) == 16);
static_assert(offsetof(FrameUniforms, cascade_origin) == 288 + 16 * OCEAN_RENDER_MAX_CASCADES);
static_assert(offsetof(FrameUniforms, environment) == 288 + 32 * OCEAN_RENDER_MAX_CASCADES);
static_assert(sizeof(LocalLayerUniforms) == 32);
static_assert(offsetof(FrameUniforms, local) == 304 + 32 * OCEAN_RENDER_MAX_CASCADES);
static_assert(sizeof(DampingUniforms) == 48);
static_assert(offsetof(FrameUniforms, damping) == 336 + 32 * OCEAN_RENDER_MAX_CASCADES);
static_assert(offsetof(FrameUniforms, sphere) == 384 + 32 * OCEAN_RENDER_MAX_CASCADES);
static_assert(sizeof(SphereUniforms) == 64);
static_assert(sizeof(EyeUniforms) == 272);
static_assert(offsetof(FrameUniforms, eyes) == 448 + 32 * OCEAN_RENDER_MAX_CASCADES);
static_assert(offsetof(FrameUniforms, underwater) == 992 + 32 * OCEAN_RENDER_MAX_CASCADES);
static_assert(sizeof(FarOctaveUniforms) == 16);
static_assert(offsetof(FrameUniforms, far_octaves) == 1040 + 32 * OCEAN_RENDER_MAX_CASCADES);
static_assert(sizeof(FarMapUniforms) == 48);
static_assert(offsetof(FrameUniforms, far_map) == 1088 + 32 * OCEAN_RENDER_MAX_CASCADES);
static_assert(offsetof(FrameUniforms, foam_weights) == 1136 + 32 * OCEAN_RENDER_MAX_CASCADES);
static_assert(offsetof(FrameUniforms, air_rayleigh) == 1136 + 36 * OCEAN_RENDER_MAX_CASCADES);
static_assert(offsetof(FrameUniforms, ripples) == 1168 + 36 * OCEAN_RENDER_MAX_CASCADES);
static_assert(sizeof(RippleUniforms) == 16 * OCEAN_RENDER_MAX_RIPPLES + 16);
static_assert(offsetof(FrameUniforms, foam_streak) ==
              1184 + 36 * OCEAN_RENDER_MAX_CASCADES + 16 * OCEAN_RENDER_MAX_RIPPLES);
static_assert(offsetof(FrameUniforms, whitecaps) ==
              1200 + 36 * OCEAN_RENDER_MAX_CASCADES + 16 * OCEAN_RENDER_MAX_RIPPLES);
static_assert(sizeof(WhitecapUniforms) == 16 * OCEAN_RENDER_WHITECAP_WAVES + 16);
static_assert(sizeof(FrameUniforms) == 1216 + 36 * OCEAN_RENDER_MAX_CASCADES +
                                           16 * OCEAN_RENDER_MAX_RIPPLES +
                                           16 * OCEAN_RENDER_WHITECAP_WAVES);
static_assert(sizeof(SkyPush) == 64);
}  // namespace ocean::render::shader
#endif

#endif
