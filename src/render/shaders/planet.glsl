// planet.glsl — positions in a large world and on a curved planet (docs/rendering.md R.15,
// R.16): the cascades' texture coordinates read from positions relative to the frame's origin
// (the far field's noise: far_field.glsl), and the curvature that bends the flat sea's far field down
// by d²/(2R) so that the horizon sits at the dip of a sphere of radius R.
//
// Sources: the geometric dip of the horizon, arccos(R/(R + h)) ≈ √(2h/R), at the distance
// √(2Rh) (Young, "Dip of the horizon"); rendering relative to a centre chosen in double
// precision (Cozzi & Ring, "3D Engine Design for Virtual Globes", 2011, ch. 5).
#ifndef OCEAN_RENDER_PLANET_GLSL
#define OCEAN_RENDER_PLANET_GLSL

#include "render_common.glsl"

// Where cascade c's maps are read at a point xz relative to the origin: (O + xz)/L_c with
// O/L_c computed in double on the CPU (R.16), plus the half-texel of the maps' sample grid.
vec2 cascade_uv(vec2 xz, int c) {
  return xz / u.cascades[c].patch_size_m + u.cascade_origin[c].xy + 0.5 / u.cascades[c].resolution;
}

// How far the sea at xz lies below the camera's tangent plane: d²/(2R), d its horizontal
// distance from the camera (R.15); 0 on a flat world.
float curvature_drop(vec2 xz) {
  vec2 d = xz - eye_position().xz;
  return dot(d, d) * u.planet.inv_two_radius_per_m;
}

// The sphere's up vector at xz in the camera's tangent frame, to first order in d/R (R.15),
// unnormalised: (d_x/R, 1, d_z/R).
vec3 curved_up(vec2 xz) {
  vec2 d = (xz - eye_position().xz) * u.planet.inv_radius_per_m;
  return vec3(d.x, 1.0, d.y);
}

#endif
