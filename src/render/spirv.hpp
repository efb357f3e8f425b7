// The renderer's shaders as SPIR-V words, compiled from shaders/*.vert|frag|comp by glslc at build
// time and embedded by cmake/OceanShaders.cmake. OCEAN_RENDER_SPIRV(name) declares one as
// spirv::name(); a pass's own shader is declared in the pass's source (far_map.cpp: far_map), the
// shared ones here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#define OCEAN_RENDER_SPIRV(name)                         \
  extern const std::uint32_t ocean_spv_##name[];         \
  extern const std::size_t ocean_spv_##name##_words;     \
  namespace ocean::render::spirv {                       \
  inline std::span<const std::uint32_t> name() {         \
    return {ocean_spv_##name, ocean_spv_##name##_words}; \
  }                                                      \
  }

OCEAN_RENDER_SPIRV(sky_vert)
OCEAN_RENDER_SPIRV(sky_frag)
OCEAN_RENDER_SPIRV(ocean_vert)
OCEAN_RENDER_SPIRV(ocean_frag)
OCEAN_RENDER_SPIRV(wire_frag)
OCEAN_RENDER_SPIRV(tonemap_frag)
OCEAN_RENDER_SPIRV(object_vert)
OCEAN_RENDER_SPIRV(object_frag)
OCEAN_RENDER_SPIRV(sphere_vert)
OCEAN_RENDER_SPIRV(sphere_frag)
// Stereo in one pass: the same shaders with OCEAN_MULTIVIEW (gl_ViewIndex picks the eye).
OCEAN_RENDER_SPIRV(sky_vert_mv)
OCEAN_RENDER_SPIRV(sky_frag_mv)
OCEAN_RENDER_SPIRV(ocean_vert_mv)
OCEAN_RENDER_SPIRV(ocean_frag_mv)
OCEAN_RENDER_SPIRV(object_vert_mv)
OCEAN_RENDER_SPIRV(object_frag_mv)
// Motion vectors (R.26).
OCEAN_RENDER_SPIRV(ocean_vert_motion)
OCEAN_RENDER_SPIRV(motion_frag)
OCEAN_RENDER_SPIRV(motion_sky_frag)
// Both eyes' motion vectors in one multiview pass (R.61).
OCEAN_RENDER_SPIRV(ocean_vert_motion_mv)
OCEAN_RENDER_SPIRV(motion_sky_frag_mv)
OCEAN_RENDER_SPIRV(ocean_tess_vert)
OCEAN_RENDER_SPIRV(ocean_tesc)
OCEAN_RENDER_SPIRV(ocean_tese)
