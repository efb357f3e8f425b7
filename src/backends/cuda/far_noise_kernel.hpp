// The far field's noise map kernel (far_noise.cu, docs/rendering.md R.13a): its arguments and its
// launcher, read by both compilers as kernels.hpp is. Host code calls the launcher only.
#pragma once

#include <cuda_runtime_api.h>

namespace ocean::noise {
struct FarNoiseMapParams;  // src/sim/far_noise.h
}

namespace ocean::cuda::detail {

/// Fixed at configure(); the parameters behind `params` are rewritten each frame.
struct FarNoiseArgs {
  const noise::FarNoiseMapParams* params = nullptr;  ///< device: the frame's map parameters
  float* map = nullptr;  ///< device: float3 (h, ∂h/∂x, ∂h/∂z) per texel, index row·M + col
  int resolution = 0;    ///< M texels per side
};

/// The map: far_noise_texel (src/sim/far_noise.h) at every texel, one thread per texel.
cudaError_t launch_far_noise(const FarNoiseArgs& args, cudaStream_t stream);

}  // namespace ocean::cuda::detail
