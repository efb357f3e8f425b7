// Internal: the SIMD kernels of the CPU backend's fused passes (Highway, dispatched at run time):
// spectrum evolution straight into a column block of the FFT, and the displacement assembly
// from a row block. Lane layout as in src/fft/lane_kernels.hpp: 16 lines interleaved.
#pragma once

#include <complex>
#include <cstddef>
#include <cstdint>

#include "sim/packing.hpp"

namespace ocean::cpu {

/// Inputs of the evolution of one cascade, in column-block order so that a column block's
/// evolution reads one sequential stream: for column block b and row j, a record of `record`
/// floats at spectrum + (b·N + j)·record holds the S' components of the block's 16 columns
/// (4 × 16 floats, M.6.5) and, when looping, their harmonic indices (16 floats, exact
/// integers).
struct EvolveArgs {
  int n = 0;
  const float* spectrum = nullptr;
  std::size_t record = 64;
  /// Not looping: ω/2π per texel, block-major ((b·N + j)·16 + l). Looping: null.
  const double* rate = nullptr;
  /// Column 16·b of every block b alone, for the mirrored kernel, which evolves only that
  /// column of a mirror block: per (b, j), kLane0Record floats at lane0 + (b·N + j)·8 (the S'
  /// components, then the harmonic index when looping), and, not looping, its rate at
  /// lane0_rate[b·N + j].
  const float* lane0 = nullptr;
  const double* lane0_rate = nullptr;
  /// Mirrored kernel: for block pair b, only rows [rows[2b], rows[2b + 1]) (closed under
  /// row → (N − row) mod N) carry spectrum in either block; the others are written as zeros
  /// without evolving them. Null: every row.
  const int* rows = nullptr;
  /// Mirrored kernel: bit p set when plane p transforms with the pruned first stage, which
  /// reads rows [N/4, 3N/4) only: the rows without spectrum are written as zeros only there.
  unsigned pruned_planes = 0;
  /// Phase in turns is frac(rate·clock): rate = harmonic index and clock = frac(t/T) when
  /// looping (exact, M.7.3), rate = ω/2π and clock = t otherwise.
  double clock = 0.0;
  /// 2: planes (h + i·Dx, Dz); 4: the analytic-gradient planes as well (M.7.2). Each plane's
  /// spectrum is a factor of k times h̃, computed from k = Δk·(col − N/2, row − N/2).
  int planes = 2;
  double dk = 0.0;      ///< 2π/L
  double lambda = 0.0;  ///< choppiness
  /// Cascade pairing (2 planes): instead of writing D̃z into plane 1, add i·D̃z to it (the
  /// first cascade of the pair wrote its own D̃z there), so that one transform yields both
  /// cascades' Dz: the first's in the real part, this one's in the imaginary part.
  bool dz_into_imaginary = false;
};

/// Record length of EvolveArgs::spectrum: 80 floats when looping, 64 otherwise.
constexpr std::size_t evolution_record(bool looping) { return looping ? 80 : 64; }
/// Record length of EvolveArgs::lane0 (5 floats used, two records per cache line).
constexpr std::size_t kLane0Record = 8;

/// Plane spectra as multiples of h̃ at wave vector (kx, kz) (M.7.2): f[0..1] for 2 planes,
/// f[0..3] for 4. The oracle's double-precision formulas, shared with the reference pipeline.
void plane_factors(double kx, double kz, double lambda, int planes, std::complex<double>* f);

/// Evolves h̃(k, t) on columns [16·block, 16·block + 16) and writes every plane's spectrum
/// factor·h̃ in lane layout: re[p]/im[p][row·16 + l] for column 16·block + l (N·16 floats each,
/// 64-byte aligned); with dz_into_imaginary, plane 1 is read and updated.
void evolve_planes(const EvolveArgs& args, int block, float* const* re, float* const* im);

/// The same for block `block` < N/32 and its mirror block N/16 − 1 − block together (N ≥ 32):
/// h̃(−k) = conj h̃(k) exactly, so the mirror block's columns 16·mirror + m, m ≥ 1, come from
/// column 16·block + 16 − m with no sine or cosine of their own; its column 16·mirror is
/// evolved directly from EvolveArgs::lane0. Same results as evolve_planes on both blocks, bit
/// for bit; it reads no records of blocks ≥ N/32.
void evolve_planes_mirrored(const EvolveArgs& args, int block, float* const* re, float* const* im,
                            float* const* mirror_re, float* const* mirror_im);

/// Reference evolution of texel (row, col) with the same phase recipe in double precision and
/// std::cos/std::sin (the oracle the SIMD kernel is tested against): every plane's value.
void evolve_texel_reference(const EvolveArgs& args, int row, int col, float* re, float* im);

/// Which maps the displacement assembly writes with streaming (non-temporal) stores, which go
/// to memory past the caches without reading the lines first: for frames larger than the
/// caches, whose maps would leave them before anything reads them. Used on AVX-512 where the
/// rows are 64-byte aligned; elsewhere the stores are ordinary ones. Same bits either way.
struct AssemblyStores {
  bool stream_displacement = false;  ///< the float3 map (read again by the surface pass)
  bool stream_half = false;          ///< the half4 map (not read in the frame)
};

/// From a row block's transformed planes in lane layout (plane 0 = h + i·Dx, plane 1 = Dz + i·…)
/// writes rows [16·block, 16·block + 16) of the displacement float3 and half4 maps, applying
/// (−1)^(x+y) (eq. 43).
void assemble_displacement(const float* h, const float* dx, const float* dz, int n, int block,
                           float* displacement, std::uint16_t* displacement_half,
                           AssemblyStores stores = {});

/// Inputs and outputs of the surface pass (gradients by central differences, normal, Jacobian,
/// foam, base level of the packed map) of one cascade.
struct SurfaceArgs {
  int n = 0;
  const float* displacement = nullptr;  ///< float3 (Dx, h, Dz) per texel
  float inv_spacing = 0.0f;             ///< N/L
  float base_length = 1.0f;             ///< normal length for the base roughness (eq. 49)
  float smoothness = 0.0f;              ///< smoothness of the base level (eq. 53)
  packing::FoamTerms foam_source;       ///< the foam source's terms (M.7.4)
  float decay = 0.0f;                   ///< decay_per_s·Δt
  bool reset_foam = true;
  bool blue_is_foam = true;
  float* foam_state = nullptr;  ///< accumulated foam, read and written
  // Optional outputs (FrameOutputs): null when not requested.
  float* jacobian = nullptr;
  float* foam = nullptr;
  float* normal = nullptr;          ///< float3
  float* mip_work = nullptr;        ///< float4 (n·len, blue) from level 2 on: level 2 is written
  std::uint32_t* packed = nullptr;  ///< RGBA8 chain: levels 0, 1 and 2 are written
};

/// The surface pass for rows 4·first … 4·(first + count) − 1 with central differences and
/// toroidal wrap (eqs. 45–51), the SIMD twin of finalize()'s central-difference path, and rows
/// 2·first … of mip level 1 and first … first + count − 1 of mip level 2 from them (eqs.
/// 52–53; the float4 work values of levels 0 and 1 stay on the stack, so mip_work's levels 0
/// and 1 are not written). Each displacement row is deinterleaved once into a ring of three.
void surface_row_quads(const SurfaceArgs& args, int first, int count);

/// One row of mip level `level` ≥ 1 from level − 1 (Aebi, VR Ocean, eqs. 52–53): 2×2 box filter
/// of the float4 work values (roughness-scaled normal, blue), smoothness from the filtered
/// normal's length, RGBA8 packing. `packed` points at the start of the whole RGBA8 chain, `work`
/// at the work values of level `work_level` ≤ level − 1, followed by the levels below it.
void mip_row(int n, int level, int row, float* work, int work_level, std::uint32_t* packed);

}  // namespace ocean::cpu
