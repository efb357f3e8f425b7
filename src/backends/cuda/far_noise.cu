// The far field's noise map on the CUDA device (docs/rendering.md R.13a): height and surface
// gradient of the three advected octaves at every texel of the window, on a stream of its own
// beside the cascades' (plan.cpp's schedule), inside the frame's graph.
//
// This work is based on: VR-GIS FFT+Perlin, §III (the Perlin noise height and normal maps
// computed by CUDA concurrent kernels beside the FFT's). The texel is far_noise_texel of
// src/sim/far_noise.h, the one source the CPU reference (far_noise_map::fill_rows, the same bits
// as far_noise_texel), the Vulkan kernel (far_noise.comp) and this kernel compile; the host splits
// each octave's drifted lattice coordinate in double precision (far_noise_map::params), so the
// kernel's float arithmetic is as exact days in as at t = 0. Compiled with --fmad=false, as
// kernels.cu: the remaining difference from the CPU is the device's cosf/sinf (2 ulp), which
// conformance::kFarNoiseDeviceBounds accounts for.
#include "far_noise_kernel.hpp"
#include "sim/far_noise.h"

namespace ocean::cuda::detail {
namespace {

constexpr int kTile = 16;  // 16×16 threads per block, as the per-texel kernels of kernels.cu

__global__ void far_noise(FarNoiseArgs a) {
  const unsigned col = blockIdx.x * blockDim.x + threadIdx.x;
  const unsigned row = blockIdx.y * blockDim.y + threadIdx.y;
  const auto n = static_cast<unsigned>(a.resolution);
  if (col >= n || row >= n) return;
  float h, sx, sz;
  noise::far_noise_texel(*a.params, col, row, h, sx, sz);
  const std::size_t i = 3 * (static_cast<std::size_t>(row) * n + col);
  a.map[i] = h;
  a.map[i + 1] = sx;
  a.map[i + 2] = sz;
}

}  // namespace

cudaError_t launch_far_noise(const FarNoiseArgs& args, cudaStream_t stream) {
  const unsigned blocks = static_cast<unsigned>((args.resolution + kTile - 1) / kTile);
  far_noise<<<dim3(blocks, blocks), dim3(kTile, kTile), 0, stream>>>(args);
  return cudaGetLastError();
}

}  // namespace ocean::cuda::detail
