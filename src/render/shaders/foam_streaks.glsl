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
// 98 % of the weight), weights e^{−a_j/τ} normalised; each tap filters the map over the taps'
// spacing along the wind and the pixel's footprint across it (an anisotropic lookup), so that
// the taps join into one streak instead of repeating a fleck, and the streak stays as narrow as
// the fleck.

// Cascade c's foam at uv drawn out downwind; dx_uv, dy_uv the pixel's footprint in uv, `plain`
// the map's foam there, which a pixel longer along the wind than the whole footprint keeps (the
// taps would all read it, a fraction of the pixel apart).
float streaked_foam(vec2 uv, int c, vec2 dx_uv, vec2 dy_uv, float plain) {
  vec2 drift_m = u.foam_streak.xy;  // u_d·τ, m
  float inv_size = 1.0 / u.cascades[c].patch_size_m;
  float step_tau = OCEAN_RENDER_FOAM_STREAK_SPAN / float(OCEAN_RENDER_FOAM_STREAK_TAPS);
  vec2 along = normalize(drift_m), across = vec2(-along.y, along.x);
  // The pixel's footprint in the wind's frame, stretched along the wind to the taps' spacing.
  float spacing_uv = length(drift_m) * step_tau * inv_size;
  float pixel_along = max(abs(dot(dx_uv, along)), abs(dot(dy_uv, along)));
  float pixel_across = max(abs(dot(dx_uv, across)), abs(dot(dy_uv, across)));
  if (spacing_uv * float(OCEAN_RENDER_FOAM_STREAK_TAPS) <= pixel_along) return plain;
  vec2 g_along = along * max(spacing_uv, pixel_along), g_across = across * pixel_across;
  float sum = 0.0, weights = 0.0;
  for (int j = 0; j < OCEAN_RENDER_FOAM_STREAK_TAPS; ++j) {
    float age = (float(j) + 0.5) * step_tau;  // a_j/τ
    float w = exp(-age);
    vec3 at = vec3(uv - drift_m * (age * inv_size), float(c));
    sum += w * textureGrad(normal_map, at, g_along, g_across).z;
    weights += w;
  }
  return sum / weights;
}
