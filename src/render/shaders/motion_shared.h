// motion_shared.h — the motion-vector pass's push constants and bindings (docs/rendering.md
// R.26), shared by the C++ renderer (src/render/motion.cpp) and its GLSL (ocean.vert with
// OCEAN_MOTION, motion.frag, motion_sky.frag); std430 equals the C++ layout.
#ifndef OCEAN_MOTION_SHARED_H
#define OCEAN_MOTION_SHARED_H

#ifdef __cplusplus
#include "render_shared.h"
namespace ocean::render::shader {
#endif

// Set 1 of the motion pipelines.
#define OCEAN_MOTION_BINDING_PREVIOUS 0  // sampler2DArray RGBA16F: the previous frame's cascades

// Push constants of the motion pass (vertex and fragment), 128 bytes.
struct MotionPush {
  mat4 previous_view_proj;  // the previous camera relative to this frame's origin (R.16)
  // Current clip of a far point (ndc, 1, 1) → previous clip of the same direction (the sky).
  mat4 sky_reprojection;
};

#ifdef __cplusplus
static_assert(sizeof(MotionPush) == 128);
}  // namespace ocean::render::shader
#endif

#endif
