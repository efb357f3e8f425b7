// CUDA objects of a configured simulation (device_state.hpp): creation, release, and issuing a
// frame's schedule on the streams, eagerly or captured into a graph.
#include "device_state.hpp"

#include <string>

#include "errors.hpp"
#include "far_noise_state.hpp"

namespace ocean::cuda::detail {
namespace {

// The first failure among consecutive calls, for `if (Status s = ...; !s.ok()) return s;`.
#define OCEAN_CUDA_TRY(call, what)                                  \
  do {                                                              \
    if (Status s_ = to_status((call), (what)); !s_.ok()) return s_; \
  } while (false)

// cudaMalloc and cudaMallocHost for typed pointers (the runtime's C API takes void**).
template <typename T>
cudaError_t device_alloc(T** p, std::size_t bytes) {
  void* v = nullptr;
  const cudaError_t e = cudaMalloc(&v, bytes);
  *p = static_cast<T*>(v);
  return e;
}
template <typename T>
cudaError_t pinned_alloc(T** p, std::size_t bytes) {
  void* v = nullptr;
  const cudaError_t e = cudaMallocHost(&v, bytes);
  *p = static_cast<T*>(v);
  return e;
}

Status issue_op(DeviceState& st, const Op& op) {
  cudaStream_t stream = st.streams[static_cast<std::size_t>(op.stream)];
  for (int w : op.waits)
    OCEAN_CUDA_TRY(cudaStreamWaitEvent(stream, st.events[static_cast<std::size_t>(w)], 0),
                   "cudaStreamWaitEvent");
  const std::size_t c = op.cascade < 0 ? 0 : static_cast<std::size_t>(op.cascade);
  const Layout& l = st.layout;
  switch (op.kind) {
    case Op::upload_params:
      OCEAN_CUDA_TRY(cudaMemcpyAsync(st.params_device, st.params_host, sizeof(FrameParams),
                                     cudaMemcpyHostToDevice, stream),
                     "the frame parameters' upload");
      break;
    case Op::evolve:
      OCEAN_CUDA_TRY(
          st.cufft != nullptr ? launch_evolve(st.args[c], stream) : launch_rows(st.args[c], stream),
          "the evolution kernel");
      break;
    case Op::fft: {
      if (st.cufft == nullptr) {
        OCEAN_CUDA_TRY(launch_columns(st.args[c], stream), "the column FFT kernel");
        break;
      }
      if (Status s = to_status(st.cufft->set_stream(st.plans[c], stream), "cufftSetStream");
          !s.ok())
        return s;
      auto* planes = reinterpret_cast<cufftComplex*>(st.args[c].fft_planes);
      if (Status s = to_status(st.cufft->exec_c2c(st.plans[c], planes, planes, CUFFT_INVERSE),
                               "cufftExecC2C");
          !s.ok())
        return s;
      break;
    }
    case Op::finalize: {
      const MipPass& first = l.mip_passes.front();
      OCEAN_CUDA_TRY(launch_finalize(st.args[c], first.tile, first.levels, stream),
                     "the finalize kernel");
      break;
    }
    case Op::mips: {
      const MipPass& p = l.mip_passes[static_cast<std::size_t>(op.pass)];
      OCEAN_CUDA_TRY(launch_mips(st.args[c], p.source, p.tile, p.levels, stream), "the mip kernel");
      break;
    }
    case Op::share: {
      const char* readback = st.device + c * l.cascade_bytes + l.readback.offset;
      const auto cascade = static_cast<int>(c);
      OCEAN_CUDA_TRY(
          cudaMemcpyAsync(st.shared + st.shared_layout.displacement_offset(cascade),
                          readback + l.outputs[displacement_half].offset,
                          st.shared_layout.displacement_bytes, cudaMemcpyDeviceToDevice, stream),
          "the shared displacement copy");
      OCEAN_CUDA_TRY(cudaMemcpyAsync(st.shared + st.shared_layout.mips_offset(cascade),
                                     readback + l.outputs[packed_mips].offset,
                                     st.shared_layout.mips_bytes, cudaMemcpyDeviceToDevice, stream),
                     "the shared mip-chain copy");
      break;
    }
    case Op::readback:
      OCEAN_CUDA_TRY(cudaMemcpyAsync(st.host + c * l.readback.bytes,
                                     st.device + c * l.cascade_bytes + l.readback.offset,
                                     l.readback.bytes, cudaMemcpyDeviceToHost, stream),
                     "the readback copy");
      break;
    case Op::noise_params:
    case Op::noise:
    case Op::noise_readback:
      if (Status s = issue_noise_op(st, op, stream); !s.ok()) return s;
      break;
    case Op::fork:
    case Op::join: break;
  }
  if (op.records >= 0)
    OCEAN_CUDA_TRY(cudaEventRecord(st.events[static_cast<std::size_t>(op.records)], stream),
                   "cudaEventRecord");
  return {};
}

}  // namespace

void DeviceState::release_shared() {
  if (shared_frame != nullptr) (void)cudaGraphExecDestroy(shared_frame);
  for (cudaExternalSemaphore_t s : {written, read})
    if (s != nullptr) (void)cudaDestroyExternalSemaphore(s);
  if (shared != nullptr) (void)cudaFree(shared);
  if (shared_memory != nullptr) (void)cudaDestroyExternalMemory(shared_memory);
  shared_frame = nullptr, written = nullptr, read = nullptr, shared = nullptr;
  shared_memory = nullptr;
  shared_frames = 0;
}

DeviceState::~DeviceState() {
  release_shared();
  for (cudaGraphExec_t g : {frame, simulation, serial, cascades_alone, noise_alone})
    if (g != nullptr) (void)cudaGraphExecDestroy(g);
  for (cufftHandle p : plans) (void)cufft->destroy(p);
  for (cudaEvent_t e : events) (void)cudaEventDestroy(e);
  for (cudaEvent_t e : {start, stop})
    if (e != nullptr) (void)cudaEventDestroy(e);
  for (cudaStream_t s : streams) (void)cudaStreamDestroy(s);
  if (host != nullptr) (void)cudaFreeHost(host);
  if (params_host != nullptr) (void)cudaFreeHost(params_host);
  if (device != nullptr) (void)cudaFree(device);
  if (params_device != nullptr) (void)cudaFree(params_device);
}

Status create_device_state(DeviceState& st, const Layout& l, const CufftLibrary* cufft,
                           const CascadeArgs& base) {
  st.layout = l;
  st.cufft = cufft;
  const auto cascades = static_cast<std::size_t>(l.cascades);
  for (std::size_t i = 0; i <= cascades; ++i) {
    OCEAN_CUDA_TRY(cudaStreamCreateWithFlags(&st.streams.emplace_back(), cudaStreamNonBlocking),
                   "cudaStreamCreate");
    OCEAN_CUDA_TRY(cudaEventCreateWithFlags(&st.events.emplace_back(), cudaEventDisableTiming),
                   "cudaEventCreate");
  }
  OCEAN_CUDA_TRY(cudaEventCreate(&st.start), "cudaEventCreate");
  OCEAN_CUDA_TRY(cudaEventCreate(&st.stop), "cudaEventCreate");
  OCEAN_CUDA_TRY(device_alloc(&st.device, l.device_bytes()), "the simulation's device buffers");
  OCEAN_CUDA_TRY(device_alloc(&st.params_device, sizeof(FrameParams)), "cudaMalloc");
  OCEAN_CUDA_TRY(pinned_alloc(&st.host, l.host_bytes()), "the pinned readback buffer");
  OCEAN_CUDA_TRY(pinned_alloc(&st.params_host, sizeof(FrameParams)), "cudaMallocHost");
  *st.params_host = FrameParams{};
  OCEAN_CUDA_TRY(cudaMemset(st.device, 0, l.device_bytes()), "cudaMemset");

  int n[2] = {l.resolution, l.resolution};
  const int dist = static_cast<int>(l.texels);
  for (std::size_t c = 0; c < cascades; ++c) {
    if (cufft != nullptr) {
      cufftHandle plan = 0;
      if (Status s = to_status(cufft->plan_many(&plan, 2, n, nullptr, 1, dist, nullptr, 1, dist,
                                                CUFFT_C2C, l.planes),
                               "cufftPlanMany");
          !s.ok())
        return s;
      st.plans.push_back(plan);
    }
    char* block = st.device + c * l.cascade_bytes;
    char* readback = block + l.readback.offset;
    const auto output = [&](Output o) -> char* {
      return l.outputs[o].bytes == 0 ? nullptr : readback + l.outputs[o].offset;
    };
    CascadeArgs a = base;
    a.frame = st.params_device;
    a.spectrum = reinterpret_cast<const float4*>(block + l.spectrum.offset);
    a.phase_rate = reinterpret_cast<const double*>(block + l.phase_rate.offset);
    a.twiddle = reinterpret_cast<const float2*>(block + l.twiddle.offset);
    a.fft_planes = reinterpret_cast<float2*>(block + l.fft_planes.offset);
    a.mip_work = reinterpret_cast<float4*>(block + l.mip_work.offset);
    a.foam_state = reinterpret_cast<float*>(block + l.foam_state.offset);
    a.displacement = reinterpret_cast<float*>(output(displacement));
    a.displacement_half = reinterpret_cast<ushort4*>(output(displacement_half));
    a.normal = reinterpret_cast<float*>(output(normal));
    a.jacobian = reinterpret_cast<float*>(output(jacobian));
    a.packed_mips = reinterpret_cast<std::uint32_t*>(output(packed_mips));
    st.args.push_back(a);
  }
  return create_noise_state(st);
}

Status issue(DeviceState& st, const Schedule& schedule, bool capture, cudaGraphExec_t* graph) {
  cudaStream_t origin = st.streams.front();
  if (capture)
    OCEAN_CUDA_TRY(cudaStreamBeginCapture(origin, cudaStreamCaptureModeThreadLocal),
                   "cudaStreamBeginCapture");
  Status issued;
  for (const Op& op : schedule.ops) {
    issued = issue_op(st, op);
    if (!issued.ok()) break;
  }
  if (!capture) return issued;
  cudaGraph_t captured = nullptr;
  const cudaError_t ended = cudaStreamEndCapture(origin, &captured);
  if (!issued.ok() || ended != cudaSuccess) {
    if (captured != nullptr) (void)cudaGraphDestroy(captured);
    return issued.ok() ? to_status(ended, "cudaStreamEndCapture") : issued;
  }
  const cudaError_t made = cudaGraphInstantiateWithFlags(graph, captured, 0);
  (void)cudaGraphDestroy(captured);
  return to_status(made, "cudaGraphInstantiate");
}

}  // namespace ocean::cuda::detail
