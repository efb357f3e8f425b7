// `ocean bench --overlap` (bench/overlap.hpp): the cascades, the far field's noise map and both.
#include "bench/overlap.hpp"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

#include "bench/harness.hpp"
#include "bench/report.hpp"
#include "cli_common.hpp"
#include "ocean/backends.hpp"
#include "ocean/backends/cpu.hpp"
#include "progress.hpp"

namespace ocean::cli::bench {

namespace {

// The three measurements alternate frame by frame (cascades, noise, both, cascades, ...), so that
// all three see the same moments of a machine shared with other work: 2 warm-up frames each, then
// at least 5 and about min_time seconds in all (at most 500 each); medians.
struct Timed {
  Stats cascades, noise, both;
};

// `alone(t)` steps the cascades without the map, `noise(t)` the map alone, `both(t)` the frame
// with the map; each advances its own clock by 1/90 s per frame.
template <typename Alone, typename Noise, typename Both>
Timed time_three(double min_time, Alone alone, Noise noise, Both both) {
  std::vector<double> a, n, b;
  double ta = 0.0, tn = 0.0, tb = 0.0, total = 0.0;
  const auto timed = [&total](auto&& step, double& t, std::vector<double>* into) {
    const Clock::time_point start = Clock::now();
    step(t);
    const double s = std::chrono::duration<double>(Clock::now() - start).count();
    t += 1.0 / 90.0;
    if (into == nullptr) return;
    into->push_back(s);
    total += s;
  };
  for (int i = 0; i < 2; ++i) {
    timed(alone, ta, nullptr);
    timed(noise, tn, nullptr);
    timed(both, tb, nullptr);
  }
  while ((a.size() < 5 || total < min_time) && a.size() < 500) {
    timed(alone, ta, &a);
    timed(noise, tn, &n);
    timed(both, tb, &b);
  }
  return {stats_of(a), stats_of(n), stats_of(b)};
}

Result<Timed> time_cpu(const SimulationConfig& with, double min_time, TaskRunner& runner) {
  SimulationConfig without = with;
  without.far_noise.resolution = 0;
  std::unique_ptr<cpu::CpuBackend> plain = cpu::make_cpu_backend();
  std::unique_ptr<cpu::CpuBackend> noisy = cpu::make_cpu_backend();
  if (Status s = plain->configure(without, runner); !s.ok()) return s;
  if (Status s = noisy->configure(with, runner); !s.ok()) return s;
  Frame a, b;
  plain->allocate(a);
  noisy->allocate(b);
  return time_three(
      min_time, [&](double t) { plain->step(t, a); },
      [&](double t) { noisy->step_far_noise(t, b); }, [&](double t) { noisy->step(t, b); });
}

// Wall time of whole frames (submit, wait, copy into the Frame): two backends on one device,
// one without the map and one with it.
Result<Timed> time_vulkan(const SimulationConfig& with, double min_time, std::string& device) {
  SimulationConfig without = with;
  without.far_noise.resolution = 0;
  Result<std::vector<std::unique_ptr<Backend>>> made = make_backends("vulkan", 2);
  if (!made.ok()) return made.status();
  Backend& plain = *made.value()[0];
  Backend& noisy = *made.value()[1];
  DeviceCapabilities& plain_gpu = *capabilities(plain);
  DeviceCapabilities& noisy_gpu = *capabilities(noisy);
  device = plain_gpu.device_name();
  std::unique_ptr<TaskRunner> serial = make_serial_runner();
  if (Status s = plain.configure(without, *serial); !s.ok()) return s;
  if (Status s = noisy.configure(with, *serial); !s.ok()) return s;
  Frame a, b;
  plain.allocate(a);
  noisy.allocate(b);
  const Timed timed = time_three(
      min_time, [&](double t) { plain.step(t, a); },
      [&](double t) { (void)noisy_gpu.step_far_noise(t, b); }, [&](double t) { noisy.step(t, b); });
  if (!plain_gpu.status().ok()) return plain_gpu.status();
  if (!noisy_gpu.status().ok()) return noisy_gpu.status();
  return timed;
}

// CUDA: GPU time from CUDA events (CudaBackend::time_frames: the frame, the cascades alone and the
// map alone as three graphs on the same streams, alternating launch by launch, means of
// kCudaFrames after a warm-up): the device's time, no host round trip.
constexpr int kCudaFrames = 50;
Result<cuda::FrameTimings> time_cuda(const SimulationConfig& with, std::string& device) {
  Result<std::unique_ptr<Backend>> made = make_backend("cuda");
  if (!made.ok()) return made.status();
  Backend& backend = *made.value();
  DeviceCapabilities& gpu = *capabilities(backend);
  device = gpu.device_name() + ", " + std::string(gpu.fft_engine());
  std::unique_ptr<TaskRunner> serial = make_serial_runner();
  if (Status s = backend.configure(with, *serial); !s.ok()) return s;
  return gpu.time_frames(kCudaFrames);
}

}  // namespace

double overlap_of(double cascades_ms, double noise_ms, double both_ms) {
  return (cascades_ms + noise_ms - both_ms) / std::min(cascades_ms, noise_ms);
}

int run_overlap(const OverlapOptions& o) {
  std::shared_ptr<TaskRunner> runner = make_tbb_runner(o.threads);
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  std::string device, vulkan_note, cuda_device, cuda_note;
  Progress progress("bench", static_cast<long long>(o.resolutions.size() * o.cascades.size()));
  long long done = 0;
  for (int n : o.resolutions) {
    for (int c : o.cascades) {
      SimulationConfig config = bench_config(n, c, FrameOutputs::all());
      config.far_noise.resolution = o.noise_resolution;
      std::vector<std::pair<std::string, Result<Timed>>> measured;
      measured.emplace_back("cpu", time_cpu(config, o.min_time, *runner));
      if (Status built = compiled_in("vulkan"); built.ok()) {
        Result<Timed> gpu = time_vulkan(config, o.min_time, device);
        if (gpu.ok() || gpu.status().code() != ErrorCode::unsupported)
          measured.emplace_back("vulkan", gpu);
        else
          vulkan_note = gpu.status().message();
      } else {
        vulkan_note = built.message();
      }
      const auto row = [&](const std::string& backend, double cascades_ms, double noise_ms,
                           double both_ms) {
        return nlohmann::ordered_json{{"backend", backend},
                                      {"resolution", n},
                                      {"cascades", c},
                                      {"noise_resolution", o.noise_resolution},
                                      {"threads", backend == "cpu" ? runner->concurrency() : 0},
                                      {"cascades_ms", cascades_ms},
                                      {"noise_ms", noise_ms},
                                      {"both_ms", both_ms},
                                      {"sum_ms", cascades_ms + noise_ms},
                                      {"overlap", overlap_of(cascades_ms, noise_ms, both_ms)}};
      };
      for (const auto& [backend, timed] : measured) {
        if (!timed.ok()) return report(timed.status());
        const Timed& t = timed.value();
        nlohmann::ordered_json r =
            row(backend, t.cascades.median_ms, t.noise.median_ms, t.both.median_ms);
        r["both_min_max_ms"] = {t.both.min_ms, t.both.max_ms};
        rows.push_back(r);
      }
      if (Status built = compiled_in("cuda"); !built.ok()) {
        cuda_note = built.message();
      } else if (Result<cuda::FrameTimings> cuda_timed = time_cuda(config, cuda_device);
                 cuda_timed.ok()) {
        const cuda::FrameTimings& t = cuda_timed.value();
        nlohmann::ordered_json r = row("cuda", t.cascades_ms, t.noise_ms, t.simulation_ms);
        r["gpu_mean_of_frames"] = kCudaFrames;
        r["serial_ms"] = t.serial_ms;
        rows.push_back(r);
      } else if (cuda_timed.status().code() == ErrorCode::unsupported) {
        cuda_note = cuda_timed.status().message();
      } else {
        return report(cuda_timed.status());
      }
      progress.update(++done);
    }
  }
  progress.finish();
  const std::string definition =
      "(cascades_ms + noise_ms - both_ms) / min(cascades_ms, noise_ms): 1 = the shorter part "
      "hidden entirely, 0 = one after the other";
  if (o.json) {
    nlohmann::ordered_json out = {{"definition", definition}, {"rows", rows}};
    if (!device.empty()) out["vulkan_device"] = device;
    if (!vulkan_note.empty()) out["vulkan_note"] = vulkan_note;
    if (!cuda_device.empty()) out["cuda_device"] = cuda_device;
    if (!cuda_note.empty()) out["cuda_note"] = cuda_note;
    print_json(out);
    return kExitOk;
  }
  std::cout << "The cascades and the far field's noise map, alone and together: median wall time "
               "per frame, ms (CPU: "
            << runner->concurrency() << " threads, two tasks of the frame graph; Vulkan"
            << (device.empty() ? std::string() : " on " + device)
            << ": one submission, no barrier between the noise and the FFT's first stage; CUDA"
            << (cuda_device.empty() ? std::string() : " on " + cuda_device)
            << ": the map on its own stream in the frame's graph, GPU time, mean of " << kCudaFrames
            << " frames)\n"
            << std::setw(8) << "backend" << std::setw(6) << "N" << std::setw(3) << "C"
            << std::setw(7) << "map" << std::setw(11) << "cascades" << std::setw(9) << "noise"
            << std::setw(9) << "both" << std::setw(9) << "sum" << std::setw(9) << "overlap\n";
  for (const auto& r : rows) {
    std::cout << std::setw(8) << r["backend"].get<std::string>() << std::setw(6)
              << r["resolution"].get<int>() << std::setw(3) << r["cascades"].get<int>()
              << std::setw(7) << r["noise_resolution"].get<int>() << std::setw(11)
              << fixed(r["cascades_ms"].get<double>(), 2) << std::setw(9)
              << fixed(r["noise_ms"].get<double>(), 2) << std::setw(9)
              << fixed(r["both_ms"].get<double>(), 2) << std::setw(9)
              << fixed(r["sum_ms"].get<double>(), 2) << std::setw(9)
              << fixed(r["overlap"].get<double>(), 2) << "\n";
  }
  std::cout << "overlap = " << definition << "\n";
  if (!vulkan_note.empty()) std::cout << "vulkan: " << vulkan_note << "\n";
  if (!cuda_note.empty()) std::cout << "cuda: " << cuda_note << "\n";
  return kExitOk;
}

}  // namespace ocean::cli::bench
