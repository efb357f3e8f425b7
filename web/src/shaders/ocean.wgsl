// ocean.wgsl — drawing: the sky on a full-screen triangle, then the water on a camera-following
// polar grid displaced by the sum of the cascades' fields (Aebi, VR Ocean, eq. 44) and shaded with
// the sum of their slopes, read from trilinearly filtered normal/foam mips as the native renderer
// does (src/render/shaders/ocean.frag).
//
// This work is based on:
//   - Schlick, C. (1994) An inexpensive BRDF model for physically-based rendering: Fresnel
//     F(θ) = F0 + (1 − F0)(1 − cos θ)^5 with F0 = 0.02 for water (Paleologue 2024:
//     0.02 + 0.98(1 − cos θ)^5, sharp specular, horizon-only fog).
//   - Mitchell, J. (2005) Real-Time Synthesis and Rendering of Ocean Water: fog(s·(1 − r) +
//     r·(env + sun)); docs/rendering.md describes the native renderer's version.
// Horizon fog only (Paleologue 2024's choice): the sea fades into the sky colour at the horizon.

struct View {
  view_proj: mat4x4f,
  inv_view_proj: mat4x4f,
  eye: vec4f,          // camera position, m (w unused)
  sun: vec4f,          // direction towards the sun (w unused)
  resolution: f32,     // N
  grid_rings: f32,     // rings of the polar grid
  grid_segments: f32,  // segments per ring
  cascades: f32,       // cascade count, 1 … 4
  patch_size_m: vec4f, // L of each cascade, largest first
  geometry_wavelength_m: vec4f,  // each cascade's displacement fades against it (R.9)
}

@group(0) @binding(0) var<uniform> view: View;
@group(0) @binding(1) var<storage, read> displacement: array<vec4f>;  // (Dx, h, Dz, 0), N² per cascade
@group(0) @binding(2) var normal_foam: texture_2d_array<f32>;         // (n, foam) mips, a layer per cascade
@group(0) @binding(3) var trilinear: sampler;

const kFarRadius = 20000.0;  // m: the grid reaches the horizon
const kNearRadius = 0.5;     // m: innermost ring

// Sky radiance along a direction: a horizon-to-zenith gradient and a sun disc.
fn sky(dir: vec3f) -> vec3f {
  let up = clamp(dir.y, -0.05, 1.0);
  let horizon = vec3f(0.78, 0.85, 0.92);
  let zenith = vec3f(0.20, 0.42, 0.75);
  var c = mix(horizon, zenith, pow(max(up, 0.0), 0.45));
  let s = max(dot(dir, view.sun.xyz), 0.0);
  c += vec3f(1.0, 0.9, 0.7) * (pow(s, 800.0) * 6.0 + pow(s, 12.0) * 0.15);
  return c;
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
@fragment fn sky_fs(in: SkyOut) -> @location(0) vec4f {
  let far = view.inv_view_proj * vec4f(in.ndc, 1.0, 1.0);
  return vec4f(sky(normalize(far.xyz / far.w - view.eye.xyz)), 1.0);
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

@fragment fn water_fs(in: WaterOut) -> @location(0) vec4f {
  // Each cascade's mean normal over the pixel (the mips pick the level from the pixel footprint,
  // so far normals are averages, not aliased samples) becomes a surface gradient; the gradients
  // add, as the heights do. Texel i sits at x = i·L/N: half a texel's shift.
  var slope = vec2f(0.0);
  var f = 0.0;
  for (var c = 0u; c < u32(view.cascades); c++) {
    let uv = in.plane_xz / view.patch_size_m[c] + 0.5 / view.resolution;
    let m = textureSample(normal_foam, trilinear, uv, c);
    slope += m.xz / max(m.y, 0.05);
    f += m.w;
  }
  let n = normalize(vec3f(slope.x, 1.0, slope.y));
  let to_eye = view.eye.xyz - in.world;
  let distance = length(to_eye);
  let v = to_eye / distance;
  let cos_theta = clamp(dot(n, v), 0.0, 1.0);
  let fresnel = 0.02 + 0.98 * pow(1.0 - cos_theta, 5.0);  // Schlick, F0 = 0.02
  var r = reflect(-v, n);
  r.y = abs(r.y);  // no reflections of the sea itself: fold into the upper hemisphere
  let reflected = sky(r);
  let body = vec3f(0.004, 0.045, 0.075) + vec3f(0.0, 0.04, 0.05) * max(view.sun.y, 0.0);
  let h = normalize(view.sun.xyz + v);
  let specular = pow(max(dot(n, h), 0.0), 600.0) * 4.0 * fresnel;
  var c = body * (1.0 - fresnel) + reflected * fresnel + vec3f(1.0, 0.9, 0.7) * specular;
  c = mix(c, vec3f(0.9, 0.93, 0.95), clamp(f, 0.0, 1.0) * 0.8);
  // Horizon fog: only the distance matters, towards the sky's horizon colour.
  let fog = 1.0 - exp(-distance / 6000.0);
  c = mix(c, sky(normalize(vec3f(-v.x, 0.0, -v.z))), clamp(fog, 0.0, 1.0));
  return vec4f(c, 1.0);
}
