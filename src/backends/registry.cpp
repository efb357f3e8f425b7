// The backend table: every backend by name, with a clear answer for those not built in.
#include <string>

#include "cpu/cpu_backend.hpp"
#include "ocean/backends.hpp"
#include "ocean/fft.hpp"

namespace ocean {

std::vector<BackendInfo> list_backends() {
  return {{"cpu", true,
           "SIMD pipeline (" + fft::active_simd_target() + "), radix-4 Stockham FFT, oneTBB"},
          {"vulkan", false,
           "built without Vulkan: the Vulkan compute backend is not part of this build"},
          {"cuda", false, "built without CUDA: the CUDA backend is not part of this build"}};
}

Result<std::unique_ptr<Backend>> make_backend(std::string_view name) {
  if (name == "cpu") return std::unique_ptr<Backend>(std::make_unique<cpu::CpuBackend>());
  for (const BackendInfo& info : list_backends()) {
    if (info.name == name)
      return unsupported("unsupported: backend '" + info.name + "' " + info.detail);
  }
  return invalid_argument("backend = '" + std::string(name) +
                          "' is unknown: must be one of cpu, vulkan, cuda");
}

Result<std::unique_ptr<Simulator>> make_simulator(const SimulationConfig& config,
                                                  std::string_view backend,
                                                  std::shared_ptr<TaskRunner> runner) {
  Result<std::unique_ptr<Backend>> b = make_backend(backend);
  if (!b.ok()) return b.status();
  return Simulator::make(config, std::move(b).value(), std::move(runner));
}

}  // namespace ocean
