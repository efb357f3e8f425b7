// The Vulkan compute backend: host side. configure() generates every cascade's spectrum with the
// CPU code (on demand: again at each reconfigure), converts ω into the exact phase rate of M.7.3
// and uploads it once; a frame writes the per-frame parameters, resubmits the pre-recorded
// command buffer and copies the read-back outputs into the Frame.
//
// This work is based on: Aebi, VR Ocean, §4.2 (stage chain), §4.2.1 (spectrum regenerated on
// demand); docs/math.md (M.7.3) for the exact looping phase.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "gpu_state.hpp"
#include "ocean/backends/vulkan.hpp"
#include "ocean/plan.hpp"
#include "sim/far_noise_map.hpp"
#include "sim/packing.hpp"

namespace ocean::vk {
namespace {

// x truncated to 12 significant bits, so that products with another 12-bit value are exact.
float truncate12(double x) {
  if (x == 0.0) return 0.0f;
  int e = 0;
  const double m = std::frexp(x, &e);
  return static_cast<float>(std::ldexp(std::trunc(m * 4096.0) / 4096.0, e));
}

// Splits a ≥ 0 into hi + mid + lo (hi, mid with 12 significant bits) for phase_turns (M.7.3).
void split_phase(double a, shader::SimParams& p) {
  p.phase_hi = truncate12(a);
  const double rest = a - static_cast<double>(p.phase_hi);
  p.phase_mid = truncate12(rest);
  p.phase_lo = static_cast<float>(rest - static_cast<double>(p.phase_mid));
}

Status limit(bool ok, const std::string& what) {
  return ok ? Status{} : unsupported("unsupported on this Vulkan device: " + what);
}

}  // namespace

VulkanBackend::VulkanBackend(std::shared_ptr<Context> context) : context_(std::move(context)) {}
VulkanBackend::~VulkanBackend() = default;

Status VulkanBackend::configure(const SimulationPlan& plan, TaskRunner& /*runner*/) {
  const SimulationConfig& config = plan.config();
  if (config.outputs.velocity) {
    return unsupported(
        "the Vulkan backend does not compute the velocity (outputs.velocity): use the "
        "cpu backend");
  }
  const auto n = static_cast<std::uint32_t>(config.resolution);
  const auto cascades = static_cast<std::uint32_t>(config.cascade_patch_sizes_m.size());
  const std::uint32_t planes = config.normals == NormalMethod::analytic ? 4u : 2u;
  const std::size_t texels = std::size_t{n} * n;
  const VkPhysicalDeviceLimits& lim = context_->properties.limits;
  const std::string res = "resolution " + std::to_string(n);
  if (Status s =
          limit(n * 8 <= lim.maxComputeSharedMemorySize,
                res + " needs " + std::to_string(n * 8) + " bytes of shared memory, device has " +
                    std::to_string(lim.maxComputeSharedMemorySize) + ": lower resolution");
      !s.ok())
    return s;
  if (Status s = limit(
          n / 4 <= lim.maxComputeWorkGroupInvocations && n / 4 <= lim.maxComputeWorkGroupSize[0],
          res + " needs workgroups of " + std::to_string(n / 4) + " invocations");
      !s.ok())
    return s;
  const double plane_bytes = 8.0 * cascades * planes * static_cast<double>(texels);
  if (Status s = limit(plane_bytes <= lim.maxStorageBufferRange,
                       res + " with " + std::to_string(cascades) + " cascades and " +
                           std::to_string(planes) + " planes needs a " +
                           std::to_string(static_cast<long long>(plane_bytes) >> 20) +
                           " MiB storage buffer, device allows " +
                           std::to_string(lim.maxStorageBufferRange >> 20) +
                           " MiB: lower resolution or cascades");
      !s.ok())
    return s;

  // Spectra on the host (the CPU reference code), phase rates for exact evolution (M.7.3): with
  // a loop the integer harmonic j = ω'/ω0, else ω itself.
  std::vector<float> spectrum(4 * cascades * texels), phase_rate(cascades * texels);
  for (std::uint32_t c = 0; c < cascades; ++c) {
    Result<InitialSpectrum> h0 = make_initial_spectrum(plan.sea(), plan.cascades()[c].spectrum);
    if (!h0.ok())
      return Status(h0.status().code(),
                    "cascade " + std::to_string(c) + ": " + h0.status().message());
    std::memcpy(&spectrum[4 * c * texels], h0.value().packed.data(), 16 * texels);
    for (std::size_t i = 0; i < texels; ++i) {
      const double omega = h0.value().omega[i];
      phase_rate[c * texels + i] = static_cast<float>(
          config.loop_period_s > 0.0 ? EvolutionPhase::rate(omega, config.loop_period_s) : omega);
    }
  }
  std::vector<float> twiddle(2 * n);
  for (std::uint32_t t = 0; t < n; ++t) {  // e^{+2πi·t/N}, double precision then float
    const double angle = 2.0 * kPi * t / n;
    twiddle[2 * t] = static_cast<float>(std::cos(angle));
    twiddle[2 * t + 1] = static_cast<float>(std::sin(angle));
  }

  shader::SimParams p{};
  p.cascades = cascades;
  p.planes = planes;
  p.normal_method = config.normals == NormalMethod::analytic ? OCEAN_NORMALS_ANALYTIC
                    : config.normals == NormalMethod::sobel  ? OCEAN_NORMALS_SOBEL
                                                             : OCEAN_NORMALS_CENTRAL;
  p.blue_is_foam = config.blue_channel == BlueChannel::foam ? 1u : 0u;
  p.reset_foam = 1u;
  p.choppiness = static_cast<float>(config.choppiness);
  p.foam_breaking = config.foam.source == FoamSource::breaking ? 1u : 0u;
  const float r = static_cast<float>(config.roughness);
  p.base_length = 1.0f - r * (0.306f + r * (0.113f + r * 0.081f));      // Aebi, VR Ocean, eq. 49
  const float t = std::clamp(3.0f * p.base_length - 2.0f, 0.0f, 1.0f);  // eq. 53
  p.base_smoothness = 1.0f - std::sqrt((1.0f - t) * (1.0f + 0.15f * t));
  for (std::uint32_t c = 0; c < cascades; ++c) {
    const double L = config.cascade_patch_sizes_m[c];
    p.dk[c] = static_cast<float>(2.0 * kPi / L);
    p.inv_spacing[c] = static_cast<float>(n / L);
    const packing::FoamTerms foam = packing::foam_terms(config.foam, plan.foam().cascades[c]);
    p.foam_threshold[c] = foam.threshold;
    p.foam_gain[c] = foam.gain;
  }
  const int levels = std::countr_zero(n);
  for (int m = 0; m <= levels; ++m)
    p.mip_offset[m] = static_cast<std::uint32_t>(mip_offset(config.resolution, m));
  p.mip_offset[levels + 1] = static_cast<std::uint32_t>(mip_chain_texels(config.resolution));

  FarFieldNoise far_noise;
  if (config.far_noise.resolution > 0) far_noise = plan.far_noise();

  gpu_.reset();  // frees the previous configuration first (lower peak memory)
  auto gpu = std::make_unique<detail::GpuState>();
  const FrameOutputs& want = config.outputs;
  const std::array<bool, detail::kOutputs> read_back = {true,          true,      want.normal,
                                                        want.jacobian, want.foam, true};
  if (Status s = detail::create_gpu_state(*gpu, *context_, n, cascades, planes,
                                          {spectrum, phase_rate, twiddle}, p, read_back,
                                          static_cast<std::uint32_t>(config.far_noise.resolution));
      !s.ok())
    return s;
  gpu_ = std::move(gpu);
  config_ = config;
  far_noise_ = far_noise;
  status_ = {};
  timings_ = {};
  has_stepped_ = false;
  pending_ = false;
  return {};
}

void VulkanBackend::allocate(Frame& frame) const { allocate_frame(config_, frame); }

Status VulkanBackend::submit(double time_s) {
  if (!status_.ok()) return status_;
  // Foam accumulates over the time since the previous step; a first step or a jump back in
  // time starts it afresh (as the CPU backend).
  const bool reset_foam = !has_stepped_ || time_s < last_time_s_;
  const double dt = reset_foam ? 0.0 : time_s - last_time_s_;
  auto* p = static_cast<shader::SimParams*>(gpu_->params.mapped);
  if (config_.loop_period_s > 0.0) {
    split_phase(EvolutionPhase(time_s, config_.loop_period_s).clock(), *p);  // τ = frac(t/T)
  } else {
    split_phase(time_s / (2.0 * kPi), *p);
  }
  p->foam_decay = static_cast<float>(config_.foam.decay_per_s * dt);
  p->reset_foam = reset_foam ? 1u : 0u;
  write_far_noise_params(time_s);
  if (Status s = vk::submit(*context_, gpu_->frame); !s.ok()) {
    status_ = s;
    return s;
  }
  pending_ = true;
  pending_time_s_ = time_s;
  last_time_s_ = time_s;
  has_stepped_ = true;
  return {};
}

Status VulkanBackend::read(Frame& out) {
  if (!pending_) return status_;
  pending_ = false;
  if (Status s = wait(*context_, gpu_->frame); !s.ok()) {
    status_ = s;
    return s;
  }
  for (std::size_t c = 0; c < out.cascades.size(); ++c) {
    CascadeFrame& f = out.cascades[c];
    const auto at = [](auto& v) -> void* { return v.empty() ? nullptr : v.data(); };
    void* dst[detail::kOutputs] = {at(f.displacement), at(f.displacement_half),
                                   at(f.normal),       at(f.jacobian),
                                   at(f.foam),         at(f.packed_mips)};
    for (std::size_t o = 0; o < detail::kOutputs; ++o) {
      if (dst[o] == nullptr || !gpu_->read_back[o]) continue;  // not requested (FrameOutputs)
      const std::size_t bytes = gpu_->bytes_per_cascade[o];
      std::memcpy(dst[o], static_cast<const char*>(gpu_->host[o].mapped) + c * bytes, bytes);
    }
  }
  read_far_noise(out);
  if (gpu_->stamps.pool != VK_NULL_HANDLE) {
    double ms[detail::kStamps];
    if (Status s = read_timestamps_ms(*context_, gpu_->stamps, ms); !s.ok()) {
      status_ = s;
      return s;
    }
    timings_ = {.evolve_fft_rows_ms = ms[detail::rows] - ms[detail::start],
                .fft_columns_ms = ms[detail::columns] - ms[detail::rows],
                .finalize_ms = ms[detail::finalized] - ms[detail::columns],
                .mips_ms = ms[detail::mipped] - ms[detail::finalized],
                .readback_ms = ms[detail::copied] - ms[detail::mipped],
                .total_ms = ms[detail::copied] - ms[detail::start]};
  }
  out.time_s = pending_time_s_;
  return {};
}

void VulkanBackend::step(double time_s, Frame& out) {
  if (submit(time_s).ok()) (void)read(out);
}

void VulkanBackend::write_far_noise_params(double time_s) {
  if (gpu_->far_noise.resolution == 0) return;
  const noise::FarNoiseMapParams p = far_noise_map::params(far_noise_, config_.far_noise, time_s);
  std::memcpy(gpu_->far_noise.params.mapped, &p, sizeof(p));
  pending_far_origin_m_ = config_.far_noise.origin_m;
}

void VulkanBackend::read_far_noise(Frame& out) const {
  if (gpu_->far_noise.resolution == 0 || out.far_noise.height_slope.empty()) return;
  out.far_noise.origin_m = pending_far_origin_m_;
  std::memcpy(out.far_noise.height_slope.data(), gpu_->far_noise.host.mapped,
              out.far_noise.height_slope.size() * sizeof(float));
}

Status VulkanBackend::step_far_noise(double time_s, Frame& out) {
  if (!status_.ok() || pending_) return status_;
  if (gpu_ == nullptr || gpu_->far_noise.resolution == 0) return {};
  write_far_noise_params(time_s);
  Status s = vk::submit(*context_, gpu_->far_noise.alone);
  if (s.ok()) s = wait(*context_, gpu_->far_noise.alone);
  if (!s.ok()) {
    status_ = s;
    return s;
  }
  read_far_noise(out);
  return {};
}

SimulationImages VulkanBackend::images() const {
  if (!gpu_) return {};
  return {.displacement = gpu_->displacement_image.image,
          .displacement_view = gpu_->displacement_image.view,
          .normal_foam = gpu_->normal_image.image,
          .normal_foam_view = gpu_->normal_image.view,
          .size = gpu_->resolution,
          .layers = gpu_->cascades,
          .mips = gpu_->normal_image.mips,
          .far_noise = gpu_->far_noise.map.buffer,
          .far_noise_resolution = gpu_->far_noise.resolution};
}

Result<std::unique_ptr<VulkanBackend>> make_vulkan_backend(const ContextParams& params) {
  Result<std::unique_ptr<Context>> ctx = create_context(params);
  if (!ctx.ok()) return ctx.status();
  return std::make_unique<VulkanBackend>(std::shared_ptr<Context>(std::move(ctx).value()));
}

Result<StageTimings> benchmark(const SimulationConfig& config, int frames,
                               const ContextParams& params) {
  if (frames < 1) return invalid_argument("frames = " + std::to_string(frames) + " must be ≥ 1");
  Result<std::unique_ptr<VulkanBackend>> backend = make_vulkan_backend(params);
  if (!backend.ok()) return backend.status();
  VulkanBackend& b = *backend.value();
  if (!b.context().timestamps)
    return unsupported("Vulkan device '" + b.context().info.name + "' has no compute timestamps");
  std::unique_ptr<TaskRunner> runner = make_serial_runner();
  if (Status s = b.configure(config, *runner); !s.ok()) return s;
  Frame frame;
  b.allocate(frame);
  b.step(0.0, frame);  // warm-up
  StageTimings sum;
  for (int i = 0; i < frames; ++i) {
    b.step((i + 1) / 60.0, frame);
    if (!b.status().ok()) return b.status();
    const StageTimings& t = b.timings();
    sum.evolve_fft_rows_ms += t.evolve_fft_rows_ms;
    sum.fft_columns_ms += t.fft_columns_ms;
    sum.finalize_ms += t.finalize_ms;
    sum.mips_ms += t.mips_ms;
    sum.readback_ms += t.readback_ms;
    sum.total_ms += t.total_ms;
  }
  const double inv = 1.0 / frames;
  for (double* v : {&sum.evolve_fft_rows_ms, &sum.fft_columns_ms, &sum.finalize_ms, &sum.mips_ms,
                    &sum.readback_ms, &sum.total_ms})
    *v *= inv;
  sum.device = b.context().info.name;
  return sum;
}

}  // namespace ocean::vk
