// The far field's per-frame noise map (docs/rendering.md R.13a), private to the library: the
// parameters a backend's noise task or kernel reads for one frame, and the CPU task's rows. The
// texel arithmetic is src/sim/far_noise.h's far_noise_texel, shared with the Vulkan kernel.
#pragma once

#include <cstddef>

#include "ocean/far_noise.hpp"
#include "sim/far_noise.h"

namespace ocean::far_noise_map {

/// The map's parameters at time t: per octave, the lattice coordinate of texel (0, 0) of
/// `map`'s window moved back by the octave's drift velocity_mps·t, split in double precision
/// into whole cells (wrapped modulo 2³², as the lattice's indices) and the rest in [0, 1).
noise::FarNoiseMapParams params(const FarFieldNoise& noise, const FarNoiseConfig& map,
                                double time_s);

/// Rows [begin, end) of the map: float3 (h, ∂h/∂x, ∂h/∂z) per texel into out[3·(row·N + col)].
void fill_rows(const noise::FarNoiseMapParams& p, std::size_t begin, std::size_t end, float* out);

}  // namespace ocean::far_noise_map
