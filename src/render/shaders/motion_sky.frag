#version 450
// Motion vectors of the sky (docs/rendering.md R.26): a point at infinity moves with the camera's
// rotation only; MotionPush::sky_reprojection takes its current clip position to the previous one
// (with OCEAN_MULTIVIEW, stereo: the eye's EyeUniforms::sky_reprojection).
#include "render_common.glsl"
#include "motion_shared.h"

layout(push_constant, std430) uniform MotionBlock {
  MotionPush motion_push;
};
layout(location = 0) in vec2 ndc;
layout(location = 0) out vec2 motion;

void main() {
#ifdef OCEAN_MULTIVIEW  // stereo (R.61): the eye's own
  vec4 previous = u.eyes[gl_ViewIndex].sky_reprojection * vec4(ndc, 1.0, 1.0);
#else
  vec4 previous = motion_push.sky_reprojection * vec4(ndc, 1.0, 1.0);
#endif
  motion = ndc - previous.xy / previous.w;
}
