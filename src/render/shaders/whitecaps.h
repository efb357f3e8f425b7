// whitecaps.h — the sea's whitecaps drawn as patches (docs/rendering.md R.11b), one source for the
// shaders (ocean.frag) and the C++ tests that check them. Written in the subset C++ and GLSL
// share, as far_noise.h.
//
// Each cascade's foam is the probability F that the sea breaks at a point given what the cascade
// resolves (docs/math.md M.7.4): F = P(J_true < J_thr | J_c), the rest of the sea deciding.
// Drawn as it is, F is a faint grey wash wherever breaking is likely; a whitecap is white where
// it is and absent elsewhere (Monahan's coverage W is measured as the white area of photographs,
// Monahan 1971). Here the rest of the sea is given a realisation: a Gaussian field g of unit
// variance, and the point is white where g < Φ⁻¹(F), which holds with probability F — the cover's
// mean is kept, the patches are white. The part of g a pixel resolves, g_v of variance v (the
// sines its footprint spans less than half a wavelength of, as the ripples', R.62), is drawn; the
// rest, 1 − v, and the spread s² of g_v across the pixel stay a probability:
//
//   φ = Φ((a·√(1 + s²) − g_v)/√(1 − v + s²)),  a = Φ⁻¹(F)                              (R.11b)
//
// whose mean over g_v ~ N(0, v) is Φ(a) = F exactly, for any v and s². v = 0 (nothing resolved,
// far away) draws F itself; v = 1, s² = 0 draws white patches with area fraction F.
#ifndef OCEAN_RENDER_WHITECAPS_H
#define OCEAN_RENDER_WHITECAPS_H

#include "render_shared.h"

#ifdef __cplusplus
#include <algorithm>
#include <cmath>
namespace ocean::render::shader {
#define OCEAN_FN inline
#define OCEAN_OUT(T) T&
#define OCEAN_IN(T) const T&
using std::abs;
using std::cos;
using std::exp;
using std::log;
using std::max;
using std::min;
using std::sin;
using std::sqrt;
#else
#define OCEAN_FN
#define OCEAN_OUT(T) out T
#define OCEAN_IN(T) T
#endif

// Φ(x), the standard normal distribution function: ½·erfc(|x|/√2) by Abramowitz & Stegun,
// Handbook of Mathematical Functions, eq. 7.1.26 (|error| ≤ 1.5·10⁻⁷), the constants and the
// cap of src/sim/packing.hpp's normal_cdf, which the foam's source uses.
OCEAN_FN float whitecap_normal_cdf(float x) {
  float z = min(abs(x) * 0.70710678f, 10.5f);
  float t = 1.0f / (1.0f + 0.3275911f * z);
  float poly =
      t * (0.254829592f +
           t * (-0.284496736f + t * (1.421413741f + t * (-1.453152027f + t * 1.061405429f))));
  float tail = 0.5f * poly * exp(-z * z);
  return x < 0.0f ? tail : 1.0f - tail;
}

// Φ⁻¹(p) = √2·erfinv(2p − 1), 0 < p < 1, by Giles's single-precision erfinv (M. Giles,
// "Approximating the erfinv function", GPU Computing Gems Jade Edition, 2011: polynomials in
// w = −ln(1 − x²), split at w = 5). 1 − x² is taken as 4p(1 − p), which keeps its precision
// where p is small (a whitecap cover of 10⁻⁴ would lose a third of it through 2p − 1 in float).
OCEAN_FN float whitecap_normal_quantile(float p) {
  float x = 2.0f * p - 1.0f;
  float w = -log(4.0f * p * (1.0f - p));
  float q;
  if (w < 5.0f) {
    w = w - 2.5f;
    q = 2.81022636e-08f;
    q = 3.43273939e-07f + q * w;
    q = -3.5233877e-06f + q * w;
    q = -4.39150654e-06f + q * w;
    q = 0.00021858087f + q * w;
    q = -0.00125372503f + q * w;
    q = -0.00417768164f + q * w;
    q = 0.246640727f + q * w;
    q = 1.50140941f + q * w;
  } else {
    w = sqrt(w) - 3.0f;
    q = -0.000200214257f;
    q = 0.000100950558f + q * w;
    q = 0.00134934322f + q * w;
    q = -0.00367342844f + q * w;
    q = 0.00573950773f + q * w;
    q = -0.0076224613f + q * w;
    q = 0.00943887047f + q * w;
    q = 1.00167406f + q * w;
    q = 2.83297682f + q * w;
  }
  return 1.41421356f * q * x;
}

// R.11b: the drawn cover φ of a point whose breaking probability is F, where the resolved part of
// the field is g_v (variance v) and its spread across the pixel s². Covers within 10⁻⁶ of 0 or 1
// are drawn as they are.
OCEAN_FN float whitecap_patch(float cover, float g, float v, float s2) {
  if (cover <= 1e-6f || cover >= 1.0f - 1e-6f) return cover;
  float a = whitecap_normal_quantile(cover);
  float rest = max(1.0f - v, 0.0f) + s2;
  return whitecap_normal_cdf((a * sqrt(1.0f + s2) - g) / sqrt(max(rest, 1e-8f)));
}

// The field g at (rx, rz) metres from the quadtree's centre: Σ w_i·A_i·sin(k_i·r + ψ_i) over the
// uniforms' sines (k_x, k_z, A_i, ψ_i at the quadtree's centre and the frame's time), Σ A_i²/2 = 1.
// (dxx, dxz), (dyx, dyz): the pixel's footprint (the world position's screen derivatives). A sine
// whose phase changes by Δθ = max(|k·dx|, |k·dy|) across the pixel is drawn with weight
// w = clamp(2 − 2Δθ/π, 0, 1) (R.62's rule); v = Σ w²·A²/2 is what is drawn of the variance and
// s² = (|∂g_v·dx|² + |∂g_v·dy|²)/12 the variance of g_v over the pixel (a box of its width).
OCEAN_FN void whitecap_field(OCEAN_IN(WhitecapUniforms) wc, float rx, float rz, float dxx,
                             float dxz, float dyx, float dyz, OCEAN_OUT(float) g,
                             OCEAN_OUT(float) v, OCEAN_OUT(float) s2) {
  g = 0.0f;
  v = 0.0f;
  float gx = 0.0f, gy = 0.0f;
  int n = int(wc.count);
  for (int i = 0; i < n; ++i) {
    vec4 s = wc.waves[i];
    float kdx = s.x * dxx + s.y * dxz, kdy = s.x * dyx + s.y * dyz;
    float w = min(max(2.0f - max(abs(kdx), abs(kdy)) * 0.63661977f, 0.0f), 1.0f);
    if (w <= 0.0f) continue;
    float theta = s.x * rx + s.y * rz + s.w;
    g += w * s.z * sin(theta);
    v += 0.5f * w * w * s.z * s.z;
    float c = w * s.z * cos(theta);
    gx += c * kdx;
    gy += c * kdy;
  }
  s2 = (gx * gx + gy * gy) / 12.0f;
}

#ifdef __cplusplus
}  // namespace ocean::render::shader
#endif
#undef OCEAN_FN
#undef OCEAN_OUT
#undef OCEAN_IN

#endif
