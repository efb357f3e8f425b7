// common.glsl — declarations and helpers shared by the compute kernels. Each helper names the
// C++ function it mirrors (src/backends/cpu); tests/backends/conformance_test.cpp compares them.
#extension GL_GOOGLE_include_directive : require
#include "ocean_shared.h"

layout(constant_id = 0) const uint N = 256;     // resolution
layout(constant_id = 1) const uint LOG2N = 8;   // log2 N

layout(std430, binding = OCEAN_BINDING_PARAMS) readonly buffer Params { SimParams params; };

vec2 cmul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }

// cpu::pack_rgba8: ⌊saturate(v)·255 + 0.5⌋ per channel, R in the low byte (Aebi, VR Ocean,
// eqs. 50–51).
uint quantise(float v) { return uint(clamp(v, 0.0, 1.0) * 255.0 + 0.5); }
uint pack_rgba8(float nx, float nz, float blue, float smoothness) {
  return quantise(nx * 0.5 + 0.5) | (quantise(nz * 0.5 + 0.5) << 8) | (quantise(blue) << 16) |
         (quantise(smoothness) << 24);
}

// cpu::smoothness_from_normal_length (Aebi, VR Ocean, eq. 53).
float smoothness_from_normal_length(float len) {
  float t = clamp(3.0 * len - 2.0, 0.0, 1.0);
  float r = (1.0 - t) * (1.0 + 0.15 * t);
  return 1.0 - sqrt(r);
}
