// The host-side plan of a CUDA frame, a pure function of the configuration (tested without a
// device, tests/backends/cuda_test.cpp): where each array lives in the one device allocation and
// in the pinned host buffer, how the mip chain splits into kernel passes, and the frame's
// operations with the stream each runs on and the events that order them (the far field's noise
// map, when on, on a stream of its own beside the cascades').
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
  // The far field's noise map (SimulationConfig::far_noise, docs/rendering.md R.13a), after
  // every cascade's block in both allocations; noise_resolution 0 and empty regions when off.
  // Offsets are from the start of the device allocation and of the pinned host buffer.
  int noise_resolution = 0;    ///< M texels per side
  Region noise_params_device;  ///< noise::FarNoiseMapParams, copied from noise_params_host
  Region noise_map;            ///< float3 (h, ∂h/∂x, ∂h/∂z) per texel: the kernel's output
  Region noise_params_host;    ///< pinned: the frame's FarNoiseMapParams, rewritten per frame
  Region noise_readback;       ///< pinned: the map's copy, read into Frame::far_noise
  /// Bytes of the device allocation (every cascade, then the map) and of the pinned host buffer
  /// (every cascade's readback block, packed, then the map's parameters and readback).
  [[nodiscard]] std::size_t device_bytes() const {
    return noise_resolution > 0 ? noise_map.offset + noise_map.bytes : cascade_bytes * cascades;
  }
  [[nodiscard]] std::size_t host_bytes() const {
    return noise_resolution > 0 ? noise_readback.offset + noise_readback.bytes
                                : readback.bytes * cascades;
  }
};

/// Alignment of every region: cuFFT and vector loads want 16 bytes; 256 is what cudaMalloc gives.
inline constexpr std::size_t kAlignment = 256;

/// validate(config), then the layout. invalid_argument from validate.
Result<Layout> make_layout(const SimulationConfig& config);

/// The frame's operations (evolve and fft: evolution then cuFFT, or with the own FFT kernels the
/// evolution fused into the row transforms, then the column transforms; noise_params, noise and
/// noise_readback: the far field's map). Each runs on stream `stream` (0 = the frame's origin
/// stream, c + 1 = cascade c's, cascades + 1 = the noise map's) after every event in `waits` and
/// records `records` when done. A concurrent schedule forks from the origin with event 0 and joins
/// with one event per cascade (1 + c) and one for the map (cascades + 1), which the final `join`
/// op on the origin waits for; a serial one runs everything on the origin stream and uses no event.
struct Op {
  /// share: the cascade's half4 displacement and RGBA8 chain copied, device to device, into the
  /// renderer's shared buffer (ocean/interop.hpp, interop::inputs_layout).
  enum Kind {
    upload_params,
    fork,  ///< the fork event's record alone, where no upload_params records it
    evolve,
    fft,
    finalize,
    mips,
    share,
    readback,
    noise_params,    ///< the frame's FarNoiseMapParams, pinned host → device
    noise,           ///< the map's kernel
    noise_readback,  ///< the map, device → pinned host
    join
  } kind = upload_params;
  int cascade = -1;  ///< -1 for upload_params, fork, join and the map's operations
  int pass = 0;      ///< for mips: index into Layout::mip_passes
  int stream = 0;
  std::vector<int> waits;
  int records = -1;  ///< event index, -1 for none
};
struct Schedule {
  int streams = 1;      ///< origin + one per cascade + one for the map when concurrent
  int events = 0;       ///< fork + one per cascade + one for the map when concurrent
  std::vector<Op> ops;  ///< in issue order
};

/// What a schedule holds. The map's operations exist only where the layout has a map.
struct ScheduleParts {
  bool concurrent = true;  ///< a stream per cascade and one for the map; else one stream
  bool readback = true;    ///< the copies into pinned memory
  bool cascades = true;    ///< the cascades' chains
  bool noise = true;       ///< the far field's noise map
  /// Each cascade's share op after its last mip pass, before its readback (the renderer's
  /// shared inputs).
  bool share = false;
};
/// Stream and event indices are those of the whole frame whatever the parts, so every schedule
/// of a layout runs on the same DeviceState. The frame parameters' upload (FrameParams) belongs
/// to the cascades: without them a concurrent schedule forks with a `fork` op, so that the map
/// alone times the map alone.
Schedule make_schedule(const Layout& layout, const ScheduleParts& parts);
/// Every part: make_schedule(layout, {concurrent, with_readback, true, true, with_share}).
Schedule make_schedule(const Layout& layout, bool concurrent, bool with_readback,
                       bool with_share = false);
/// The stream (concurrent schedules) and the join event of the far field's noise map.
[[nodiscard]] inline int noise_stream(const Layout& layout) { return layout.cascades + 1; }
[[nodiscard]] inline int noise_event(const Layout& layout) { return layout.cascades + 1; }

}  // namespace ocean::cuda::detail
