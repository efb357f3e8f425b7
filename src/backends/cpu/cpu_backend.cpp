// CPU backend: configuration (spectra per cascade band, plans, buffers) and the per-frame stage
// chain (Aebi, VR Ocean, §4.2). The default pipeline fuses the SIMD evolution into the column
// FFT and the displacement assembly into the row FFT, over all cascades' 16-line blocks at once;
// the scalar reference pipeline (evolve → radix-2 FFT → assemble) is kept as the oracle and for
// external FFT engines. Both then share finalize and the mips.
#include "cpu_backend.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <string>

#include "ocean/plan.hpp"

namespace ocean::cpu {

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

}  // namespace

Status CpuBackendImpl::configure(const SimulationPlan& resolved, TaskRunner& runner) {
  const SimulationConfig& config = resolved.config();
  if (options_.pipeline == CpuPipeline::external_fft && options_.fft == nullptr)
    return invalid_argument("CPU backend: the external FFT pipeline needs an FFT engine");
  Result<fft::Plan2D> plan = fft::Plan2D::make(config.resolution);
  if (!plan.ok()) return plan.status();
  Result<fft::LanePlan2D> simd_plan = fft::LanePlan2D::make(config.resolution);
  if (!simd_plan.ok()) return simd_plan.status();
  fft::SimdPlan2D velocity_plan;
  if (config.outputs.velocity) {
    Result<fft::SimdPlan2D> made = fft::SimdPlan2D::make(config.resolution);
    if (!made.ok()) return made.status();
    velocity_plan = std::move(made).value();
  }
  FarFieldNoise far_noise;
  if (config.far_noise.resolution > 0) far_noise = resolved.far_noise();
  std::vector<CascadeState> cascades(config.cascade_patch_sizes_m.size());
  const auto texels =
      static_cast<std::size_t>(config.resolution) * static_cast<std::size_t>(config.resolution);
  const bool pairs =
      options_.pipeline != CpuPipeline::scalar_reference && plane_count(config.normals) == 2;
  std::vector<CascadeGroup> groups;
  for (std::size_t c = 0; c < cascades.size(); c += pairs ? 2 : 1)
    groups.push_back({c, std::min<std::size_t>(pairs ? 2 : 1, cascades.size() - c)});
  for (std::size_t c = 0; c < cascades.size(); ++c) {
    CascadeState& state = cascades[c];
    state.resolution = config.resolution;
    state.patch_size_m = config.cascade_patch_sizes_m[c];
    Result<InitialSpectrum> spectrum =
        make_initial_spectrum(resolved.sea(), resolved.cascades()[c].spectrum);
    if (!spectrum.ok()) {
      return Status(spectrum.status().code(),
                    "cascade " + std::to_string(c) + ": " + spectrum.status().message());
    }
    state.spectrum = std::move(spectrum).value();
    state.planes = plane_count(config.normals);
    state.choppiness = config.choppiness;
    const bool second_of_pair = pairs && c % 2 == 1;
    const auto planes = second_of_pair ? 1 : static_cast<std::size_t>(state.planes);
    const bool fused = options_.pipeline == CpuPipeline::fused_simd;
    if (fused) {
      build_kernel_inputs(state, config.loop_period_s, true);
      build_row_ranges(state);
      state.tiles = AlignedFloats(2 * planes * texels);  // one allocation: huge pages sooner
      for (std::size_t p = 0; p < planes; ++p) {
        state.tile_re.push_back(state.tiles.data() + 2 * p * texels);
        state.tile_im.push_back(state.tiles.data() + (2 * p + 1) * texels);
      }
    } else {
      build_plane_factors(state, config.normals, config.choppiness);
    }
    if (!fused || config.normals == NormalMethod::analytic) {  // row-major planes
      state.plane_re.assign(planes, std::vector<float>(texels));
      state.plane_im.assign(planes, std::vector<float>(texels));
    }
    state.foam.assign(texels, 0.0f);
    state.foam_source = packing::foam_terms(config.foam, resolved.foam().cascades[c]);
    // The fused central-difference surface pass keeps levels 0 and 1 of the work values on the
    // stack: its chain starts at level 2.
    const bool fused_surface = fused && config.normals == NormalMethod::central_difference;
    state.mip_work_level = fused_surface ? 2 : 0;
    state.mip_work.assign(4 * (mip_chain_texels(config.resolution) -
                               mip_offset(config.resolution, state.mip_work_level)),
                          0.0f);
    if (config.outputs.velocity) {
      state.velocity_re.assign(2, std::vector<float>(texels));
      state.velocity_im.assign(2, std::vector<float>(texels));
      build_velocity_inputs(state, config.loop_period_s);
    }
  }
  config_ = config;
  runner_ = &runner;
  plan_ = std::move(plan).value();
  simd_plan_ = std::move(simd_plan).value();
  velocity_plan_ = std::move(velocity_plan);
  cascades_ = std::move(cascades);
  groups_ = std::move(groups);
  far_noise_ = far_noise;
  surface_args_.assign(cascades_.size(), SurfaceArgs{});
  chain_times_.assign(groups_.size(), StageTimes{});
  // Streaming stores for the maps that would leave the caches before anything reads them: the
  // half map (never read in the frame) from 256², where a cascade pair's maps outgrow a core's
  // L2, and the float map from 512², where they outgrow the last-level cache before the surface
  // pass reads them back. Measured (4 cascades, 2 threads, A/B in one process): 512² −12 %,
  // 1024² −9 %, 2048² −6 %; streaming the float map at 256² is 10 % slower (docs/performance.md).
  assembly_stores_ = {.stream_displacement = config.resolution >= 512,
                      .stream_half = config.resolution >= 256};
  evolve_args_.assign(cascades_.size(), EvolveArgs{});
  has_stepped_ = false;
  return {};
}

void CpuBackendImpl::allocate(Frame& frame) const { allocate_frame(config_, frame); }

std::size_t CpuBackendImpl::state_bytes_per_cascade() const {
  if (cascades_.empty()) return 0;
  const CascadeState& s = cascades_.front();
  const auto bytes = [](const auto& v) { return v.size() * sizeof(v[0]); };
  std::size_t total = bytes(s.spectrum.packed) + bytes(s.spectrum.omega) + bytes(s.spectrum.h0) +
                      bytes(s.evolution_rate) + bytes(s.evolution_lane0_rate) + bytes(s.foam) +
                      bytes(s.mip_work) +
                      (s.evolution_spectrum.size() + s.evolution_lane0.size()) * sizeof(float);
  for (const auto& v : s.factor) total += bytes(v);
  for (const auto& v : s.plane_re) total += 2 * bytes(v);  // with plane_im
  for (const auto& v : s.velocity_re) total += 2 * bytes(v);  // with velocity_im
  total += bytes(s.velocity_khat) + bytes(s.velocity_harmonic) + bytes(s.velocity_phasor);
  total += bytes(s.tiles);
  return total;
}

bool CpuBackendImpl::group_outer_half_zero(const CascadeGroup& group) const {
  bool all = true;
  for (std::size_t c = group.first; c < group.first + group.count; ++c)
    all = all && cascades_[c].outer_half_zero;
  return all;
}

bool CpuBackendImpl::plane_outer_half_zero(const CascadeGroup& group, std::size_t c,
                                           std::size_t p) const {
  // Plane 1 of a pair carries both cascades' Dz; every other plane one cascade's fields.
  return simd_plan_.prunes_outer_half() &&
         (p == 1 ? group_outer_half_zero(group) : cascades_[c].outer_half_zero);
}

void CpuBackendImpl::step_chained(TaskRunner& stages, double time_s, double dt_s, bool reset_foam,
                                  Frame& out) {
  // One chain per cascade group: columns → rows → surface (with mip levels 1 and 2) → the other
  // mip levels, the chains side by side and each stage a loop of its own. With the frame's
  // runner for the stages, a worker that ends its chain helps with the other chains' loops
  // instead of waiting at a barrier per stage; with a serial one, each chain stays on one
  // thread.
  // The far field's noise map, when on, is one more task beside the chains, sharing nothing
  // with them.
  prepare_evolution(time_s);
  prepare_surface(dt_s, reset_foam, out);
  const bool with_noise = config_.far_noise.resolution > 0;
  const std::size_t tasks = groups_.size() + (with_noise ? 1 : 0);
  runner_->parallel_for(tasks, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t g = begin; g < end; ++g) {
      if (g == groups_.size()) {
        // Its rows on the frame's runner even when each chain keeps to one thread: the map
        // shares no data with the chains, and a thread done with its chain helps with it.
        far_noise_task(*runner_, time_s, out);
        continue;
      }
      const CascadeGroup& group = groups_[g];
      const Clock::time_point start = Clock::now();
      synthesise_fused(stages, g, 1, out);
      const Clock::time_point synthesised = Clock::now();
      surface_fused(stages, group.first, group.count);
      const Clock::time_point finalized = Clock::now();
      mips_fused(stages, 3, group.first, group.count, out);
      chain_times_[g] = {seconds(synthesised - start), seconds(finalized - synthesised),
                         seconds(Clock::now() - finalized)};
    }
  });
  // The chains overlap in time: the longest chain's stages.
  times_ = {.far_noise_s = with_noise ? times_.far_noise_s : 0.0};
  for (const StageTimes& t : chain_times_) {
    times_.synthesis_s = std::max(times_.synthesis_s, t.synthesis_s);
    times_.finalize_s = std::max(times_.finalize_s, t.finalize_s);
    times_.mips_s = std::max(times_.mips_s, t.mips_s);
  }
}

void CpuBackendImpl::step(double time_s, Frame& out) {
  // Foam accumulates over the time since the previous step; a first step or a jump back in
  // time starts it afresh.
  const bool reset_foam = !has_stepped_ || time_s < last_time_s_;
  const double dt = reset_foam ? 0.0 : time_s - last_time_s_;
  const bool fused = options_.pipeline == CpuPipeline::fused_simd;
  if (fused && config_.normals == NormalMethod::central_difference) {
    // A chain per thread when there are no more threads than cascade groups and a group's
    // frame (about 3 MiB at 256²) still fits the caches of one core: on a machine whose cores
    // do not share a cache, stealing inside a chain moves its planes and outputs between the
    // cores, and 4 × 64²…256² ran 15–30 % faster with each chain on one thread. From 512² the
    // group's data streams from memory either way, and the groups' unequal costs (band-limited
    // cascades evolve and transform less) weigh more: their stages are shared, 8–30 % faster
    // there (docs/performance.md).
    const bool chain_per_thread =
        static_cast<std::size_t>(runner_->concurrency()) <= groups_.size() &&
        config_.resolution <= 256;
    step_chained(chain_per_thread ? *serial_ : *runner_, time_s, dt, reset_foam, out);
  } else if (config_.far_noise.resolution > 0 && options_.pipeline != CpuPipeline::external_fft) {
    // Two tasks side by side: the cascades' stages and the far field's noise map. (An external
    // FFT engine is called on the thread that calls step(): then the two run in turn, below.)
    double far_noise_s = 0.0;
    runner_->parallel_for(2, 1, [&](std::size_t begin, std::size_t end) {
      for (std::size_t task = begin; task < end; ++task) {
        if (task == 0) {
          step_stages(time_s, dt, reset_foam, out);
        } else {
          far_noise_task(*runner_, time_s, out);
          far_noise_s = times_.far_noise_s;
        }
      }
    });
    times_.far_noise_s = far_noise_s;
  } else {
    step_stages(time_s, dt, reset_foam, out);
    times_.far_noise_s = 0.0;
    if (config_.far_noise.resolution > 0) far_noise_task(*runner_, time_s, out);
  }
  if (config_.outputs.velocity) {
    for (std::size_t c = 0; c < cascades_.size(); ++c)
      velocity(cascades_[c], time_s, config_.loop_period_s, velocity_plan_, out.cascades[c],
               *runner_);
  }
  out.time_s = time_s;
  last_time_s_ = time_s;
  has_stepped_ = true;
}

void CpuBackendImpl::step_stages(double time_s, double dt_s, bool reset_foam, Frame& out) {
  const bool fused = options_.pipeline == CpuPipeline::fused_simd;
  const Clock::time_point start = Clock::now();
  if (fused) {
    prepare_evolution(time_s);
    synthesise_fused(*runner_, 0, groups_.size(), out);
  } else {
    synthesise_unfused(time_s, out);
  }
  const Clock::time_point synthesised = Clock::now();
  for (std::size_t c = 0; c < cascades_.size(); ++c)
    finalize(cascades_[c], config_, dt_s, reset_foam, out.cascades[c], *runner_);
  const Clock::time_point finalized = Clock::now();
  if (fused) {
    mips_fused(*runner_, 1, 0, cascades_.size(), out);
  } else {
    for (std::size_t c = 0; c < cascades_.size(); ++c)
      build_mips(cascades_[c], out.cascades[c], *runner_);
  }
  times_.synthesis_s = seconds(synthesised - start);
  times_.finalize_s = seconds(finalized - synthesised);
  times_.mips_s = seconds(Clock::now() - finalized);
}

void CpuBackendImpl::far_noise_task(TaskRunner& rows, double time_s, Frame& out) {
  const Clock::time_point start = Clock::now();
  const noise::FarNoiseMapParams p = far_noise_map::params(far_noise_, config_.far_noise, time_s);
  float* map = out.far_noise.height_slope.data();
  out.far_noise.origin_m = config_.far_noise.origin_m;
  // Rows in chunks of about 2 K texels (0.2–0.4 ms of work): enough to share even a 64² map
  // between threads, few enough to schedule.
  const std::size_t grain = std::max<std::size_t>(1, 2048 / p.resolution);
  rows.parallel_for(p.resolution, grain, [&](std::size_t begin, std::size_t end) {
    far_noise_map::fill_rows(p, begin, end, map);
  });
  times_.far_noise_s = seconds(Clock::now() - start);
}

void CpuBackendImpl::step_far_noise(double time_s, Frame& out) {
  if (config_.far_noise.resolution == 0) return;
  far_noise_task(*runner_, time_s, out);
}

std::unique_ptr<CpuBackend> make_cpu_backend(CpuOptions options) {
  return std::make_unique<CpuBackendImpl>(options);
}

}  // namespace ocean::cpu
