// Foam drawn out along the wind (docs/waves.md W.29–W.31, docs/rendering.md R.11). Foam floats
// downwind with the surface's wind drift u_d (about 3 % of U10; Wu 1975) while it decays with the
// e-folding time τ of a whitecap (Monahan 1971; Callaghan et al. 2012), so the foam seen at p is
// the foam that formed at p − u_d·a, a ago, over the ages a that survive, e^{−a/τ}/τ (W.30):
//
//   F_drawn(p) = ∫₀^∞ F(p − u_d·a)·e^{−a/τ} da/τ                                        (W.31)
//
// the cascade's map F read through a footprint along the wind whose mean length is |u_d|·τ and
// whose width is the pixel's. Its weights sum to one, so the drawn coverage is the map's
// (Monahan's law, M.7.4, is untouched). Taken with K taps at the ages a_j = (j + ½)·S·τ/K (S = 4:
// 98 % of the weight), weights e^{−a_j/τ} normalised; each read at the mip whose texels span half
// the taps' spacing, so that the taps join into one streak instead of repeating a fleck.

// Cascade c's foam at uv (its plain sample, `lod_bias` the pixel's own bias) drawn out downwind.
float streaked_foam(vec2 uv, int c, float lod_bias) {
  vec2 drift_m = u.foam_streak.xy;  // u_d·τ, m
  float inv_size = 1.0 / u.cascades[c].patch_size_m;
  float step_tau = OCEAN_RENDER_FOAM_STREAK_SPAN / float(OCEAN_RENDER_FOAM_STREAK_TAPS);
  float spacing_m = length(drift_m) * step_tau;
  float texel_m = u.cascades[c].patch_size_m / u.cascades[c].resolution;
  float bias = lod_bias + max(log2(max(spacing_m / texel_m, 1e-6)) - 1.0, 0.0);
  float sum = 0.0, weights = 0.0;
  for (int j = 0; j < OCEAN_RENDER_FOAM_STREAK_TAPS; ++j) {
    float age = (float(j) + 0.5) * step_tau;  // a_j/τ
    float w = exp(-age);
    sum += w * texture(normal_map, vec3(uv - drift_m * (age * inv_size), float(c)), bias).z;
    weights += w;
  }
  return sum / weights;
}
