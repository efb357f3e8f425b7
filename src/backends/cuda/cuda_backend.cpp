// The CUDA backend: host side. configure() generates every cascade's spectrum with the CPU code
// (again at each reconfigure), uploads it with the exact phase rates of M.7.3, creates the
// device state (device_state.cpp) and captures the frame into a graph; a frame rewrites the
// per-frame parameters, launches the graph and copies the pinned readback into the Frame. The far
// field's noise map, when configured, is far_noise_state.cpp's: fitted here, its parameters
// written with the frame's, its copy read with the cascades'.
//
// This work is based on: Aebi, VR Ocean, §4.2 (stage chain), §4.2.1 (spectrum regenerated on
// demand); docs/math.md (M.7.3) for the exact looping phase.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "device_state.hpp"
#include "errors.hpp"
#include "far_noise_state.hpp"
#include "ocean/plan.hpp"
#include "sim/packing.hpp"

namespace ocean::cuda {

using detail::DeviceState;
using detail::to_status;

namespace {

// The configuration's scalars as the kernels read them.
detail::CascadeArgs base_args(const SimulationConfig& config, const detail::Layout& l) {
  detail::CascadeArgs a;
  a.n = l.resolution;
  a.log2n = l.log2_resolution;
  a.planes = l.planes;
  a.normal_method = config.normals == NormalMethod::analytic ? detail::kNormalsAnalytic
                    : config.normals == NormalMethod::sobel  ? detail::kNormalsSobel
                                                             : detail::kNormalsCentral;
  a.blue_is_foam = config.blue_channel == BlueChannel::foam ? 1 : 0;
  a.choppiness = static_cast<float>(config.choppiness);
  a.foam_breaking = config.foam.source == FoamSource::breaking ? 1 : 0;
  const float r = static_cast<float>(config.roughness);
  a.base_length = 1.0f - r * (0.306f + r * (0.113f + r * 0.081f));      // Aebi, VR Ocean, eq. 49
  const float t = std::clamp(3.0f * a.base_length - 2.0f, 0.0f, 1.0f);  // eq. 53
  a.base_smoothness = 1.0f - std::sqrt((1.0f - t) * (1.0f + 0.15f * t));
  for (int m = 0; m <= l.log2_resolution; ++m)
    a.mip_offset[m] = static_cast<std::uint32_t>(mip_offset(l.resolution, m));
  return a;
}

}  // namespace

std::string_view to_string(FftEngine engine) {
  switch (engine) {
    case FftEngine::cufft: return "cufft";
    case FftEngine::kernels: return "kernels";
    case FftEngine::automatic: break;
  }
  return "automatic";
}

CudaBackend::CudaBackend(int device, FftEngine fft) : device_(device), fft_(fft) {
  cudaDeviceProp p{};
  if (cudaGetDeviceProperties(&p, device) == cudaSuccess) device_name_ = p.name;
}
CudaBackend::~CudaBackend() {
  (void)cudaSetDevice(device_);
  gpu_.reset();
}

Status CudaBackend::configure(const SimulationPlan& plan, TaskRunner& /*runner*/) {
  const SimulationConfig& config = plan.config();
  if (config.outputs.velocity) {
    return unsupported(
        "the CUDA backend does not compute the velocity (outputs.velocity): use the "
        "cpu backend");
  }
  Result<detail::Layout> layout = detail::make_layout(config);
  if (!layout.ok()) return layout.status();
  const detail::Layout& l = layout.value();
  const FarFieldNoise far_noise =
      config.far_noise.resolution > 0 ? plan.far_noise() : FarFieldNoise{};
  const detail::CufftLibrary* cufft = nullptr;
  if (fft_ == FftEngine::cufft) {
    Result<const detail::CufftLibrary*> loaded = detail::load_cufft();
    if (!loaded.ok()) return loaded.status();
    cufft = loaded.value();
  }
  if (Status s = to_status(cudaSetDevice(device_), "cudaSetDevice"); !s.ok()) return s;

  gpu_.reset();  // frees the previous configuration first (lower peak memory)
  auto gpu = std::make_unique<DeviceState>();
  if (Status s = detail::create_device_state(*gpu, l, cufft, base_args(config, l)); !s.ok())
    return s;
  std::vector<double> rate(l.texels);
  std::vector<float> twiddle(2 * static_cast<std::size_t>(l.resolution));
  for (int t = 0; t < l.resolution; ++t) {  // e^{+2πi·t/N}, double precision then float
    const double angle = 2.0 * kPi * t / l.resolution;
    twiddle[2 * static_cast<std::size_t>(t)] = static_cast<float>(std::cos(angle));
    twiddle[2 * static_cast<std::size_t>(t) + 1] = static_cast<float>(std::sin(angle));
  }
  for (int c = 0; c < l.cascades; ++c) {
    const double size_m = config.cascade_patch_sizes_m[static_cast<std::size_t>(c)];
    detail::CascadeArgs& args = gpu->args[static_cast<std::size_t>(c)];
    args.dk = static_cast<float>(2.0 * kPi / size_m);
    args.inv_spacing = static_cast<float>(l.resolution / size_m);
    const packing::FoamTerms foam =
        packing::foam_terms(config.foam, plan.foam().cascades[static_cast<std::size_t>(c)]);
    args.foam_threshold = foam.threshold;
    args.foam_gain = foam.gain;
    // Spectra on the host (the CPU reference code) and the phase rate of EvolutionPhase (M.7.3).
    Result<InitialSpectrum> h0 =
        make_initial_spectrum(plan.sea(), plan.cascades()[static_cast<std::size_t>(c)].spectrum);
    if (!h0.ok())
      return Status(h0.status().code(),
                    "cascade " + std::to_string(c) + ": " + h0.status().message());
    for (std::size_t i = 0; i < l.texels; ++i)
      rate[i] = EvolutionPhase::rate(h0.value().omega[i], config.loop_period_s);
    char* block = gpu->device + static_cast<std::size_t>(c) * l.cascade_bytes;
    if (Status s = to_status(cudaMemcpy(block + l.spectrum.offset, h0.value().packed.data(),
                                        l.spectrum.bytes, cudaMemcpyHostToDevice),
                             "the spectrum upload");
        !s.ok())
      return s;
    if (Status s = to_status(cudaMemcpy(block + l.phase_rate.offset, rate.data(),
                                        l.phase_rate.bytes, cudaMemcpyHostToDevice),
                             "the spectrum upload");
        !s.ok())
      return s;
    if (Status s = to_status(cudaMemcpy(block + l.twiddle.offset, twiddle.data(), l.twiddle.bytes,
                                        cudaMemcpyHostToDevice),
                             "the twiddle upload");
        !s.ok())
      return s;
  }
  // The uploads and the memset ran on the legacy default stream, with which the backend's
  // non-blocking streams do not synchronise (and a pageable copy may return before its DMA ends).
  if (Status s = to_status(cudaDeviceSynchronize(), "the spectrum upload"); !s.ok()) return s;
  // One eager frame (loads every kernel and cuFFT's, and reports a failure where it happens),
  // then the same schedule captured once into the graph every step launches.
  const detail::Schedule frame = detail::make_schedule(l, true, true);
  detail::write_noise_params(*gpu, far_noise, config.far_noise, 0.0);
  if (Status s = detail::issue(*gpu, frame, false); !s.ok()) return s;
  if (Status s = to_status(cudaStreamSynchronize(gpu->streams.front()), "the first frame"); !s.ok())
    return s;
  if (Status s = detail::issue(*gpu, frame, true, &gpu->frame); !s.ok()) return s;
  gpu_ = std::move(gpu);
  config_ = config;
  far_noise_ = far_noise;
  status_ = {};
  has_stepped_ = false;
  pending_ = false;
  return {};
}

void CudaBackend::allocate(Frame& frame) const { allocate_frame(config_, frame); }

Status CudaBackend::share_inputs(interop::SharedInputs& shared) {
  if (!gpu_) return invalid_argument("CUDA backend: share_inputs() before configure()");
  DeviceState& g = *gpu_;
  const detail::Layout& l = g.layout;
  if (shared.layout.resolution != l.resolution || shared.layout.cascades != l.cascades)
    return invalid_argument(
        "CUDA backend: the shared inputs are for N = " + std::to_string(shared.layout.resolution) +
        " and " + std::to_string(shared.layout.cascades) + " cascades, configured for " +
        std::to_string(l.resolution) + " and " + std::to_string(l.cascades));
  // The frame's half4 map and RGBA8 chain are what the share copies move (always read back).
  if (l.outputs[detail::displacement_half].bytes != shared.layout.displacement_bytes ||
      l.outputs[detail::packed_mips].bytes != shared.layout.mips_bytes)
    return invalid_argument("CUDA backend: the shared layout's arrays differ from the frame's");
  if (shared.memory_fd < 0 || shared.written_fd < 0 || shared.read_fd < 0)
    return invalid_argument("CUDA backend: the shared inputs lack a descriptor");
  if (Status s = to_status(cudaSetDevice(device_), "cudaSetDevice"); !s.ok()) return s;
  g.release_shared();
  const Status made = [&]() -> Status {
    cudaExternalMemoryHandleDesc memory{};
    memory.type = cudaExternalMemoryHandleTypeOpaqueFd;
    memory.handle.fd = shared.memory_fd;
    memory.size = shared.memory_bytes;
    memory.flags = shared.dedicated ? cudaExternalMemoryDedicated : 0u;
    if (Status s = to_status(cudaImportExternalMemory(&g.shared_memory, &memory),
                             "cudaImportExternalMemory (the renderer's buffer)");
        !s.ok())
      return s;
    shared.memory_fd = -1;
    cudaExternalMemoryBufferDesc buffer{};
    buffer.offset = 0;
    buffer.size = shared.layout.bytes();
    void* mapped = nullptr;
    if (Status s = to_status(cudaExternalMemoryGetMappedBuffer(&mapped, g.shared_memory, &buffer),
                             "cudaExternalMemoryGetMappedBuffer");
        !s.ok())
      return s;
    g.shared = static_cast<char*>(mapped);
    for (auto [fd, semaphore] :
         {std::pair{&shared.written_fd, &g.written}, std::pair{&shared.read_fd, &g.read}}) {
      cudaExternalSemaphoreHandleDesc desc{};
      desc.type = shared.timeline ? cudaExternalSemaphoreHandleTypeTimelineSemaphoreFd
                                  : cudaExternalSemaphoreHandleTypeOpaqueFd;
      desc.handle.fd = *fd;
      if (Status s = to_status(cudaImportExternalSemaphore(semaphore, &desc),
                               "cudaImportExternalSemaphore (the renderer's semaphore)");
          !s.ok())
        return s;
      *fd = -1;
    }
    g.shared_layout = shared.layout;
    g.timeline = shared.timeline;
    return detail::issue(g, detail::make_schedule(l, true, true, true), true, &g.shared_frame);
  }();
  if (!made.ok()) g.release_shared();
  return made;
}

static_assert(static_cast<int>(DeviceOutput::displacement) == detail::displacement &&
                  static_cast<int>(DeviceOutput::displacement_half) == detail::displacement_half &&
                  static_cast<int>(DeviceOutput::normal) == detail::normal &&
                  static_cast<int>(DeviceOutput::jacobian) == detail::jacobian &&
                  static_cast<int>(DeviceOutput::foam) == detail::foam &&
                  static_cast<int>(DeviceOutput::packed_mips) == detail::packed_mips,
              "DeviceOutput follows the readback block's order");

Result<const void*> CudaBackend::device_output(int cascade, DeviceOutput output) const {
  if (!gpu_) return Status(ErrorCode::internal, "CUDA backend queried before configure()");
  const detail::Layout& l = gpu_->layout;
  if (cascade < 0 || cascade >= l.cascades) {
    return invalid_argument("cascade = " + std::to_string(cascade) +
                            " is out of range: must be 0 to " + std::to_string(l.cascades - 1));
  }
  // Every output sits in the cascade's readback block, the region read() copies to the host.
  const detail::Region& r = l.outputs[static_cast<int>(output)];
  if (r.bytes == 0)
    return unsupported("the output is not computed by this configuration (see outputs)");
  return static_cast<const void*>(gpu_->device +
                                  static_cast<std::size_t>(cascade) * l.cascade_bytes +
                                  l.readback.offset + r.offset);
}

std::uint64_t CudaBackend::shared_frame() const {
  return gpu_ && gpu_->shared_frame != nullptr ? gpu_->shared_frames : 0;
}

Status CudaBackend::submit_shared() {
  DeviceState& g = *gpu_;
  cudaStream_t origin = g.streams.front();
  const std::uint64_t n = g.shared_frames + 1;
  if (n > 1) {  // the renderer has copied frame n − 1 out of the buffer
    cudaExternalSemaphoreWaitParams wait{};
    wait.params.fence.value = n - 1;  // ignored for a binary semaphore
    if (Status s = to_status(cudaWaitExternalSemaphoresAsync(&g.read, &wait, 1, origin),
                             "cudaWaitExternalSemaphoresAsync");
        !s.ok())
      return s;
  }
  if (Status s = to_status(cudaGraphLaunch(g.shared_frame, origin), "cudaGraphLaunch"); !s.ok())
    return s;
  cudaExternalSemaphoreSignalParams signal{};
  signal.params.fence.value = n;
  if (Status s = to_status(cudaSignalExternalSemaphoresAsync(&g.written, &signal, 1, origin),
                           "cudaSignalExternalSemaphoresAsync");
      !s.ok())
    return s;
  g.shared_frames = n;
  return {};
}

Status CudaBackend::submit(double time_s) {
  if (!status_.ok()) return status_;
  if (!gpu_) return status_ = Status(ErrorCode::internal, "CUDA backend used before configure()");
  // Foam accumulates over the time since the previous step; a first step or a jump back in time
  // starts it afresh (as the CPU backend).
  const bool reset_foam = !has_stepped_ || time_s < last_time_s_;
  const double dt = reset_foam ? 0.0 : time_s - last_time_s_;
  *gpu_->params_host = {.clock = EvolutionPhase(time_s, config_.loop_period_s).clock(),
                        .foam_decay = static_cast<float>(config_.foam.decay_per_s * dt),
                        .reset_foam = reset_foam ? 1u : 0u};
  detail::write_noise_params(*gpu_, far_noise_, config_.far_noise, time_s);
  pending_far_origin_m_ = config_.far_noise.origin_m;
  if (Status s = to_status(cudaSetDevice(device_), "cudaSetDevice"); !s.ok()) return status_ = s;
  if (gpu_->shared_frame != nullptr) {
    if (Status s = submit_shared(); !s.ok()) return status_ = s;
  } else if (Status s =
                 to_status(cudaGraphLaunch(gpu_->frame, gpu_->streams.front()), "cudaGraphLaunch");
             !s.ok()) {
    return status_ = s;
  }
  pending_ = true;
  pending_time_s_ = time_s;
  last_time_s_ = time_s;
  has_stepped_ = true;
  return {};
}

Status CudaBackend::read(Frame& out) {
  if (!pending_) return status_;
  pending_ = false;
  if (Status s = to_status(cudaStreamSynchronize(gpu_->streams.front()), "a frame"); !s.ok())
    return status_ = s;
  const detail::Layout& l = gpu_->layout;
  for (std::size_t c = 0; c < out.cascades.size(); ++c) {
    CascadeFrame& f = out.cascades[c];
    const char* block = gpu_->host + c * l.readback.bytes;
    const auto at = [](auto& v) -> void* { return v.empty() ? nullptr : v.data(); };
    void* dst[detail::kOutputs] = {at(f.displacement), at(f.displacement_half),
                                   at(f.normal),       at(f.jacobian),
                                   at(f.foam),         at(f.packed_mips)};
    for (int o = 0; o < detail::kOutputs; ++o) {
      const detail::Region& r = l.outputs[o];
      if (dst[o] != nullptr && r.bytes != 0) std::memcpy(dst[o], block + r.offset, r.bytes);
    }
  }
  detail::read_noise_map(*gpu_, out);
  if (!out.far_noise.height_slope.empty()) out.far_noise.origin_m = pending_far_origin_m_;
  out.time_s = pending_time_s_;
  return {};
}

void CudaBackend::step(double time_s, Frame& out) {
  if (submit(time_s).ok()) (void)read(out);
}

Result<FrameTimings> CudaBackend::time_frames(int frames) {
  if (frames < 1) return invalid_argument("frames = " + std::to_string(frames) + " must be ≥ 1");
  if (!gpu_) return Status(ErrorCode::internal, "CUDA backend timed before configure()");
  if (!status_.ok()) return status_;
  if (Status s = to_status(cudaSetDevice(device_), "cudaSetDevice"); !s.ok()) return s;
  DeviceState& g = *gpu_;
  const detail::Layout& l = g.layout;
  const bool with_noise = l.noise_resolution > 0;
  // The frame without readback (concurrent, serial) and, with a map, each part alone.
  const std::pair<cudaGraphExec_t*, detail::ScheduleParts> graphs[] = {
      {&g.simulation, {.readback = false}},
      {&g.serial, {.concurrent = false, .readback = false}},
      {&g.cascades_alone, {.readback = false, .noise = false}},
      {&g.noise_alone, {.readback = false, .cascades = false}}};
  for (const auto& [graph, parts] : graphs) {
    if (*graph != nullptr || (!with_noise && !(parts.cascades && parts.noise))) continue;
    if (Status s = detail::issue(g, detail::make_schedule(l, parts), true, graph); !s.ok())
      return s;
  }
  cudaStream_t origin = g.streams.front();
  // Mean GPU time of `frames` runs of each of `enqueues` on the origin stream, after one warm-up
  // run of each; with several, they alternate run by run (as ocean bench --overlap's
  // measurements), so that a clock that changes during the run reaches each alike.
  using Enqueue = std::function<Status()>;
  const auto time = [&](const std::vector<Enqueue>& enqueues) -> Result<std::vector<double>> {
    std::vector<double> total_ms(enqueues.size(), 0.0);
    for (int i = 0; i <= frames; ++i) {
      g.params_host->clock = (i + 1) / 60.0;
      g.params_host->reset_foam = 0;
      detail::write_noise_params(g, far_noise_, config_.far_noise, (i + 1) / 60.0);
      for (std::size_t k = 0; k < enqueues.size(); ++k) {
        if (Status s = to_status(cudaEventRecord(g.start, origin), "cudaEventRecord"); !s.ok())
          return s;
        if (Status s = enqueues[k](); !s.ok()) return s;
        if (Status s = to_status(cudaEventRecord(g.stop, origin), "cudaEventRecord"); !s.ok())
          return s;
        if (Status s = to_status(cudaEventSynchronize(g.stop), "a timed frame"); !s.ok()) return s;
        float ms = 0.0f;
        if (Status s =
                to_status(cudaEventElapsedTime(&ms, g.start, g.stop), "cudaEventElapsedTime");
            !s.ok())
          return s;
        if (i > 0) total_ms[k] += ms;
      }
    }
    for (double& t : total_ms) t /= frames;
    return total_ms;
  };
  const auto launch = [&](cudaGraphExec_t graph) -> Enqueue {
    return [&, graph] { return to_status(cudaGraphLaunch(graph, origin), "cudaGraphLaunch"); };
  };
  // The frame and, with a map, the cascades alone and the map alone (their overlap).
  Result<std::vector<double>> concurrent =
      with_noise ? time({launch(g.simulation), launch(g.cascades_alone), launch(g.noise_alone)})
                 : time({launch(g.simulation)});
  if (!concurrent.ok()) return concurrent.status();
  Result<std::vector<double>> serial = time({launch(g.serial)});
  if (!serial.ok()) return serial.status();
  detail::Schedule copies;  // the frame's readback alone, on the origin stream
  for (int c = 0; c < l.cascades; ++c)
    copies.ops.push_back({.kind = detail::Op::readback, .cascade = c});
  if (with_noise) copies.ops.push_back({.kind = detail::Op::noise_readback});
  Result<std::vector<double>> readback = time({[&] { return detail::issue(g, copies, false); }});
  if (!readback.ok()) return readback.status();
  const std::vector<double>& both = concurrent.value();
  return FrameTimings{.simulation_ms = both[0],
                      .serial_ms = serial.value()[0],
                      .readback_ms = readback.value()[0],
                      .cascades_ms = with_noise ? both[1] : both[0],
                      .noise_ms = with_noise ? both[2] : 0.0};
}

}  // namespace ocean::cuda
