// ripples.glsl — the waves shorter than the finest cascade near the eye (docs/rendering.md R.62):
// a sum of sines drawn from Elfouhaily et al.'s (1997) spectrum beyond the cascades' grids
// (docs/math.md M.9.4), each drawn where the pixel resolves it and otherwise left in the
// roughness, so the total slope variance is the same at every distance (Olano & Baker 2010:
// variances of independent layers add).
#ifndef OCEAN_RENDER_RIPPLES_GLSL
#define OCEAN_RENDER_RIPPLES_GLSL

// Adds the resolved short waves' surface gradient (as normal x/y, z/y: −∇η) at the point xz to
// `slope` and takes their slope variance out of `variance`. dx, dy: the pixel's footprint (the
// world position's screen derivatives). Wave i with vector k and slope amplitude a·k changes its
// phase by Δθ = max(|k·dx|, |k·dy|) across a pixel; it is drawn with weight
// w = clamp(2 − 2Δθ/π, 0, 1), whole down to 4 pixels a wavelength and gone at 2 (Nyquist), and
// w²·(a·k)²/2 of its slope variance leaves the roughness. The phases are the CPU's at the camera
// (R.16), so k·(x − x_eye) stays small where any wave is drawn.
void ripples_at(vec2 xz, vec2 dx, vec2 dy, inout vec2 slope, inout float variance) {
  int n = u.local.calm > 0.5 ? 0 : int(u.ripples.count);  // calm: the layer alone
  if (n == 0) return;
  // A lower bound of Δθ/|k| over every direction: max(|k̂·dx|, |k̂·dy|) ≥ |dx × dy|/(2·max(|dx|, |dy|)).
  // The waves come by increasing k, so once the bound passes π none further is drawn.
  float floor_rate = abs(dx.x * dy.y - dx.y * dy.x) / (2.0 * max(max(length(dx), length(dy)), 1e-12));
  vec2 r = xz - u.camera_pos_m.xz;
  for (int i = 0; i < n; ++i) {
    vec4 wave = u.ripples.waves[i];
    float k = length(wave.xy);
    if (k * floor_rate >= PI) break;
    float dtheta = max(abs(dot(wave.xy, dx)), abs(dot(wave.xy, dy)));
    float w = clamp(2.0 - dtheta * (2.0 / PI), 0.0, 1.0);
    if (w <= 0.0) continue;
    float theta = dot(wave.xy, r) + wave.w;
    slope += (w * wave.z * sin(theta) / k) * wave.xy;  // −∇(a·cos θ) = a·k·sin θ·k̂
    variance -= w * w * 0.5 * wave.z * wave.z;
  }
}

#endif
