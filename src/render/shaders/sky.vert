#version 450
// The fullscreen triangle of the sky and the tone-mapping pass: clip-space corners (−1,−1),
// (3,−1), (−1,3) at the far plane; `ndc` carries the position for the sky's view ray.
layout(location = 0) out vec2 ndc;
void main() {
  vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2) * 2.0 - 1.0;
  ndc = p;
  gl_Position = vec4(p, 1.0, 1.0);
}
