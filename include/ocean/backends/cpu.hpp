// ocean/backends/cpu.hpp — the CPU backend's options for benchmarks and oracles: which pipeline
// runs, an external FFT engine to measure the pipeline against, and the wall time of each
// stage of the last step. make_backend("cpu") (ocean/backends.hpp) gives the default pipeline;
// this header is for callers that choose.
//
// Contract: as every Backend (ocean/sim.hpp): configure() validates, allocates and plans;
// step() allocates nothing. Target: ocean::backend_cpu.
#pragma once

#include <cstddef>
#include <memory>
#include <span>

#include "ocean/fft.hpp"
#include "ocean/sim.hpp"

namespace ocean::cpu {

/// A third-party FFT engine for baseline measurements: unnormalised inverse 2D transforms of
/// N×N split-complex planes in place, without the (−1)^(x+y) shift (ocean/fft.hpp's sign
/// convention). Called from the backend's step on the thread that calls step().
class ExternalFft {
 public:
  virtual ~ExternalFft() = default;
  virtual void inverse(std::span<const fft::SplitComplex> planes) = 0;
};

enum class CpuPipeline {
  fused_simd,        ///< SIMD evolution fused into the column FFT, assembly into the row FFT
  scalar_reference,  ///< scalar evolution, radix-2 FFT, scalar assembly: the oracle
  external_fft,      ///< as scalar_reference with the FFT replaced by an ExternalFft
};

struct CpuOptions {
  CpuPipeline pipeline = CpuPipeline::fused_simd;
  ExternalFft* fft = nullptr;  ///< required for external_fft; not owned, outlives the backend
};

/// Wall time of the stages of the last step, seconds.
struct StageTimes {
  double synthesis_s = 0.0;  ///< evolution + FFT + displacement assembly
  double finalize_s = 0.0;   ///< gradients, normals, Jacobian, foam, base-level packing
  double mips_s = 0.0;       ///< mip chain
  /// The far field's noise map (SimulationConfig::far_noise), a task beside the cascades': its
  /// own wall time, which overlaps theirs; 0 when the map is off.
  double far_noise_s = 0.0;
};

/// The CPU backend as a Backend with its measurements.
class CpuBackend : public Backend {
 public:
  /// Wall times of the last step's stages (zero before the first step). With central
  /// differences the cascade groups run side by side: the longest group's times.
  [[nodiscard]] virtual const StageTimes& last_stage_times() const = 0;
  /// Bytes of the state kept for one cascade (spectra, kernel inputs, planes, foam, mip work),
  /// not counting the frame the caller owns. Valid after configure().
  [[nodiscard]] virtual std::size_t state_bytes_per_cascade() const = 0;
  /// The far field's noise map alone: Frame::far_noise at time_s, on the configured runner, the
  /// cascades untouched (what `ocean bench --overlap` times against the whole step). No-op when
  /// SimulationConfig::far_noise is off. Allocates nothing.
  virtual void step_far_noise(double time_s, Frame& out) = 0;
};

/// A CPU backend running `options.pipeline`. Allocates the backend only; configure() does the
/// rest.
std::unique_ptr<CpuBackend> make_cpu_backend(CpuOptions options = {});

}  // namespace ocean::cpu
