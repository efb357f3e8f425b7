// object_shared.h — the push constants of the object pass (docs/rendering.md R.20), shared by
// the C++ renderer (src/render/objects.cpp) and object.vert/object.frag, laid out so that std430
// equals the C++ layout (static_asserts below). The frame's uniforms and the sky table are the
// scene set of render_shared.h.
#ifndef OCEAN_OBJECT_SHARED_H
#define OCEAN_OBJECT_SHARED_H

#include "render_shared.h"

// Vertex input of the object pipeline: one interleaved buffer of (position, normal).
#define OCEAN_OBJECT_VERTEX_FLOATS 6

#ifdef __cplusplus
namespace ocean::render::shader {
#endif

struct ObjectPush {
  mat4 model;          // mesh frame → world, column-major
  vec4 base_metallic;  // linear base colour (rgb) and metallic (a)
  vec4
      roughness_pad;  // perceptual roughness (x); 1: drawn mirrored in y = 0 (y, R.53); z, w unused
};

#ifdef __cplusplus
static_assert(sizeof(ObjectPush) == 96);
static_assert(offsetof(ObjectPush, base_metallic) == 64);
}  // namespace ocean::render::shader
#endif

#endif
