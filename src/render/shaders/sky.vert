#version 450
// The fullscreen triangle of the sky and the tone-mapping pass: clip-space corners (−1,−1),
// (3,−1), (−1,3) at the far plane; `ndc` carries the position for the sky's view ray.
// With OCEAN_MULTIVIEW (stereo, R.25) a quad of two triangles inside clip space instead (six
// vertices: a primitive the clipper cuts loses its view in Mesa 22's llvmpipe, drawing nothing
// in the right eye), and the corner's far-plane point in the eye's frame.
#ifdef OCEAN_MULTIVIEW
#include "render_common.glsl"
layout(location = 1) out vec4 eye_far_point;
const vec2 kQuad[6] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(-1.0, 1.0),
                             vec2(1.0, -1.0), vec2(1.0, 1.0));
#endif
layout(location = 0) out vec2 ndc;
void main() {
#ifdef OCEAN_MULTIVIEW
  vec2 p = kQuad[gl_VertexIndex];
  eye_far_point = u.eyes[gl_ViewIndex].inverse_view_proj * vec4(p, 1.0, 1.0);
#else
  vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2) * 2.0 - 1.0;
#endif
  ndc = p;
  gl_Position = vec4(p, 1.0, 1.0);
}
