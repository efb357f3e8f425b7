// The tessellated mesh's push constants of a grid (src/render, private; tessellation_levels.cpp,
// docs/rendering.md R.40–R.42). It needs nothing of the renderer's state (state.hpp), so that the
// flag parser's fuzz target (tests/fuzz) compiles tessellation_levels.cpp alone.
#pragma once

#include "ocean/render.hpp"
#include "ocean/tessellation.hpp"
#include "shaders/tessellation.h"

namespace ocean::render {

// What tessellation_levels evaluates, and the tessellated mesh's draws push.
shader::TessellationPush tessellation_push(const TessellationParams& params,
                                           const TessellationGrid& grid);

}  // namespace ocean::render
