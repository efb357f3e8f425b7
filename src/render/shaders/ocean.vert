#version 450
// The ocean patches of the quadtree LOD (Aebi, VR Ocean, §5, eq. 70) and the horizon skirt
// (§5.7): the unit patch mesh scaled and moved per instance, displaced by the sum of the cascades'
// displacement maps (Aebi, VR Ocean, eq. 44; sampling M.7.6). Each cascade's displacement fades
// out where the mesh is too coarse to carry its dominant wavelength, and all of it fades out
// towards the border of the ocean square, where the flat skirt begins (docs/rendering.md R.9,
// R.10). Beyond the far field's D_min (VR-GIS FFT+Perlin, eq. 6) the cascades are read through
// hex tiles with random offsets and cascade 0 blends into the far field's noise (R.13, R.14).
// All weights are functions of the world position and the camera alone, so vertices that two
// patches share get the same displacement and the stitched mesh stays closed.
// OCEAN_MOTION_MULTIVIEW: the motion vectors of both eyes in one multiview pass (R.61).
#ifdef OCEAN_MOTION_MULTIVIEW
#define OCEAN_MOTION 1
#define OCEAN_MULTIVIEW 1
#endif
#include "ocean_displacement.glsl"
#ifdef OCEAN_MOTION
#include "motion_shared.h"
// Motion vectors (R.26): the cascades of the previous frame and its camera.
layout(set = 1, binding = OCEAN_MOTION_BINDING_PREVIOUS) uniform sampler2DArray previous_map;
layout(push_constant, std430) uniform MotionBlock {
  MotionPush motion;
};
layout(location = 3) out vec4 clip_now;
layout(location = 4) out vec4 clip_previous;
#endif

layout(location = 0) in vec2 a_position;  // unit patch [−0.5, 0.5]² (skirt: world x, z)
layout(location = 1) in vec3 a_instance;  // centre x, centre z, size (skirt: 0, 0, 1)
layout(location = 2) in uvec4 a_meta;     // grid x, grid y, level (skirt: OCEAN_RENDER_SKIRT_LEVEL), configuration

layout(location = 0) out vec2 world_xz;     // undisplaced position relative to the origin (R.16)
layout(location = 1) out vec3 world_pos;    // displaced position relative to the origin
layout(location = 2) flat out uint level;

void main() {
  vec2 xz = a_instance.xy + a_position * a_instance.z;
  // The spacing a patch at this distance has at most: a node splits while the camera is closer
  // than τ·s (eq. 57), so a leaf at distance d has s ≤ d/τ·2 and spacing s/V.
  float d = length(vec3(xz.x, 0.0, xz.y) - eye_position());
  float spacing = max(2.0 * d / (u.lod_scale * u.vertices), 1e-3);
  vec3 displacement = ocean_displacement(xz, spacing);
  world_xz = xz;
  // The planet bends the sea down by d²/(2R) (R.15).
  world_pos = vec3(xz.x + displacement.x, displacement.y - curvature_drop(xz),
                   xz.y + displacement.z);
  level = a_meta.z;
  gl_Position = eye_view_proj() * vec4(world_pos, 1.0);
#ifdef OCEAN_MOTION
  // The same surface point (the label xz) a frame ago: its displacement then, the camera then.
  vec3 previous = ocean_displacement_from(previous_map, xz, spacing);
  clip_now = gl_Position;  // without the sub-pixel jitter (R.61): the motion of the surface
  clip_now.xy -= vec2(u.jitter_ndc_x, u.jitter_ndc_y) * gl_Position.w;
#ifdef OCEAN_MULTIVIEW
  mat4 previous_view_proj = u.eyes[gl_ViewIndex].previous_view_proj;
#else
  mat4 previous_view_proj = motion.previous_view_proj;
#endif
  clip_previous = previous_view_proj *
                  vec4(xz.x + previous.x, previous.y - curvature_drop(xz), xz.y + previous.z, 1.0);
#endif
}
