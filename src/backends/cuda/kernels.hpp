// The CUDA kernels' arguments and launchers (kernels.cu), shared by the host code and the kernels:
// plain structs of scalars and pointers, one source for both compilers (after zeux/niagara's
// shared header). Host code calls the launchers only; no kernel is visible outside kernels.cu.
#pragma once

#include <cuda_runtime_api.h>
#include <vector_types.h>

#include <cstdint>

namespace ocean::cuda::detail {

// Normal methods as the kernels see them (NormalMethod of ocean/sim.hpp).
inline constexpr int kNormalsCentral = 0;
inline constexpr int kNormalsSobel = 1;
inline constexpr int kNormalsAnalytic = 2;
inline constexpr int kMaxMipLevels = 12;  // log2 2048 + 1

/// Rewritten in pinned host memory before each frame and copied to the device by the frame's
/// first operation.
struct FrameParams {
  double clock = 0.0;            ///< EvolutionPhase::clock(): frac(t/T) when looping, else t
  float foam_decay = 0.0f;       ///< decay_per_s·dt
  std::uint32_t reset_foam = 1;  ///< 1 on the first step or after a jump back in time
};

/// Everything one cascade's kernels read, fixed at configure(). Optional outputs are nullptr when
/// the configuration does not request them (their stores are skipped).
struct CascadeArgs {
  int n = 0;
  int log2n = 0;
  int planes = 2;
  int normal_method = kNormalsCentral;
  int blue_is_foam = 1;
  float dk = 0.0f;           ///< 2π/L, rad/m
  float inv_spacing = 0.0f;  ///< N/L, 1/m
  float choppiness = 0.0f;   ///< λ
  /// The foam source x = (foam_threshold − J)·foam_gain: Φ(x) when foam_breaking, else
  /// clamp(x, 0, 1) (M.7.4; FoamSourceTerms).
  float foam_threshold = 0.0f;
  float foam_gain = 0.0f;
  int foam_breaking = 0;
  float base_length = 0.0f;  ///< normal length from roughness (Aebi, VR Ocean, eq. 49)
  float base_smoothness = 0.0f;
  std::uint32_t mip_offset[kMaxMipLevels + 1] = {};  ///< mip_offset(N, m) (eq. 55)
  const FrameParams* frame = nullptr;
  const float4* spectrum = nullptr;
  const double* phase_rate = nullptr;
  const float2* twiddle = nullptr;  ///< e^{+2πi·t/N}, t ∈ [0, N), from double (own FFT kernels)
  float2* fft_planes = nullptr;     ///< planes·N² complex, plane-major
  float* displacement = nullptr;
  ushort4* displacement_half = nullptr;
  float* normal = nullptr;
  float* jacobian = nullptr;
  float* foam_state = nullptr;
  float4* mip_work = nullptr;
  std::uint32_t* packed_mips = nullptr;
};

/// cudaSuccess when the current device runs this build's kernels; cudaErrorNoKernelImageForDevice
/// (or a JIT error) when the build carries no code for its architecture.
cudaError_t probe_kernels();
/// h̃(k, t) times each plane's field factor into fft_planes (M.6.5, M.7.2, M.7.3).
cudaError_t launch_evolve(const CascadeArgs& args, cudaStream_t stream);
/// The FFT kernels' alternative to launch_evolve + cuFFT (a port of the Vulkan backend's
/// fft.glsl): evolution fused into the inverse FFT of each row, one block per row and plane ...
cudaError_t launch_rows(const CascadeArgs& args, cudaStream_t stream);
/// ... then the inverse FFT of each column, in place (finalize applies the (−1)^(x+y) sign).
cudaError_t launch_columns(const CascadeArgs& args, cudaStream_t stream);
/// Displacement, gradients, normal, Jacobian, foam, level 0 of the packed map, and `levels` mip
/// levels reduced inside each tile×tile block (the first mip pass).
cudaError_t launch_finalize(const CascadeArgs& args, int tile, int levels, cudaStream_t stream);
/// One later mip pass: from level `source`'s work values, `levels` levels per tile×tile block.
cudaError_t launch_mips(const CascadeArgs& args, int source, int tile, int levels,
                        cudaStream_t stream);

}  // namespace ocean::cuda::detail
