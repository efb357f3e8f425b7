// The renderer's passes (src/render, private), one object per feature (pass.hpp), in frame
// order. The list is generated (src/render/CMakeLists.txt): each pass header carries one line
//   // render pass N: Type — what it draws
// and the passes follow N. Adding a feature adds its header, its source and its shader; nothing
// here changes. The shared state (state.hpp) holds the passes as a tuple; pass<P>(st) reaches
// one, for_each_pass(st, f) calls f on each in this order.
#pragma once

#include "render_passes.gen.hpp"
