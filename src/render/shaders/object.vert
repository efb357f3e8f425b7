#version 450
// Objects drawn with the water (docs/rendering.md R.20): a mesh's vertices by its model matrix
// into the world, then the frame's view-projection; the normal by the model matrix's
// inverse-transpose.
#include "render_common.glsl"
#include "object_shared.h"

layout(push_constant, std430) uniform Push {
  ObjectPush object;
};
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 world_pos;
layout(location = 1) out vec3 world_normal;

void main() {
  vec4 w = object.model * vec4(position, 1.0);
  world_pos = w.xyz;
  world_normal = transpose(inverse(mat3(object.model))) * normal;
  // The reflection pass (R.53) draws the object's mirror image in the sea level, shaded where it
  // really is.
  if (object.roughness_pad.y > 0.5) w.y = -w.y;
  gl_Position = eye_view_proj() * w;
}
