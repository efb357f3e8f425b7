// `ocean bench --backend cuda`: GPU time per frame, mean over the frames.
#include "bench/cuda_rows.hpp"

#include <iomanip>
#include <iostream>
#include <memory>

#include "bench/harness.hpp"
#include "bench/report.hpp"
#include "cli_common.hpp"
#include "ocean/backends.hpp"
#include "progress.hpp"

namespace ocean::cli::bench {

int run_cuda_bench(const std::vector<int>& resolutions, const std::vector<int>& cascades,
                   const FrameOutputs& outputs, const std::string& outputs_name, bool json) {
  if (Status s = compiled_in("cuda"); !s.ok())
    return report(unsupported("ocean bench --backend cuda: " + s.message()));
  constexpr int kFrames = 50;
  // Both FFT engines where cuFFT loads (which wins where), else the own kernels alone.
  std::vector<std::unique_ptr<Backend>> backends;
  std::string note;
  for (const cuda::FftEngine fft : {cuda::FftEngine::cufft, cuda::FftEngine::kernels}) {
    Result<std::unique_ptr<Backend>> made = make_backend("cuda", {.fft = fft});
    if (made.ok()) {
      backends.push_back(std::move(made).value());
    } else if (fft == cuda::FftEngine::cufft && made.status().message().starts_with("cuFFT")) {
      note = made.status().message();
    } else {
      return report(made.status());
    }
  }
  if (!note.empty()) std::cerr << "ocean bench: " << note << "; cuFFT rows omitted\n";
  const std::string device = capabilities(*backends.front())->device_name();
  std::unique_ptr<TaskRunner> runner = make_serial_runner();
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  Progress progress("bench",
                    static_cast<long long>(resolutions.size() * cascades.size() * backends.size()));
  long long done = 0;
  for (int n : resolutions) {
    for (int c : cascades) {
      const SimulationConfig config = bench_config(n, c, outputs);
      for (const std::unique_ptr<Backend>& b : backends) {
        if (Status s = b->configure(config, *runner); !s.ok()) return report(s);
        DeviceCapabilities& gpu = *capabilities(*b);
        Result<cuda::FrameTimings> t = gpu.time_frames(kFrames);
        if (!t.ok()) return report(t.status());
        const cuda::FrameTimings& v = t.value();
        rows.push_back({{"resolution", n},
                        {"cascades", c},
                        {"backend", "cuda"},
                        {"fft", gpu.fft_engine()},
                        {"device", device},
                        {"outputs", outputs_name},
                        {"gpu_total_ms", v.simulation_ms},
                        {"gpu_serial_ms", v.serial_ms},
                        {"stream_overlap", v.overlap()},
                        {"readback_ms", v.readback_ms}});
        progress.update(++done);
      }
    }
  }
  progress.finish();
  if (json) {
    print_json({{"device", device}, {"rows", rows}});
  } else {
    std::cout << "GPU time per frame on " << device << " from CUDA events, mean of " << kFrames
              << " frames, ms (serial: every cascade on one stream; overlap = serial/total)\n"
              << std::setw(6) << "N" << std::setw(4) << "C" << std::setw(9) << "fft"
              << std::setw(10) << "total" << std::setw(10) << "serial" << std::setw(9) << "overlap"
              << std::setw(10) << "readback\n";
    for (const auto& r : rows) {
      std::cout << std::setw(6) << r["resolution"].get<int>() << std::setw(4)
                << r["cascades"].get<int>() << std::setw(9) << r["fft"].get<std::string>()
                << std::setw(10) << fixed(r["gpu_total_ms"].get<double>(), 4) << std::setw(10)
                << fixed(r["gpu_serial_ms"].get<double>(), 4) << std::setw(9)
                << fixed(r["stream_overlap"].get<double>(), 2) << std::setw(10)
                << fixed(r["readback_ms"].get<double>(), 4) << "\n";
    }
  }
  return kExitOk;
}

}  // namespace ocean::cli::bench
