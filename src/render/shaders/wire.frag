#version 450
// Wireframe overlay of the LOD mesh: lines coloured by quadtree level, in HDR units.
#include "render_shared.h"

layout(location = 0) in vec2 world_xz;
layout(location = 1) in vec3 world_pos;
layout(location = 2) flat in uint level;
layout(location = 0) out vec4 colour;
void main() {
  vec3 c = level == OCEAN_RENDER_SKIRT_LEVEL ? vec3(0.2) : vec3(0.05, 0.05, 0.05) + 0.02 * float(level);
  colour = vec4(c, 1.0);
}
