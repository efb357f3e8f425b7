// `ocean bench --table-one` (bench/table_one.hpp): Table I of [VR-GIS FFT+Perlin], measured here.
#include "bench/table_one.hpp"

#include <iomanip>
#include <iostream>
#include <map>
#include <thread>

#include "bench/harness.hpp"
#include "bench/report.hpp"
#include "cli_common.hpp"
#include "ocean/backends.hpp"
#include "progress.hpp"

namespace ocean::cli::bench {

namespace {

// VR-GIS FFT+Perlin, Table I: CPU and GPU milliseconds per frame at the printed mesh sizes (its
// machine: a 2014-era desktop CPU and GPU, FFT plus Perlin noise).
const std::map<int, std::pair<double, double>> kSource = {
    {128, {31.68, 4.01}}, {512, {132.23, 7.50}}, {1024, {220.78, 10.57}}, {2048, {321.56, 18.30}}};

}  // namespace

int run_table_one(const std::vector<int>& resolutions, int cascades, double min_time, bool json) {
  if (Status s = compiled_in("vulkan"); !s.ok())
    return report(unsupported("ocean bench --table-one: " + s.message()));
  const std::vector<double> sizes = {1000.0, 233.0, 57.0, 13.0};
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  std::string device;
  Progress progress("bench", static_cast<long long>(resolutions.size()));
  long long done = 0;
  std::shared_ptr<TaskRunner> runner = make_tbb_runner();
  for (int n : resolutions) {
    SimulationConfig config;  // the default sea, every output
    config.resolution = n;
    config.cascade_patch_sizes_m.assign(sizes.begin(), sizes.begin() + cascades);
    Result<PipelineResult> cpu = run_pipeline(config, {}, *runner, min_time, 0.0);
    if (!cpu.ok()) return report(cpu.status());
    Result<vk::StageTimings> gpu = vulkan_stage_timings(config, 20);
    if (!gpu.ok()) return report(gpu.status());
    device = gpu.value().device;
    const double cpu_ms = cpu.value().frame.median_ms, gpu_ms = gpu.value().total_ms;
    nlohmann::ordered_json row = {
        {"resolution", n},  {"cascades", cascades}, {"cpu_threads", runner->concurrency()},
        {"cpu_ms", cpu_ms}, {"gpu_ms", gpu_ms},     {"cpu_over_gpu", cpu_ms / gpu_ms}};
    if (auto s = kSource.find(n); s != kSource.end()) {
      row["source_cpu_ms"] = s->second.first;
      row["source_gpu_ms"] = s->second.second;
      row["source_ratio"] = s->second.first / s->second.second;
    }
    rows.push_back(row);
    progress.update(++done);
  }
  progress.finish();
  if (json) {
    print_json({{"device", device}, {"rows", rows}});
    return kExitOk;
  }
  std::cout << "Table I (VR-GIS FFT+Perlin), ours: ms per frame, CPU backend ("
            << runner->concurrency() << " threads, median) against the Vulkan backend on " << device
            << " (GPU time, mean of 20 frames, read-back included); " << cascades << " cascade(s)\n"
            << std::setw(6) << "N" << std::setw(11) << "CPU ms" << std::setw(11) << "GPU ms"
            << std::setw(9) << "CPU/GPU"
            << "   | source: CPU ms  GPU ms  ratio\n";
  for (const auto& r : rows) {
    std::cout << std::setw(6) << r["resolution"].get<int>() << std::setw(11)
              << fixed(r["cpu_ms"].get<double>(), 3) << std::setw(11)
              << fixed(r["gpu_ms"].get<double>(), 3) << std::setw(9)
              << fixed(r["cpu_over_gpu"].get<double>(), 2);
    if (r.contains("source_ratio"))
      std::cout << "   | " << std::setw(14) << fixed(r["source_cpu_ms"].get<double>(), 2)
                << std::setw(8) << fixed(r["source_gpu_ms"].get<double>(), 2) << std::setw(7)
                << fixed(r["source_ratio"].get<double>(), 2);
    std::cout << "\n";
  }
  return kExitOk;
}

}  // namespace ocean::cli::bench
