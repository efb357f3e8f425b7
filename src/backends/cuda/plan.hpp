// The host-side plan of a CUDA frame, a pure function of the configuration (tested without a
// device, tests/backends/cuda_test.cpp): where each array lives in the one device allocation and
// in the pinned host buffer, how the mip chain splits into kernel passes, and the frame's
// operations with the stream each runs on and the events that order them.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "ocean/sim.hpp"

namespace ocean::cuda::detail {

/// The outputs read back each frame, in the order of the readback block and of Frame's arrays.
enum Output : int {
  displacement,
  displacement_half,
  normal,
  jacobian,
  foam,
  packed_mips,
  kOutputs
};

/// A byte range inside one cascade's block (device) or readback block (device and host).
struct Region {
  std::size_t offset = 0;
  std::size_t bytes = 0;
};

/// One mip kernel pass: reads level `source` (work values), writes levels source+1 …
/// source+levels; each thread block reduces a tile×tile square of the source level. The pass with
/// source 0 runs inside the finalize kernel (level 0 never leaves the block).
struct MipPass {
  int source = 0;
  int levels = 0;
  int tile = 0;
};

struct Layout {
  int resolution = 0;
  int log2_resolution = 0;
  int cascades = 0;
  int planes = 0;          ///< complex FFT planes per cascade: 2, or 4 for analytic normals
  std::size_t texels = 0;  ///< N²
  std::size_t chain = 0;   ///< mip_chain_texels(N)
  // Regions of one cascade's device block (every offset a multiple of kAlignment):
  Region spectrum;    ///< float4 packed S' per texel (M.6.5), uploaded at configure
  Region phase_rate;  ///< double EvolutionPhase::rate per texel (M.7.3)
  Region twiddle;     ///< float2 e^{+2πi·t/N}, t ∈ [0, N) (the own FFT kernels')
  Region fft_planes;  ///< float2 per texel per plane: the FFT's work, in place
  Region mip_work;    ///< float4 (n·|n|, blue) per mip texel; pass sources only
  Region foam_state;  ///< float per texel, when foam is not read back (else foam's)
  Region readback;    ///< the requested outputs, contiguous, copied in one piece
  std::size_t cascade_bytes = 0;
  /// Each output's range inside the readback block; bytes = 0 when not requested.
  std::array<Region, kOutputs> outputs{};
  std::vector<MipPass> mip_passes;
  /// Bytes of the device allocation (every cascade) and of the pinned host buffer.
  [[nodiscard]] std::size_t device_bytes() const { return cascade_bytes * cascades; }
  [[nodiscard]] std::size_t host_bytes() const { return readback.bytes * cascades; }
};

/// Alignment of every region: cuFFT and vector loads want 16 bytes; 256 is what cudaMalloc gives.
inline constexpr std::size_t kAlignment = 256;

/// validate(config), then the layout. invalid_argument from validate.
Result<Layout> make_layout(const SimulationConfig& config);

/// The frame's operations (evolve and fft: evolution then cuFFT, or with the own FFT kernels the
/// evolution fused into the row transforms, then the column transforms). Each runs on stream
/// `stream` (0 = the frame's origin stream, c + 1 = cascade c's) after every event in `waits` and
/// records `records` when done. A concurrent schedule forks from the origin with event 0 and joins
/// with one event per cascade (1 + c), which the final `join` op on the origin waits for; a serial
/// one runs everything on the origin stream and uses no event.
struct Op {
  /// share: the cascade's half4 displacement and RGBA8 chain copied, device to device, into the
  /// renderer's shared buffer (ocean/interop.hpp, interop::inputs_layout).
  enum Kind {
    upload_params,
    evolve,
    fft,
    finalize,
    mips,
    share,
    readback,
    join
  } kind = upload_params;
  int cascade = -1;  ///< -1 for upload_params and join
  int pass = 0;      ///< for mips: index into Layout::mip_passes
  int stream = 0;
  std::vector<int> waits;
  int records = -1;  ///< event index, -1 for none
};
struct Schedule {
  int streams = 1;  ///< origin + one per cascade when concurrent
  int events = 0;
  std::vector<Op> ops;  ///< in issue order
};
/// `with_share`: each cascade's share op after its last mip pass, before its readback.
Schedule make_schedule(const Layout& layout, bool concurrent, bool with_readback,
                       bool with_share = false);

}  // namespace ocean::cuda::detail
