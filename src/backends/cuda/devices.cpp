// The CUDA devices of this machine, the backend's factory and its benchmark entry point.
#include <string>

#include "cufft_library.hpp"
#include "errors.hpp"
#include "kernels.hpp"
#include "ocean/backends/cuda.hpp"

namespace ocean::cuda {

using detail::to_status;

namespace {

// "13.0" from the runtime's 13000.
std::string version_text(int v) {
  return std::to_string(v / 1000) + "." + std::to_string(v % 1000 / 10);
}

}  // namespace

std::string runtime_versions() {
  int driver = 0, runtime = 0;
  (void)cudaDriverGetVersion(&driver);  // 0 without a driver
  (void)cudaRuntimeGetVersion(&runtime);
  return "driver " + (driver > 0 ? version_text(driver) : std::string("none")) + ", runtime " +
         version_text(runtime);
}

Result<std::vector<DeviceInfo>> list_devices() {
  int count = 0;
  if (Status s = to_status(cudaGetDeviceCount(&count), "cudaGetDeviceCount"); !s.ok()) return s;
  if (count == 0)
    return unsupported(std::string(detail::kNoDevice) + "the CUDA runtime reports no device");
  std::vector<DeviceInfo> devices;
  for (int d = 0; d < count; ++d) {
    DeviceInfo info{.index = d};
    cudaDeviceProp p{};
    if (Status s = to_status(cudaGetDeviceProperties(&p, d), "cudaGetDeviceProperties"); !s.ok()) {
      info.reason = s.message();
      devices.push_back(info);
      continue;
    }
    info.name = p.name;
    info.compute_major = p.major;
    info.compute_minor = p.minor;
    info.memory_bytes = p.totalGlobalMem;
    info.multiprocessors = p.multiProcessorCount;
    for (std::size_t i = 0; i < info.uuid.size(); ++i)
      info.uuid[i] = static_cast<std::uint8_t>(p.uuid.bytes[i]);
    Status probe = to_status(cudaSetDevice(d), "cudaSetDevice");
    if (probe.ok()) probe = to_status(detail::probe_kernels(), "the kernel probe");
    info.usable = probe.ok();
    info.reason = probe.message();
    devices.push_back(info);
  }
  return devices;
}

Result<std::unique_ptr<CudaBackend>> make_cuda_backend(FftEngine fft) {
  Result<std::vector<DeviceInfo>> devices = list_devices();
  if (!devices.ok()) return devices.status();
  for (const DeviceInfo& d : devices.value())
    if (d.usable) return make_cuda_backend(d.index, fft);
  const DeviceInfo& first = devices.value().front();
  const std::string& why = first.reason;
  return unsupported(why.starts_with(detail::kNoDevice)
                         ? why
                         : std::string(detail::kNoDevice) + first.name + ": " + why);
}

Result<std::unique_ptr<CudaBackend>> make_cuda_backend(int device, FftEngine fft) {
  if (fft != FftEngine::kernels) {
    Result<const detail::CufftLibrary*> cufft = detail::load_cufft();
    if (!cufft.ok() && fft == FftEngine::cufft) return cufft.status();
    fft = cufft.ok() ? FftEngine::cufft : FftEngine::kernels;
  }
  return std::make_unique<CudaBackend>(device, fft);
}

Result<FrameTimings> benchmark(const SimulationConfig& config, int frames, FftEngine fft) {
  if (frames < 1) return invalid_argument("frames = " + std::to_string(frames) + " must be ≥ 1");
  Result<std::unique_ptr<CudaBackend>> backend = make_cuda_backend(fft);
  if (!backend.ok()) return backend.status();
  std::unique_ptr<TaskRunner> runner = make_serial_runner();
  if (Status s = backend.value()->configure(config, *runner); !s.ok()) return s;
  return backend.value()->time_frames(frames);
}

}  // namespace ocean::cuda
