// The CUDA backend's kernels: evolution, finalize with the first mip levels, later mip passes.
// The inverse FFT between evolution and finalize is cuFFT's (cuda_backend.cpp). Each kernel
// mirrors the CPU reference stage it names and the Vulkan shader beside it
// (src/backends/vulkan/shaders); compiled with --fmad=false so that, like the CPU's, no product
// is fused into an addition.
//
// This work is based on:
//   - Tessendorf, J. (2001) Simulating Ocean Water, eqs. 43–44 (evolution), 29 (choppy
//     displacement), 37 (slopes), §4.4.
//   - Aebi, VR Ocean, eqs. 24–30 (single-FMA evolution), 42–43 (the (−1)^(x+y) shift), 44
//     (displacement), 45–46 (central differences), 48 (Jacobian), 49–51 (normal length, RGBA8),
//     52–53 (box-filtered mips, length → smoothness), 55 (mip offsets).
//   - Mitchell 2005, §3.2 (Sobel normals); Vincevičius 2024, eq. 2.8 (analytic slopes), §2.4
//     (foam accumulation, listing 2.4); Toksvig, M. (2005) Mipmapping normal maps.
// Equations: docs/math.md (M.6.5), (M.7.2)–(M.7.5).
#include <cuda_fp16.h>

#include "kernels.hpp"

namespace ocean::cuda::detail {
namespace {

constexpr int kBlock = 256;   // threads of the 1-D evolution kernel
constexpr int kMaxTile = 16;  // side of the 2-D blocks (plan.cpp, kTile)

__device__ float2 cmul(float2 a, float2 b) {
  return make_float2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x);
}

// cpu::plane_factors (evolve.cpp): plane p's spectrum is factor·h̃ (M.7.2).
__device__ float2 plane_factor(const CascadeArgs& a, int plane, float kx, float kz) {
  const float k = sqrtf(kx * kx + kz * kz);
  const float ux = k > 0.0f ? kx / k : 0.0f;
  const float uz = k > 0.0f ? kz / k : 0.0f;
  const float lambda = a.choppiness;
  if (plane == 0) return make_float2(1.0f - lambda * ux, 0.0f);                    // (h, Dx)
  if (a.normal_method != kNormalsAnalytic) return make_float2(0.0f, lambda * uz);  // (Dz, ·)
  if (plane == 1) return make_float2(-kx, lambda * uz);             // (Dz, ∂h/∂x)
  if (plane == 2) return make_float2(0.0f, kz - lambda * kx * ux);  // (∂h/∂z, ∂Dx/∂x)
  return make_float2(-lambda * kz * uz, -lambda * kz * ux);         // (∂Dz/∂z, ∂Dx/∂z)
}

// h̃(k, t) of texel i (row-major, DC at (N/2, N/2)) times plane `plane`'s field factor.
__device__ float2 evolved(const CascadeArgs& a, unsigned i, int plane) {
  const int col = static_cast<int>(i & (a.n - 1)), row = static_cast<int>(i >> a.log2n);
  // EvolutionPhase (M.7.3) in double, as the CPU: turns = frac(rate·clock), exact after days.
  double turns = a.phase_rate[i] * a.frame->clock;
  turns -= floor(turns);
  const float t = static_cast<float>(turns >= 0.5 ? turns - 1.0 : turns);
  float s, c;
  sincospif(2.0f * t, &s, &c);
  const float4 p = a.spectrum[i];
  const float2 h = make_float2(p.x * c + p.z * s, p.y * c + p.w * s);  // (M.6.5)
  const float kx = a.dk * static_cast<float>(col - a.n / 2);
  const float kz = a.dk * static_cast<float>(row - a.n / 2);
  return cmul(plane_factor(a, plane, kx, kz), h);
}

// Φ(x), the standard normal distribution function, by Abramowitz & Stegun eq. 7.1.26 with the
// constants and the cap of src/sim/packing.hpp (normal_cdf).
__device__ float normal_cdf(float x) {
  const float z = fminf(fabsf(x) * 0.70710678f, 10.5f);
  const float t = 1.0f / (1.0f + 0.3275911f * z);
  const float poly =
      t * (0.254829592f +
           t * (-0.284496736f + t * (1.421413741f + t * (-1.453152027f + t * 1.061405429f))));
  const float tail = 0.5f * poly * expf(-z * z);
  return x < 0.0f ? tail : 1.0f - tail;
}

__global__ void evolve(CascadeArgs a) {
  const unsigned i = blockIdx.x * blockDim.x + threadIdx.x;
  const unsigned texels = 1u << (2 * a.log2n);
  if (i >= texels) return;
  for (int plane = 0; plane < a.planes; ++plane)
    a.fft_planes[plane * texels + i] = evolved(a, i, plane);
}

// Inverse FFT of line[0..N) in shared memory by the block's max(N/4, 1) threads, a port of the
// Vulkan backend's fft.glsl: Stockham autosort (Stockham 1966; Cochran et al. 1967, "What is the
// fast Fourier transform?", in the formulation of E. Bainville, "OpenCL Fast Fourier Transform"
// (2010)), radix-4 passes then one radix-2 pass when log2 N is odd. x[n] = Σ_k X[k]·e^{+2πi·kn/N},
// unnormalised (docs/conventions.md), as cuFFT's CUFFT_INVERSE and fft::Plan2D::inverse.
__device__ void inverse_fft_shared(const CascadeArgs& a, float2* line) {
  const int n = a.n, quarter = n / 4, j = static_cast<int>(threadIdx.x);
  const float2* tw = a.twiddle;
  int p = 1;
  for (int pass = 0; pass < a.log2n / 2; ++pass) {
    const int k = j & (p - 1);
    const int stride = n / (4 * p);  // e^{2πi·k·r/(4p)} = tw[k·r·stride]
    const float2 a0 = line[j];
    const float2 a1 = cmul(line[j + quarter], tw[k * stride]);
    const float2 a2 = cmul(line[j + 2 * quarter], tw[2 * k * stride]);
    const float2 a3 = cmul(line[j + 3 * quarter], tw[3 * k * stride]);
    // Inverse radix-4 butterfly: y_m = Σ_r a_r·i^{r·m}.
    const float2 s02 = make_float2(a0.x + a2.x, a0.y + a2.y),
                 d02 = make_float2(a0.x - a2.x, a0.y - a2.y);
    const float2 s13 = make_float2(a1.x + a3.x, a1.y + a3.y),
                 d13 = make_float2(a1.x - a3.x, a1.y - a3.y);
    __syncthreads();
    const int base = (j - k) * 4 + k;
    line[base] = make_float2(s02.x + s13.x, s02.y + s13.y);
    line[base + p] = make_float2(d02.x - d13.y, d02.y + d13.x);
    line[base + 2 * p] = make_float2(s02.x - s13.x, s02.y - s13.y);
    line[base + 3 * p] = make_float2(d02.x + d13.y, d02.y - d13.x);
    __syncthreads();
    p *= 4;
  }
  if ((a.log2n & 1) != 0) {  // one radix-2 pass: N/2 butterflies, two per thread
    float2 y[4];
    int base[2];
    for (int b = 0; b < 2; ++b) {
      const int jj = j + b * quarter, k = jj & (p - 1);
      const float2 a0 = line[jj], a1 = cmul(line[jj + n / 2], tw[k * (n / (2 * p))]);
      y[2 * b] = make_float2(a0.x + a1.x, a0.y + a1.y);
      y[2 * b + 1] = make_float2(a0.x - a1.x, a0.y - a1.y);
      base[b] = (jj - k) * 2 + k;
    }
    __syncthreads();
    for (int b = 0; b < 2; ++b) {
      line[base[b]] = y[2 * b];
      line[base[b] + p] = y[2 * b + 1];
    }
    __syncthreads();
  }
}

// Block (row, plane): evolve the row into shared memory, transform it along x.
__global__ void rows(CascadeArgs a) {
  extern __shared__ float2 line[];
  const unsigned row = blockIdx.x;
  const int plane = static_cast<int>(blockIdx.y);
  for (int col = static_cast<int>(threadIdx.x); col < a.n; col += static_cast<int>(blockDim.x))
    line[col] = evolved(a, (row << a.log2n) + static_cast<unsigned>(col), plane);
  __syncthreads();
  inverse_fft_shared(a, line);
  float2* out = a.fft_planes + (static_cast<unsigned>(plane) << (2 * a.log2n)) + (row << a.log2n);
  for (int col = static_cast<int>(threadIdx.x); col < a.n; col += static_cast<int>(blockDim.x))
    out[col] = line[col];
}

// Block (column, plane): the same along z, in place.
__global__ void columns(CascadeArgs a) {
  extern __shared__ float2 line[];
  float2* column = a.fft_planes + (blockIdx.y << (2 * a.log2n)) + blockIdx.x;
  for (int row = static_cast<int>(threadIdx.x); row < a.n; row += static_cast<int>(blockDim.x))
    line[row] = column[row << a.log2n];
  __syncthreads();
  inverse_fft_shared(a, line);
  for (int row = static_cast<int>(threadIdx.x); row < a.n; row += static_cast<int>(blockDim.x))
    column[row << a.log2n] = line[row];
}

// Plane value at a wrapped texel with the (−1)^(col+row) sign that moves DC from the centre of
// the spectrum (Aebi, VR Ocean, eqs. 42–43); cuFFT's inverse is e^{+2πi·kn/N}, unnormalised.
__device__ float2 plane_at(const CascadeArgs& a, int plane, int col, int row) {
  col &= a.n - 1;
  row &= a.n - 1;
  const float2 v = a.fft_planes[(plane << (2 * a.log2n)) + (row << a.log2n) + col];
  return ((col + row) & 1) != 0 ? make_float2(-v.x, -v.y) : v;
}

// (Dx, h, Dz): plane 0 = h + i·Dx, plane 1 = Dz + i·(...) (M.7.2).
__device__ float3 displacement_at(const CascadeArgs& a, int col, int row) {
  const float2 p0 = plane_at(a, 0, col, row);
  return make_float3(p0.y, p0.x, plane_at(a, 1, col, row).x);
}

__device__ float3 operator+(float3 u, float3 v) {
  return make_float3(u.x + v.x, u.y + v.y, u.z + v.z);
}
__device__ float3 operator-(float3 u, float3 v) {
  return make_float3(u.x - v.x, u.y - v.y, u.z - v.z);
}
__device__ float3 operator*(float3 u, float s) { return make_float3(u.x * s, u.y * s, u.z * s); }
__device__ float3 operator*(float s, float3 u) { return u * s; }

// cpu::pack_rgba8: ⌊saturate(v)·255 + 0.5⌋ per channel, R in the low byte (eqs. 50–51).
__device__ unsigned quantise(float v) {
  return static_cast<unsigned>(fminf(fmaxf(v, 0.0f), 1.0f) * 255.0f + 0.5f);
}
__device__ unsigned pack_rgba8(float nx, float nz, float blue, float smoothness) {
  return quantise(nx * 0.5f + 0.5f) | (quantise(nz * 0.5f + 0.5f) << 8) | (quantise(blue) << 16) |
         (quantise(smoothness) << 24);
}

// cpu::smoothness_from_normal_length (eq. 53).
__device__ float smoothness_from_normal_length(float len) {
  const float t = fminf(fmaxf(3.0f * len - 2.0f, 0.0f), 1.0f);
  return 1.0f - sqrtf((1.0f - t) * (1.0f + 0.15f * t));
}

// Reduces the tile×tile work values in `tile` (row stride kMaxTile) by `levels` levels, level
// `first` being the first written; (bx, by) is the block's tile position. cpu::build_mips:
// 2×2 box filter (eq. 52), smoothness from the shrinking length (eq. 53), packed (eq. 51); the
// last level's work values go to mip_work for the next pass. Every thread of the block calls it.
__device__ void reduce_tile(const CascadeArgs& a, float4* tile, int size, int first, int levels) {
  const int tx = threadIdx.x, ty = threadIdx.y;
  for (int l = 0; l < levels; ++l) {
    size >>= 1;
    const int level = first + l;
    const bool active = tx < size && ty < size;
    float4 v = make_float4(0.0f, 0.0f, 0.0f, 0.0f);
    if (active) {
      for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
          const float4 w = tile[(2 * ty + j) * kMaxTile + 2 * tx + i];
          v = make_float4(v.x + w.x, v.y + w.y, v.z + w.z, v.w + w.w);
        }
      }
      v = make_float4(0.25f * v.x, 0.25f * v.y, 0.25f * v.z, 0.25f * v.w);
    }
    __syncthreads();
    if (active) {
      tile[ty * kMaxTile + tx] = v;
      const int level_size = a.n >> level;
      const unsigned d =
          a.mip_offset[level] +
          static_cast<unsigned>((blockIdx.y * size + ty) * level_size + blockIdx.x * size + tx);
      const float len = sqrtf(v.x * v.x + v.y * v.y + v.z * v.z);
      const float inv = len > 0.0f ? 1.0f / len : 0.0f;
      a.packed_mips[d] = pack_rgba8(v.x * inv, v.z * inv, v.w, smoothness_from_normal_length(len));
      if (l == levels - 1) a.mip_work[d] = v;
    }
    __syncthreads();
  }
}

__global__ void finalize(CascadeArgs a, int tile_size, int levels) {
  __shared__ float4 tile[kMaxTile * kMaxTile];
  const int col = static_cast<int>(blockIdx.x * blockDim.x + threadIdx.x);
  const int row = static_cast<int>(blockIdx.y * blockDim.y + threadIdx.y);
  const unsigned i = (static_cast<unsigned>(row) << a.log2n) + static_cast<unsigned>(col);
  const float3 d = displacement_at(a, col, row);

  // Displacement assembly (eq. 44): the sign is applied, λ is in the spectra.
  a.displacement[3 * i + 0] = d.x;
  a.displacement[3 * i + 1] = d.y;
  a.displacement[3 * i + 2] = d.z;
  a.displacement_half[i] =
      make_ushort4(__half_as_ushort(__float2half_rn(d.x)), __half_as_ushort(__float2half_rn(d.y)),
                   __half_as_ushort(__float2half_rn(d.z)), 0);

  // Gradients ∂/∂x (gx) and ∂/∂z (gz) of (Dx, h, Dz).
  float3 gx, gz;
  const float inv_spacing = a.inv_spacing;
  if (a.normal_method == kNormalsAnalytic) {
    const float2 p1 = plane_at(a, 1, col, row), p2 = plane_at(a, 2, col, row);
    const float2 p3 = plane_at(a, 3, col, row);
    gx = make_float3(p2.y, p1.y, p3.y);  // ∂Dz/∂x = ∂Dx/∂z for the irrotational choppy field
    gz = make_float3(p3.y, p2.x, p3.x);
  } else if (a.normal_method == kNormalsSobel) {  // weights (1, 2, 1)/8 (Mitchell 2005, §3.2)
    const int c = col, r = row;
    gx = ((displacement_at(a, c + 1, r - 1) + 2.0f * displacement_at(a, c + 1, r) +
           displacement_at(a, c + 1, r + 1)) -
          (displacement_at(a, c - 1, r - 1) + 2.0f * displacement_at(a, c - 1, r) +
           displacement_at(a, c - 1, r + 1))) *
         0.125f * inv_spacing;
    gz = ((displacement_at(a, c - 1, r + 1) + 2.0f * displacement_at(a, c, r + 1) +
           displacement_at(a, c + 1, r + 1)) -
          (displacement_at(a, c - 1, r - 1) + 2.0f * displacement_at(a, c, r - 1) +
           displacement_at(a, c + 1, r - 1))) *
         0.125f * inv_spacing;
  } else {  // eq. 45
    gx = (displacement_at(a, col + 1, row) - displacement_at(a, col - 1, row)) * 0.5f * inv_spacing;
    gz = (displacement_at(a, col, row + 1) - displacement_at(a, col, row - 1)) * 0.5f * inv_spacing;
  }

  // Jacobian of x → x + D (eq. 48) and the normal ∂p/∂z × ∂p/∂x (M.7.5).
  const float jxx = 1.0f + gx.x, jzz = 1.0f + gz.z;
  const float jacobian = jxx * jzz - gz.x * gx.z;
  float3 n = make_float3(gz.y * gx.z - jzz * gx.y, jacobian, gz.x * gx.y - gz.y * jxx);
  const float len = sqrtf(n.x * n.x + n.y * n.y + n.z * n.z);
  n = len > 0.0f ? make_float3(n.x / len, n.y / len, n.z / len) : make_float3(0.0f, 1.0f, 0.0f);

  // Foam: the source on J, accumulated with Vincevičius's (2024) decay, listing 2.4 (M.7.4).
  const FrameParams& f = *a.frame;
  const float x = (a.foam_threshold - jacobian) * a.foam_gain;
  const float now = a.foam_breaking != 0 ? normal_cdf(x) : fminf(fmaxf(x, 0.0f), 1.0f);
  float foam = now;
  if (f.reset_foam == 0u) {
    const float accumulated = a.foam_state[i] - f.foam_decay / fmaxf(now, 0.5f);
    foam = fminf(fmaxf(fmaxf(accumulated, now), 0.0f), 1.0f);
  }
  a.foam_state[i] = foam;
  if (a.jacobian != nullptr) a.jacobian[i] = jacobian;
  if (a.normal != nullptr) {
    a.normal[3 * i + 0] = n.x;
    a.normal[3 * i + 1] = n.y;
    a.normal[3 * i + 2] = n.z;
  }
  const float blue = a.blue_is_foam != 0 ? foam : fminf(fmaxf(jacobian * 0.5f + 0.5f, 0.0f), 1.0f);
  a.packed_mips[i] = pack_rgba8(n.x, n.z, blue, a.base_smoothness);
  tile[threadIdx.y * kMaxTile + threadIdx.x] =
      make_float4(n.x * a.base_length, n.y * a.base_length, n.z * a.base_length, blue);
  __syncthreads();
  reduce_tile(a, tile, tile_size, 1, levels);
}

__global__ void mips(CascadeArgs a, int source, int tile_size, int levels) {
  __shared__ float4 tile[kMaxTile * kMaxTile];
  const int size = a.n >> source;
  const unsigned col = blockIdx.x * blockDim.x + threadIdx.x;
  const unsigned row = blockIdx.y * blockDim.y + threadIdx.y;
  tile[threadIdx.y * kMaxTile + threadIdx.x] =
      a.mip_work[a.mip_offset[source] + row * static_cast<unsigned>(size) + col];
  __syncthreads();
  reduce_tile(a, tile, tile_size, source + 1, levels);
}

}  // namespace

cudaError_t probe_kernels() {
  cudaFuncAttributes attributes;
  return cudaFuncGetAttributes(&attributes, evolve);
}

cudaError_t launch_evolve(const CascadeArgs& args, cudaStream_t stream) {
  const unsigned texels = 1u << (2 * args.log2n);
  evolve<<<(texels + kBlock - 1) / kBlock, kBlock, 0, stream>>>(args);
  return cudaGetLastError();
}

cudaError_t launch_rows(const CascadeArgs& args, cudaStream_t stream) {
  const dim3 grid(static_cast<unsigned>(args.n), static_cast<unsigned>(args.planes));
  rows<<<grid, static_cast<unsigned>(args.n / 4), sizeof(float2) * args.n, stream>>>(args);
  return cudaGetLastError();
}

cudaError_t launch_columns(const CascadeArgs& args, cudaStream_t stream) {
  const dim3 grid(static_cast<unsigned>(args.n), static_cast<unsigned>(args.planes));
  columns<<<grid, static_cast<unsigned>(args.n / 4), sizeof(float2) * args.n, stream>>>(args);
  return cudaGetLastError();
}

cudaError_t launch_finalize(const CascadeArgs& args, int tile, int levels, cudaStream_t stream) {
  const unsigned blocks = static_cast<unsigned>(args.n / tile);
  finalize<<<dim3(blocks, blocks), dim3(tile, tile), 0, stream>>>(args, tile, levels);
  return cudaGetLastError();
}

cudaError_t launch_mips(const CascadeArgs& args, int source, int tile, int levels,
                        cudaStream_t stream) {
  const unsigned blocks = static_cast<unsigned>((args.n >> source) / tile);
  mips<<<dim3(blocks, blocks), dim3(tile, tile), 0, stream>>>(args, source, tile, levels);
  return cudaGetLastError();
}

}  // namespace ocean::cuda::detail
