#version 450
// The sky behind the ocean: sky radiance along each pixel's view ray and the sun's disc
// (docs/rendering.md R.1–R.4).
#include "underwater.glsl"

layout(location = 0) in vec2 ndc;
#ifdef OCEAN_MULTIVIEW
layout(location = 1) in vec4 eye_far_point;  // linear in screen space: interpolates exactly
#endif
layout(location = 0) out vec4 colour;
layout(push_constant) uniform Push {
  SkyPush push;
};

void main() {
  // Vulkan's framebuffer y runs down; the projection is unflipped and the viewport negative,
  // so ndc.y here already points up.
#ifdef OCEAN_MULTIVIEW
  vec4 far_point = eye_far_point;
#else
  vec4 far_point = push.inverse_view_proj * vec4(ndc, 1.0, 1.0);
#endif
  vec3 v = normalize(far_point.xyz / far_point.w - eye_position());
  // A ray that meets no surface lies in the water all along when it ends under the sea: the
  // pixel looks into the depth (R.50, R.51).
  if (ray_stays_in_water(v)) {
    float depth;  // and the sunlight scattered towards the eye on the way (R.66)
    float r = path_to_bed(eye_position(), v, depth);
    colour = vec4(seen_under_water(eye_position(), v, true) + sunlit_water(eye_position(), v, r), 1.0);
    return;
  }
  vec3 c = sky_radiance(sky_direction_seen(v));  // from the eye's height (R.8d)
  // From altitude on a sphere the air is marched instead (R.8c): black space above a thin limb.
  float air_weight = planet_air_weight();
  vec3 sun_seen = u.sun_ground;
  bool sun_above = v.y > 0.0;
  if (air_weight > 0.0) {
    mat2x3 air = planet_air(v, 1e12);
    c = mix(c, air[1], air_weight);
    sun_seen = mix(sun_seen, u.sphere.sun_top * air[0], air_weight);
    sun_above =
        air_weight > 0.5 ? !ray_meets_sphere(planet_centre(), u.sphere.radius_m, v) : sun_above;
  }
  // Sun disc, angular radius 0.27°, limb-darkened edge over a pixel or so.
  float cos_sun = dot(v, u.sun_dir);
  float radius = radians(0.27);
  float solid_angle = PI * radius * radius;
  float edge = smoothstep(cos(radius * 1.3), cos(radius), cos_sun);
  // The disc's true radiance (E/Ω) would saturate any exposure; 2 % of it keeps a visible
  // limb in the EXR output.
  // An environment map carries its own sun (R.17).
  if (sun_above && u.environment.scale == 0.0) c += edge * sun_seen / solid_angle * 0.02;
  // No fog on the sky itself: at the horizon it already is the fog's colour (R.8).
  // The sky moves with the camera's rotation alone, which its motion vectors follow: its share
  // of the temporal blend is the steady one (alpha 0, R.61).
  colour = vec4(c, u.footprint_scale < 1.0 ? 0.0 : 1.0);
}
