// ocean_shared.h — constants and layouts shared by the C++ Vulkan backend and the GLSL compute
// shaders (one source of truth, after zeux/niagara). Included by both languages: keep to #define
// constants and structs of 32-bit scalars whose std430 layout equals the C++ layout.
#ifndef OCEAN_SHARED_H
#define OCEAN_SHARED_H

#ifdef __cplusplus
#include <cstdint>
namespace ocean::vk::shader {
using uint = std::uint32_t;
#endif

// Limits. kMaxCascades mirrors validate(SimulationConfig); 2048² is the largest resolution.
#define OCEAN_MAX_CASCADES 8
#define OCEAN_MAX_MIPS 12
#define OCEAN_MAX_PLANES 4
// Side of the square workgroup of the per-texel kernels (finalize, mips).
#define OCEAN_TILE 8

// Descriptor bindings of the single descriptor set (set 0).
#define OCEAN_BINDING_PARAMS 0       // SimParams, std430, host-written each frame
#define OCEAN_BINDING_SPECTRUM 1     // vec4 packed S' per texel, all cascades (M.6.5)
#define OCEAN_BINDING_PHASE_RATE 2   // float per texel: loop harmonic j, or ω without a loop
#define OCEAN_BINDING_TWIDDLE 3      // vec2 e^{+2πi·t/N}, t ∈ [0, N)
#define OCEAN_BINDING_PLANES 4       // vec2 per texel per plane per cascade (FFT work)
#define OCEAN_BINDING_DISPLACEMENT 5 // float3 per texel (Dx, h, Dz)
#define OCEAN_BINDING_DISP_HALF 6    // uint2 per texel: half4 (Dx, h, Dz, 0)
#define OCEAN_BINDING_NORMAL 7       // float3 per texel
#define OCEAN_BINDING_JACOBIAN 8     // float per texel
#define OCEAN_BINDING_FOAM 9         // float per texel; also the accumulated foam state
#define OCEAN_BINDING_MIP_WORK 10    // vec4 (n·|n|, blue) per mip texel
#define OCEAN_BINDING_PACKED 11      // uint RGBA8 per mip texel (Aebi, VR Ocean, eq. 51)
#define OCEAN_BINDING_DISP_IMAGE 12  // image2DArray rgba16f, one layer per cascade
#define OCEAN_BINDING_NORMAL_IMAGE 13 // image2DArray rgba8[OCEAN_MAX_MIPS], one view per mip
#define OCEAN_BINDING_COUNT 14

// Descriptor bindings of the far-field noise kernel's own set (far_noise.comp, R.13a).
#define OCEAN_FAR_BINDING_PARAMS 0  // FarNoiseMapParams (src/sim/far_noise.h), written per frame
#define OCEAN_FAR_BINDING_MAP 1     // float3 per texel (h, ∂h/∂x, ∂h/∂z)

// SimParams::normal_method
#define OCEAN_NORMALS_CENTRAL 0
#define OCEAN_NORMALS_SOBEL 1
#define OCEAN_NORMALS_ANALYTIC 2

// Everything the kernels read besides the data arrays. Per-frame fields are rewritten by the
// host before each submit; the rest is set at configure().
struct SimParams {
  uint cascades;
  uint planes;         // complex planes per cascade: 2, or 4 for analytic normals (M.7.2)
  uint normal_method;  // OCEAN_NORMALS_*
  uint blue_is_foam;   // 1: blue = foam, 0: blue = saturate(J/2 + 1/2)
  // Per frame: the phase turns = frac(phase_rate·a) with a = phase_hi + phase_mid + phase_lo,
  // split so that every partial product is exact in FP32 (M.7.3).
  float phase_hi;
  float phase_mid;
  float phase_lo;
  float foam_decay;  // per frame: decay_per_s·dt
  uint reset_foam;   // per frame: 1 on the first step or after a jump back in time
  float choppiness;  // λ
  uint foam_breaking;  // 1: foam source Φ(x), 0: clamp(x, 0, 1), x = (threshold − J)·gain (M.7.4)
  uint pad0;
  float base_length;      // normal length from roughness (Aebi, VR Ocean, eq. 49)
  float base_smoothness;  // smoothness of base_length (eq. 53)
  uint pad1;
  uint pad2;
  float dk[OCEAN_MAX_CASCADES];           // 2π/L, rad/m
  float inv_spacing[OCEAN_MAX_CASCADES];  // N/L, 1/m
  uint mip_offset[OCEAN_MAX_MIPS + 4];    // mip_offset(N, m) (eq. 55)
  float foam_threshold[OCEAN_MAX_CASCADES];  // each cascade's foam source (FoamSourceTerms)
  float foam_gain[OCEAN_MAX_CASCADES];
};

// Φ(x), the standard normal distribution function, by Abramowitz & Stegun eq. 7.1.26, with the
// constants and the cap of src/sim/packing.hpp (normal_cdf).
#ifndef __cplusplus
float normal_cdf(float x) {
  const float z = min(abs(x) * 0.70710678, 10.5);
  const float t = 1.0 / (1.0 + 0.3275911 * z);
  const float poly =
      t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 +
                                                                      t * 1.061405429))));
  const float tail = 0.5 * poly * exp(-z * z);
  return x < 0.0 ? tail : 1.0 - tail;
}
#endif

// Push constants of the mip kernel.
struct MipPush {
  uint level;  // destination level ≥ 1
  uint size;   // N >> level
  uint pad0;
  uint pad1;
};

#ifdef __cplusplus
}  // namespace ocean::vk::shader
#endif

#endif  // OCEAN_SHARED_H
