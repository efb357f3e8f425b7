#version 450
// Objects under the water's sky and sun (docs/rendering.md R.20–R.21): glTF's metallic-roughness
// model with F0 = mix(0.04, base colour, metallic); the sun by GGX with height-correlated Smith
// masking (Walter et al. 2007, as the water's R.7) plus Lambert diffuse; the sky as a hemisphere
// of irradiance for the diffuse (sky_ambient scaled from the horizontal plane by (1 + n_y)/2)
// and the sky table along the reflected ray for the specular, weighted by Schlick's Fresnel
// (Schlick 1994); the horizon fog of the water (R.8).
//
// Sources: Burley (2012) "Physically-based shading at Disney" and the glTF 2.0 specification's
// Appendix B (the metallic-roughness BRDF, α = roughness²); Walter et al. (2007) (GGX).
#include "underwater.glsl"
#include "object_shared.h"

layout(push_constant, std430) uniform Push {
  ObjectPush object;
};
layout(location = 0) in vec3 world_pos;
layout(location = 1) in vec3 world_normal;
layout(location = 0) out vec4 colour;

vec3 schlick(vec3 f0, float cos_theta) {
  float m = 1.0 - clamp(cos_theta, 0.0, 1.0);
  float m2 = m * m;
  return f0 + (1.0 - f0) * m2 * m2 * m;
}

void main() {
  vec3 base = object.base_metallic.rgb;
  float metallic = object.base_metallic.a;
  float alpha = object.roughness_pad.x * object.roughness_pad.x;
  float alpha_sq = max(alpha * alpha, 1e-4);
  // Mirrored (R.53): the object as the eye's mirror image below the sea level sees it, only the
  // part above the water, unfogged (the water's pixel is fogged), coverage in alpha.
  bool mirrored = object.roughness_pad.y > 0.5;
  if (mirrored && world_pos.y < 0.0) discard;
  vec3 eye = mirrored ? eye_position() * vec3(1.0, -1.0, 1.0) : eye_position();
  vec3 to_camera = eye - world_pos;
  float distance_m = length(to_camera);
  vec3 V = to_camera / distance_m;
  vec3 N = normalize(world_normal);
  if (dot(N, V) < 0.0) N = -N;  // a back face seen through an open mesh
  vec3 L = u.sun_dir;
  float n_dot_v = max(dot(N, V), 1e-3);
  float n_dot_l = max(dot(N, L), 0.0);
  vec3 H = normalize(V + L);
  float n_dot_h = max(dot(N, H), 0.0);
  vec3 f0 = mix(vec3(0.04), base, metallic);

  // Sun: GGX D·G/(4 n·l n·v)·F, and Lambert for the light that enters (R.20).
  float dd = n_dot_h * n_dot_h * (alpha_sq - 1.0) + 1.0;
  float D = alpha_sq / (PI * dd * dd);
  float lambda_v = sqrt(alpha_sq + (1.0 - alpha_sq) * n_dot_v * n_dot_v) * n_dot_l;
  float lambda_l = sqrt(alpha_sq + (1.0 - alpha_sq) * n_dot_l * n_dot_l) * n_dot_v;
  float G_over = 0.5 / max(lambda_v + lambda_l, 1e-6);
  vec3 F_sun = schlick(f0, max(dot(V, H), 0.0));
  vec3 diffuse_albedo = base * (1.0 - metallic);
  vec3 sun = u.sun_ground * n_dot_l * (D * G_over * F_sun + (1.0 - F_sun) * diffuse_albedo / PI);
  bool submerged = !mirrored && under_surface(world_pos);
  if (submerged)  // the waves' caustics on what lies under them (R.65)
    sun *= caustic_irradiance(world_pos.xz, -world_pos.y, kCausticHalfWidth);

  // Sky: a diffuse hemisphere and the reflected sky (R.21).
  vec3 F_env = schlick(f0, n_dot_v);
  vec3 sky_diffuse = diffuse_albedo * u.sky_ambient * (0.5 + 0.5 * N.y) / PI;
  vec3 R = reflect(-V, N);
  // Below the horizon the reflected ray meets the sea: its body colour under the sky (R.11).
  vec3 env = R.y >= 0.0 ? sky_radiance(R) : u.water_colour * u.sky_ambient / PI;
  vec3 sky_specular = F_env * env * mix(1.0, 0.3, object.roughness_pad.x);
  vec3 c = sun + (1.0 - F_env) * sky_diffuse + sky_specular;

  if (!mirrored) {
    if (submerged && under_surface(u.camera_pos_m))  // both in the water (R.51, R.66)
      c = seen_through_water(c, distance_m, -V);
    else
      c = mix(aerial_perspective(c, world_pos.y, distance_m, -V), fog_colour(-V),
              horizon_fog_seen(distance_m, world_pos.y, V));
  }
  colour = vec4(c, 1.0);
}
