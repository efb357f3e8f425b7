// seabed_shared.h — the seabed's parameters as the ocean pipeline's push constants
// (docs/rendering.md R.22–R.23), shared by the C++ renderer (src/render/seabed.cpp) and
// seabed.glsl. They use the scene pipeline layout's fragment push range, which the sky pass
// fills with its SkyPush before: the ocean draws push these over it. std430 equals the C++
// layout (static_asserts below).
#ifndef OCEAN_SEABED_SHARED_H
#define OCEAN_SEABED_SHARED_H

#include "render_shared.h"

// SeabedPush::pattern.y
#define OCEAN_SEABED_SAND 0.0
#define OCEAN_SEABED_CHECKER 1.0

#ifdef __cplusplus
namespace ocean::render::shader {
#endif

struct SeabedPush {
  vec4 absorption_enabled;  // absorption per channel, 1/m (rgb); 1 = a seabed is drawn (a)
  vec4 albedo_depth;        // linear albedo (rgb), depth below the mean sea level, m (a)
  vec4 pattern;             // period, m (x); OCEAN_SEABED_* (y); z, w unused
};

#ifdef __cplusplus
static_assert(sizeof(SeabedPush) == 48);
static_assert(sizeof(SeabedPush) <= sizeof(SkyPush));  // fits the layout's push range
}  // namespace ocean::render::shader
#endif

#endif
