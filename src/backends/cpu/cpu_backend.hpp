// The CPU reference backend: spectrum evolution, inverse FFT, displacement, gradients, foam,
// packing and mips on planar float arrays, parallel over rows through the task runner.
#pragma once

#include <array>
#include <atomic>
#include <complex>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "fft/lane_plan.hpp"
#include "kernels.hpp"
#include "ocean/backends/cpu.hpp"
#include "ocean/fft.hpp"
#include "ocean/sim.hpp"
#include "sim/far_noise_map.hpp"
#include "sim/packing.hpp"

namespace ocean::cpu {

/// Zero-initialised float storage on cache lines (huge pages when large): the SIMD kernels'
/// inputs and the planes between the passes.
using AlignedFloats = LargeVector<float>;

/// Per-cascade state that lives across frames.
struct CascadeState {
  int resolution = 0;
  double patch_size_m = 0.0;
  int planes = 2;           ///< plane spectra evolved (plane_count of the normal method)
  double choppiness = 0.0;  ///< λ
  InitialSpectrum spectrum;
  /// Reference pipeline: plane p's spectrum is factor[p][i]·h̃(k_i, t), the fields packed two
  /// per complex plane, in row-major planes (also the analytic gradients' output). The second
  /// cascade of a pair holds plane 0 only (its Dz is in the first's plane 1), here and in the
  /// tiles.
  std::vector<std::vector<std::complex<float>>> factor;
  std::vector<std::vector<float>> plane_re, plane_im;
  // Fused pipeline: structure-of-arrays inputs of the SIMD kernels (kernels.hpp) and each
  // plane between the column and the row pass as column blocks in lane layout (fft.hpp).
  AlignedFloats evolution_spectrum;    ///< EvolveArgs::spectrum records
  std::vector<double> evolution_rate;  ///< EvolveArgs::rate (not looping)
  std::vector<int> evolution_rows;     ///< EvolveArgs::rows (empty: every row)
  /// No spectrum outside rows and columns [N/4, 3N/4) (a band-limited cascade, M.7.1): its
  /// planes transform with the pruned first stage.
  bool outer_half_zero = false;
  AlignedFloats evolution_lane0;             ///< EvolveArgs::lane0 records
  std::vector<double> evolution_lane0_rate;  ///< EvolveArgs::lane0_rate (not looping)
  AlignedFloats tiles;
  std::vector<float*> tile_re, tile_im;  ///< each plane's parts in `tiles`
  LargeVector<float> foam;               ///< accumulated foam carried between frames
  packing::FoamTerms foam_source;        ///< how this cascade's J makes foam (FoamPlan)
  LargeVector<float> mip_work;           ///< float4 (n·len, foam) from mip level mip_work_level on
  int mip_work_level = 0;
  /// The velocity's two row-major planes, (w, u) and (v, unused) (M.7.11); empty unless
  /// outputs.velocity.
  std::vector<std::vector<float>> velocity_re, velocity_im;
  std::vector<float> velocity_khat;                    ///< (k̂x, k̂z) per wave vector
  std::vector<std::int32_t> velocity_harmonic;         ///< j = ω'/ω0 (looping), −1 off the band
  std::vector<std::array<double, 2>> velocity_phasor;  ///< (cos, sin) per j; empty: direct
};

/// Plane p of the reference pipeline's row-major planes as a split-complex view.
inline fft::SplitComplex plane_of(CascadeState& state, std::size_t p) {
  return {state.plane_re[p].data(), state.plane_im[p].data()};
}

/// Number of complex planes a normal method needs (two real fields per plane, M.7.2).
int plane_count(NormalMethod method);
/// Fills state.factor for the configured method and choppiness (M.7.2).
void build_plane_factors(CascadeState& state, NormalMethod method, double choppiness);
/// Fills the evolution kernels' inputs (EvolveArgs::spectrum, ::rate, ::lane0, ::lane0_rate)
/// from the spectrum. With mirror_pairs (and N ≥ 32) the records cover blocks < N/32 only:
/// enough for evolve_planes_mirrored, not for evolve_planes on the other blocks.
void build_kernel_inputs(CascadeState& state, double loop_period_s, bool mirror_pairs = false);
/// Fills state.evolution_rows (EvolveArgs::rows, N ≥ 32) and state.outer_half_zero from the
/// spectrum.
void build_row_ranges(CascadeState& state);
/// The evolution kernels' arguments for time t (M.7.3).
EvolveArgs evolve_args(const CascadeState& state, double time_s, double loop_period_s);
/// Evolves h̃(k, t) with exact phase (M.6.5, M.7.3) and writes every plane's spectrum. With a
/// partner (cascade pairing, M.7.2), plane 1 (D̃z) is added as i·D̃z into the partner's plane 1,
/// which the partner's own evolution wrote first: one transform then carries both Dz fields.
void evolve(CascadeState& state, double time_s, double loop_period_s, TaskRunner& runner,
            CascadeState* dz_partner = nullptr);
/// Displacement float3 and half4 from the transformed planes (scalar reference, eq. 44): Dx and
/// h from plane 0, Dz from `dz` (plane 1's real part, or its partner's imaginary part).
void assemble_displacement_reference(const CascadeState& state, const float* dz, CascadeFrame& out,
                                     TaskRunner& runner);
/// Gradients, normal, Jacobian, foam, base-level packing, from out.displacement (and the
/// gradient planes in analytic mode).
void finalize(CascadeState& state, const SimulationConfig& config, double dt_s, bool reset_foam,
              CascadeFrame& out, TaskRunner& runner);
/// The velocity's per-wave-vector inputs and its phasor table (looping cascades whose harmonics
/// are at most 2^16; the others evaluate each phase): velocity_khat, _harmonic, _phasor.
void build_velocity_inputs(CascadeState& state, double loop_period_s);
/// The velocity of the surface particles at time t (M.7.11): ∂h̃/∂t from the packed spectrum,
/// its horizontal and vertical spectra in the state's two velocity planes, their inverse FFT and
/// the float3 (u, w, v) into out.velocity.
void velocity(CascadeState& state, double time_s, double loop_period_s, const fft::SimdPlan2D& plan,
              CascadeFrame& out, TaskRunner& runner);
/// Box-filtered mip chain with normal-length smoothness (Aebi, VR Ocean, eqs. 52–55).
void build_mips(CascadeState& state, CascadeFrame& out, TaskRunner& runner);

// RGBA8 packing and the roughness encoding (Aebi, VR Ocean, eqs. 49–53), shared with the
// simulation front end.
using packing::normal_length_from_roughness;
using packing::pack_rgba8;
using packing::smoothness_from_normal_length;

/// The CPU backend (ocean/backends/cpu.hpp): configuration and the three pipelines' frames.
class CpuBackendImpl final : public CpuBackend {
 public:
  explicit CpuBackendImpl(CpuOptions options = {}) : options_(options) {}
  [[nodiscard]] std::string_view name() const override { return "cpu"; }
  using Backend::configure;
  Status configure(const SimulationPlan& plan, TaskRunner& runner) override;
  void allocate(Frame& frame) const override;
  void step(double time_s, Frame& out) override;
  [[nodiscard]] const StageTimes& last_stage_times() const override { return times_; }
  [[nodiscard]] std::size_t state_bytes_per_cascade() const override;
  void step_far_noise(double time_s, Frame& out) override;
  void set_far_noise_origin(const std::array<double, 2>& origin_m) override {
    config_.far_noise.origin_m = origin_m;
  }
  void warm_caches(const Frame& out) override;

 private:
  struct CascadeGroup;
  [[nodiscard]] bool group_outer_half_zero(const CascadeGroup& group) const;
  [[nodiscard]] bool plane_outer_half_zero(const CascadeGroup& group, std::size_t c,
                                           std::size_t p) const;
  // The fused pipeline's stages: evolution arguments for the frame, then the column and row
  // passes of groups [first_group, first_group + group_count); the surface pass's arguments,
  // then its rows (with mip levels 1 and 2) and the other mip levels of cascades
  // [first, first + count).
  void prepare_evolution(double time_s);
  void synthesise_fused(TaskRunner& runner, std::size_t first_group, std::size_t group_count,
                        Frame& out);
  void synthesise_unfused(double time_s, Frame& out);
  void prepare_surface(double dt_s, bool reset_foam, Frame& out);
  void surface_fused(TaskRunner& runner, std::size_t first, std::size_t count);
  void mips_fused(TaskRunner& runner, int first_level, std::size_t first, std::size_t count,
                  Frame& out);
  /// The fused central-difference frame as one chain of stages per cascade group, the chains
  /// side by side; each chain's stage loops run on `stages`: the frame's runner, or a serial
  /// runner that keeps each chain on one thread.
  void step_chained(TaskRunner& stages, double time_s, double dt_s, bool reset_foam, Frame& out);
  /// Every cascade's stages when they do not run as chains (step_chained).
  void step_stages(double time_s, double dt_s, bool reset_foam, Frame& out);
  /// The far field's noise map (R.13a) at time_s, its rows a loop on `rows`; times it.
  void far_noise_task(TaskRunner& rows, double time_s, Frame& out);

  CpuOptions options_;
  SimulationConfig config_;
  TaskRunner* runner_ = nullptr;
  std::unique_ptr<TaskRunner> serial_ = make_serial_runner();  ///< a chain's stages, one thread
  fft::Plan2D plan_;
  fft::LanePlan2D simd_plan_;
  fft::SimdPlan2D velocity_plan_;  ///< the velocity's transforms (outputs.velocity only)
  std::vector<CascadeState> cascades_;
  /// Cascades transformed together: pairs sharing plane 1 (Dz of the first in its real part,
  /// of the second in its imaginary part: 3 transforms for 2 cascades instead of 4) when the
  /// normal method needs 2 planes and the pipeline is not the scalar reference, else singles.
  struct CascadeGroup {
    std::size_t first = 0, count = 1;
  };
  std::vector<CascadeGroup> groups_;
  AssemblyStores assembly_stores_;
  std::vector<SurfaceArgs> surface_args_;
  std::vector<EvolveArgs> evolve_args_;
  std::vector<StageTimes> chain_times_;  ///< per cascade group, fused central-difference path
  StageTimes times_;
  FarFieldNoise far_noise_;  ///< fitted at configure when config_.far_noise is on
  double last_time_s_ = 0.0;
  bool has_stepped_ = false;
  std::atomic<unsigned> warm_sink_{0};  ///< what warm_caches read, so that its loads stay
};

}  // namespace ocean::cpu
