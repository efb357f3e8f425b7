#version 450
// Exposure and the ACES filmic curve of Narkowicz (2015) "ACES filmic tone mapping curve" on the
// linear HDR image (R.12); the sRGB transfer happens in the *_SRGB target's store.
#include "render_shared.h"

layout(set = 0, binding = OCEAN_RENDER_BINDING_HDR) uniform sampler2D hdr;
layout(push_constant) uniform Push {
  TonemapPush push;
};
layout(location = 0) in vec2 ndc;
layout(location = 0) out vec4 colour;

vec3 aces(vec3 x) {
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

void main() {
  vec3 c = texelFetch(hdr, ivec2(gl_FragCoord.xy), 0).rgb;
  colour = vec4(aces(max(c, vec3(0.0)) * push.exposure), 1.0);
}
