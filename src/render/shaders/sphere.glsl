// sphere.glsl — the sea on a sphere (docs/rendering.md R.30–R.38): the cube's faces, the
// single-precision offset of a vertex from its patch's centre on the sphere, and the tri-planar
// projections of the cascades (Paleologue, "Ocean Simulation with FFT and WebGPU", 2024, the
// sphere section).
#ifndef OCEAN_RENDER_SPHERE_GLSL
#define OCEAN_RENDER_SPHERE_GLSL

#include "render_common.glsl"

// Face f's normal N and axes U, V = U × N, as ocean::sphere::face_axes (R.36).
const vec3 kFaceN[6] = vec3[](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0),
                              vec3(0, 0, 1), vec3(0, 0, -1));
const vec3 kFaceU[6] = vec3[](vec3(0, 0, 1), vec3(0, 0, -1), vec3(1, 0, 0), vec3(1, 0, 0),
                              vec3(-1, 0, 0), vec3(1, 0, 0));
const vec3 kFaceV[6] = vec3[](vec3(0, 1, 0), vec3(0, 1, 0), vec3(0, 0, 1), vec3(0, 0, -1),
                              vec3(0, 1, 0), vec3(0, 1, 0));

// The plane axes (e1, e2) of the projection along x, y, z, as sphere_frame.cpp's kPlaneAxes
// (R.33): along y it is the flat sea's (x, z).
const vec3 kPlaneE1[3] = vec3[](vec3(0, 0, 1), vec3(1, 0, 0), vec3(0, 1, 0));
const vec3 kPlaneE2[3] = vec3[](vec3(0, 1, 0), vec3(0, 0, 1), vec3(1, 0, 0));

// dir(c + δ) − dir(c) with errors relative to |δ| (R.38); mirrors ocean::sphere::sphere_offset.
vec3 sphere_offset(vec3 c, vec3 delta) {
  float cc = dot(c, c), cd = dot(c, delta), dd = dot(delta, delta);
  float lv = length(c + delta), lc = sqrt(cc);
  float k = -(2.0 * cd + dd) / (lv * lc * (lv + lc));
  return delta / lv + c * k;
}

// Variance-preserving tri-planar weights (R.32); mirrors ocean::sphere::triplanar_weights.
vec3 triplanar_weights(vec3 n) {
  vec3 t = max(abs(n) - 0.5, 0.0);
  vec3 w = t * t;
  return w / length(w);
}

// Planet axes → the view's local axes (east, up, north).
vec3 to_local(vec3 p) {
  return vec3(dot(u.sphere.local_from_planet[0].xyz, p), dot(u.sphere.local_from_planet[1].xyz, p),
              dot(u.sphere.local_from_planet[2].xyz, p));
}
vec3 to_planet(vec3 l) {
  return l.x * u.sphere.local_from_planet[0].xyz + l.y * u.sphere.local_from_planet[1].xyz +
         l.z * u.sphere.local_from_planet[2].xyz;
}

// Where cascade c's maps are read for projection a at q, the point's planet-axes offset from
// the camera: (O + q)·e/L_c with O·e/L_c wrapped in double on the CPU (R.38).
vec2 sphere_uv(vec3 q, int a, int c) {
  vec3 e1 = kPlaneE1[a], e2 = kPlaneE2[a];
  vec3 o = u.cascade_origin[c].xyz;
  return vec2(dot(q, e1), dot(q, e2)) / u.cascades[c].patch_size_m + vec2(dot(o, e1), dot(o, e2)) +
         0.5 / u.cascades[c].resolution;
}

#endif
