// ocean.wgsl — drawing: the sky on a full-screen triangle, then the water on a camera-following
// polar grid displaced by the sum of the cascades' fields (Aebi, VR Ocean, eq. 44) and shaded with
// the sum of their slopes, read from trilinearly filtered normal/foam mips, as the native renderer
// does (src/render/shaders/ocean.frag, sky.frag, render_common.glsl, tonemap.frag). Each function
// names the native one it ports; docs/rendering.md has the equations (R.n).
//
// This work is based on:
//   - The native sky (R.1–R.4: Nishita et al. 1993, Henyey & Greenstein 1941, Kasten & Young
//     1989), its table filled in WebAssembly by the library's own render::Sky::fill_lut and
//     sampled as Hillaire (2020) does.
//   - Schlick, C. (1994): F = 0.02 + 0.98(1 − cos θ)^5 for water (R.6; Paleologue 2024).
//   - Walter, B. et al. (2007) Microfacet models for refraction through rough surfaces, eqs. 25
//     and 27: Beckmann facets with Smith's masking for the sun's glitter (R.7), their slope
//     variance Cox & Munk's (1954) through the mips' averaged normals (Toksvig 2005; R.5).
//   - Mitchell, J. (2005) Real-Time Synthesis and Rendering of Ocean Water: s·(1 − r) +
//     r·(env + sun) (R.12); the horizon fog of Paleologue (2024) (R.8).
//   - Narkowicz, K. (2015) ACES filmic tone mapping curve (R.12), then the sRGB transfer function
//     of IEC 61966-2-1 (the canvas is a plain 8-bit format, so the shader encodes).

struct View {
  view_proj: mat4x4f,
  inv_view_proj: mat4x4f,
  eye: vec4f,          // camera position, m; w: Hs of the sea, m
  sun: vec4f,          // direction towards the sun; w: exposure
  resolution: f32,     // N
  grid_rings: f32,     // rings of the polar grid
  grid_segments: f32,  // segments per ring
  cascades: f32,       // cascade count, 1 … 4
  patch_size_m: vec4f, // L of each cascade, largest first
  geometry_wavelength_m: vec4f,  // each cascade's displacement fades against it (R.9)
  foam_weight: vec4f,  // each cascade's share of the bands' slope variance (R.11)
  sun_ground: vec4f,   // sun irradiance at sea level (R.3); w: α₀², the short waves' slopes (R.5)
  sky_ambient: vec4f,  // sky irradiance on a horizontal plane (R.4); w: crest_scatter
  water_colour: vec4f, // the water body's albedo; w: foam_brightness
  air_rayleigh: vec4f, // Rayleigh β per m; w: its scale height, m (R.8b)
  air_mie: vec4f,      // haze β per m, its scale height m, Henyey–Greenstein g, sky brightness
  fog: vec4f,          // x: the horizon fog's density per m (R.8)
}

@group(0) @binding(0) var<uniform> view: View;
@group(0) @binding(1) var<storage, read> displacement: array<vec4f>;  // (Dx, h, Dz, 0), N² per cascade
@group(0) @binding(2) var normal_foam: texture_2d_array<f32>;         // (n, foam) mips, a layer per cascade
@group(0) @binding(3) var trilinear: sampler;
@group(0) @binding(4) var sky_lut: texture_2d<f32>;  // render::Sky's table, 128 × 64
@group(0) @binding(5) var sky_sampler: sampler;      // repeats in azimuth, clamps in elevation

const kFarRadius = 20000.0;  // m: the grid reaches the horizon
const kNearRadius = 0.5;     // m: innermost ring
const PI = 3.14159265358979;

// render_common.glsl sky_radiance (R.4): the table at u = azimuth/2π, v = √(elevation/(π/2));
// below the horizon the horizon's radiance.
fn sky(v: vec3f) -> vec3f {
  let elevation = asin(clamp(v.y, 0.0, 1.0));
  let azimuth = atan2(v.z, v.x);
  let uv = vec2f(azimuth / (2.0 * PI), sqrt(elevation / (0.5 * PI)));
  return textureSampleLevel(sky_lut, sky_sampler, uv, 0.0).rgb;
}

// render_common.glsl fresnel_schlick (R.6).
fn fresnel_schlick(cos_theta: f32) -> f32 {
  let m = 1.0 - clamp(cos_theta, 0.0, 1.0);
  let m2 = m * m;
  return 0.02 + 0.98 * m2 * m2 * m;
}

// render_common.glsl horizon_fog (R.8): (1 − exp(−(dρ)²))·(1 − |v_y|)⁴.
fn horizon_fog(distance_m: f32, view_y: f32) -> f32 {
  let d = distance_m * view.fog.x;
  var w = 1.0 - abs(view_y);
  w *= w;
  return (1.0 - exp(-d * d)) * w * w;
}

// render_common.glsl fog_colour: the sky's horizon (elevation 0) in this azimuth.
fn fog_colour(view_dir: vec3f) -> vec3f {
  let h = view_dir.xz;
  let len = length(h);
  let dir = select(vec3f(1.0, 0.0, 0.0), vec3f(h.x / len, 0.0, h.y / len), len > 1e-5);
  return sky(normalize(dir));
}

// render_common.glsl mean_air_density and aerial_perspective (R.8b): the sky's air along the
// segment from the eye to a point at height point_y, distance_m away along view_dir.
fn mean_air_density(y_low: f32, y_high: f32, scale_height_m: f32) -> f32 {
  let x = (y_high - y_low) / scale_height_m;
  return exp(-y_low / scale_height_m) * select((1.0 - exp(-x)) / x, 1.0 - 0.5 * x, x < 1e-3);
}
fn aerial_perspective(c: vec3f, point_y: f32, distance_m: f32, view_dir: vec3f) -> vec3f {
  let eye_y = view.eye.y;
  let low = min(eye_y, point_y);
  let high = max(eye_y, point_y);
  let tau_r = view.air_rayleigh.rgb *
              (distance_m * mean_air_density(low, high, view.air_rayleigh.w));
  let tau_m = view.air_mie.x * distance_m * mean_air_density(low, high, view.air_mie.y);
  let tau = tau_r + tau_m;
  let t = exp(-tau);
  let mu = dot(view_dir, view.sun.xyz);
  let g = view.air_mie.z;
  let d = 1.0 + g * g - 2.0 * g * mu;
  let hg = (1.0 - g * g) / (4.0 * PI * d * sqrt(d));
  let phase = (tau_r * (3.0 / (16.0 * PI) * (1.0 + mu * mu) + 0.25 / (4.0 * PI)) + tau_m * hg) /
              max(tau, vec3f(1e-20));
  return c * t + view.air_mie.w * view.sun_ground.rgb * (1.0 - t) * phase;
}

// render_common.glsl beckmann_masking and glitter_lobe (R.7): D·G/(4·n·l·n·v) of Beckmann
// facets of mean square slope m2 with Smith's masking (Walter et al. 2007, eqs. 25, 27).
fn beckmann_masking(c: f32, m2: f32) -> f32 {
  let a = c / sqrt(m2 * max(1.0 - c * c, 1e-8));
  return select((3.535 * a + 2.181 * a * a) / (1.0 + 2.276 * a + 2.577 * a * a), 1.0, a >= 1.6);
}
fn glitter_lobe(n_dot_h: f32, n_dot_v: f32, n_dot_l: f32, m2: f32) -> f32 {
  let c2 = max(n_dot_h * n_dot_h, 1e-8);
  let D = exp(-(1.0 - c2) / (c2 * m2)) / (PI * m2 * c2 * c2);
  let G = beckmann_masking(n_dot_v, m2) * beckmann_masking(n_dot_l, m2);
  return D * G / max(4.0 * n_dot_v * n_dot_l, 1e-6);
}

// tonemap.frag (R.12): exposure and Narkowicz's (2015) ACES fit, then the sRGB encoding of
// IEC 61966-2-1 (12.92·x below 0.0031308, else 1.055·x^(1/2.4) − 0.055), which the native
// renderer's R8G8B8A8_SRGB target applies on store.
fn aces(x: vec3f) -> vec3f {
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), vec3f(0.0), vec3f(1.0));
}
fn srgb_encode(x: vec3f) -> vec3f {
  return select(1.055 * pow(x, vec3f(1.0 / 2.4)) - 0.055, 12.92 * x, x <= vec3f(0.0031308));
}
fn tone_map(c: vec3f) -> vec4f {
  return vec4f(srgb_encode(aces(max(c, vec3f(0.0)) * view.sun.w)), 1.0);
}

// Bilinear fetch of cascade c's periodic displacement at world (x, z).
fn texel(c: u32, x: i32, z: i32) -> vec4f {
  let n = i32(view.resolution);
  return displacement[(c * u32(n) + u32(((z % n) + n) % n)) * u32(n) + u32(((x % n) + n) % n)];
}
fn displacement_at(c: u32, xz: vec2f) -> vec3f {
  let g = xz / view.patch_size_m[c] * view.resolution;
  let b = floor(g);
  let f = g - b;
  let x = i32(b.x);
  let z = i32(b.y);
  return mix(mix(texel(c, x, z), texel(c, x + 1, z), f.x),
             mix(texel(c, x, z + 1), texel(c, x + 1, z + 1), f.x), f.y).xyz;
}

struct SkyOut { @builtin(position) pos: vec4f, @location(0) ndc: vec2f, }

@vertex fn sky_vs(@builtin(vertex_index) v: u32) -> SkyOut {
  let p = vec2f(f32((v << 1u) & 2u), f32(v & 2u)) * 2.0 - 1.0;
  return SkyOut(vec4f(p, 1.0, 1.0), p);
}
// sky.frag: the sky's radiance along the pixel's ray and the sun's disc, angular radius 0.27°
// with a soft edge, at 2 % of its true radiance E/Ω (as natively, so that the limb stays visible).
@fragment fn sky_fs(in: SkyOut) -> @location(0) vec4f {
  let far = view.inv_view_proj * vec4f(in.ndc, 1.0, 1.0);
  let v = normalize(far.xyz / far.w - view.eye.xyz);
  var c = sky(v);
  let radius = radians(0.27);
  let solid_angle = PI * radius * radius;
  let edge = smoothstep(cos(radius * 1.3), cos(radius), dot(v, view.sun.xyz));
  if (v.y > 0.0) {
    c += edge * view.sun_ground.rgb / solid_angle * 0.02;
  }
  return tone_map(c);
}

struct WaterOut {
  @builtin(position) pos: vec4f,
  @location(0) world: vec3f,
  @location(1) plane_xz: vec2f,
}

@vertex fn water_vs(@builtin(vertex_index) v: u32) -> WaterOut {
  // Two triangles per quad of the polar grid; radii grow geometrically to the horizon.
  let segments = u32(view.grid_segments);
  let quad = v / 6u;
  let corner = array<vec2u, 6>(vec2u(0u, 0u), vec2u(1u, 0u), vec2u(0u, 1u), vec2u(0u, 1u),
                               vec2u(1u, 0u), vec2u(1u, 1u))[v % 6u];
  let ring = quad / segments + corner.y;
  let segment = quad % segments + corner.x;
  let radius = kNearRadius * pow(kFarRadius / kNearRadius, f32(ring) / view.grid_rings);
  let angle = f32(segment) / f32(segments) * 6.283185307;
  let xz = view.eye.xz + radius * vec2f(cos(angle), sin(angle));
  // The native renderer's geometry weight (R.9, src/render/shaders/ocean.vert): each cascade's
  // displacement is full while the vertex spacing (here the ring step, the larger of the grid's
  // two) is below a quarter of its wavelength and gone at half, the grid's Nyquist limit; the
  // mipped normals carry the cascade beyond.
  let spacing = radius * (pow(kFarRadius / kNearRadius, 1.0 / view.grid_rings) - 1.0);
  var d = vec3f(0.0);
  for (var c = 0u; c < u32(view.cascades); c++) {
    let weight = clamp(2.0 - 4.0 * spacing / view.geometry_wavelength_m[c], 0.0, 1.0);
    d += weight * displacement_at(c, xz);
  }
  let world = vec3f(xz.x + d.x, d.y, xz.y + d.z);
  var out: WaterOut;
  out.pos = view.view_proj * vec4f(world, 1.0);
  out.world = world;
  out.plane_xz = xz;
  return out;
}

// ocean.frag's shading of the water above it (R.5–R.8b, R.11, R.12), without what the page does
// not draw (objects, seabed, wakes, the far field, the underside).
@fragment fn water_fs(in: WaterOut) -> @location(0) vec4f {
  // Each cascade's mean normal over the pixel (the mips pick the level from the pixel footprint,
  // so far normals are averages, not aliased samples) becomes a surface gradient; the gradients
  // add, as the heights do (R.5). Texel i sits at x = i·L/N: half a texel's shift. The slope
  // variance the averaging removed, (|n|₀/|n|)² − 1 with |n|₀ = 1 (level 0 holds unit normals),
  // adds to the short waves' α₀² (Toksvig 2005; LEAN mapping, Olano & Baker 2010). The foam is
  // the breaking probability weighed by the cascades' shares (R.11).
  var slope = vec2f(0.0);
  var variance = view.sun_ground.w;
  var foam = 0.0;
  for (var c = 0u; c < u32(view.cascades); c++) {
    let uv = in.plane_xz / view.patch_size_m[c] + 0.5 / view.resolution;
    let m = textureSample(normal_foam, trilinear, uv, c);
    slope += m.xz / max(m.y, 0.05);
    let len2 = max(dot(m.xyz, m.xyz), 1e-4);
    variance += max(1.0 / len2 - 1.0, 0.0);
    foam += view.foam_weight[c] * m.w;
  }
  var N = normalize(vec3f(slope.x, 1.0, slope.y));
  let alpha_sq = clamp(variance, 2.5e-4, 1.0);
  let to_eye = view.eye.xyz - in.world;
  let distance_m = length(to_eye);
  let V = to_eye / distance_m;
  let L = view.sun.xyz;
  // Normals that face away from the viewer (grazing views of steep waves) are bent back.
  var n_dot_v = dot(N, V);
  if (n_dot_v < 1e-3) {
    N = normalize(N + (1e-3 - n_dot_v) * V);
    n_dot_v = 1e-3;
  }
  // Reflection of the sky (R.6).
  let env = sky(reflect(-V, N));
  let fresnel = fresnel_schlick(n_dot_v);
  // Sun specular (R.7): radiance reflected = BRDF·E·cos, divided by r for Mitchell's form.
  let sun_e = view.sun_ground.rgb;
  let H = normalize(V + L);
  let n_dot_l = max(dot(N, L), 0.0);
  let n_dot_h = max(dot(N, H), 0.0);
  let lobe = glitter_lobe(n_dot_h, n_dot_v, n_dot_l, alpha_sq);
  let fresnel_h = fresnel_schlick(max(dot(V, H), 0.0));
  let sun = sun_e * (lobe * fresnel_h * n_dot_l) / max(fresnel, 1e-4);
  // Light scattered out of the deep water body and through thin crests lit from behind (R.11).
  let sky_e = view.sky_ambient.rgb;
  let albedo = view.water_colour.rgb;
  let sun_in = max(L.y, 0.0) * (1.0 - fresnel_schlick(max(L.y, 0.0)));
  let body = albedo * (sun_e * sun_in + sky_e) / PI;
  let crest = clamp(in.world.y / max(0.5 * view.eye.w, 0.05), 0.0, 2.0);  // height over Hs/2
  let g = 0.6;
  let hg_d = 1.0 + g * g - 2.0 * g * dot(-L, V);
  let forward = (1.0 - g * g) / (4.0 * PI * hg_d * sqrt(hg_d));  // Henyey–Greenstein
  let through = view.sky_ambient.w * albedo * sun_e * forward * crest *
                pow(clamp(0.5 - 0.5 * dot(L, N), 0.0, 1.0), 2.0);
  // Mitchell 2005, eq. 5: s·(1 − r) + r·(env + sun); foam a diffuse layer over it (R.11).
  var c = (body + through) * (1.0 - fresnel) + fresnel * (env + sun);
  let foam_colour = 0.85 * view.water_colour.w * (sun_e * max(dot(N, L), 0.0) + sky_e) / PI;
  c = mix(c, foam_colour, clamp(foam, 0.0, 1.0));
  // The air between (R.8b), then the horizon fog (R.8).
  c = aerial_perspective(c, in.world.y, distance_m, -V);
  c = mix(c, fog_colour(-V), horizon_fog(distance_m, V.y));
  return tone_map(c);
}
