// `ocean bench --backend vulkan`: GPU time per stage, mean over the frames.
#include "bench/vulkan_rows.hpp"

#include <iomanip>
#include <iostream>

#include "bench/harness.hpp"
#include "bench/report.hpp"
#include "cli_common.hpp"
#include "ocean/backends.hpp"
#include "progress.hpp"

namespace ocean::cli::bench {

int run_vulkan_bench(const std::vector<int>& resolutions, const std::vector<int>& cascades,
                     const FrameOutputs& outputs, const std::string& outputs_name, bool json) {
  if (Status s = compiled_in("vulkan"); !s.ok())
    return report(unsupported("ocean bench --backend vulkan: " + s.message()));
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  Progress progress("bench", static_cast<long long>(resolutions.size() * cascades.size()));
  long long done = 0;
  for (int n : resolutions) {
    for (int c : cascades) {
      const SimulationConfig config = bench_config(n, c, outputs);
      Result<vk::StageTimings> t = vulkan_stage_timings(config, 20);
      if (!t.ok()) return report(t.status());
      const vk::StageTimings& v = t.value();
      rows.push_back({{"resolution", n},
                      {"cascades", c},
                      {"backend", "vulkan"},
                      {"outputs", outputs_name},
                      {"gpu_total_ms", v.total_ms},
                      {"gpu_stages_ms",
                       {{"evolve_fft_rows", v.evolve_fft_rows_ms},
                        {"fft_columns", v.fft_columns_ms},
                        {"finalize", v.finalize_ms},
                        {"mips", v.mips_ms},
                        {"readback", v.readback_ms}}}});
      progress.update(++done);
    }
  }
  progress.finish();
  if (json) {
    print_json({{"rows", rows}});
  } else {
    std::cout << "GPU time per frame from timestamp queries, mean of 20 frames, ms\n"
              << std::setw(6) << "N" << std::setw(4) << "C" << std::setw(10) << "total"
              << std::setw(14) << "evolve+rows" << std::setw(10) << "columns" << std::setw(10)
              << "finalize" << std::setw(8) << "mips" << std::setw(10) << "readback\n";
    for (const auto& r : rows) {
      const auto& st = r["gpu_stages_ms"];
      std::cout << std::setw(6) << r["resolution"].get<int>() << std::setw(4)
                << r["cascades"].get<int>() << std::setw(10)
                << fixed(r["gpu_total_ms"].get<double>(), 3) << std::setw(14)
                << fixed(st["evolve_fft_rows"].get<double>(), 3) << std::setw(10)
                << fixed(st["fft_columns"].get<double>(), 3) << std::setw(10)
                << fixed(st["finalize"].get<double>(), 3) << std::setw(8)
                << fixed(st["mips"].get<double>(), 3) << std::setw(10)
                << fixed(st["readback"].get<double>(), 3) << "\n";
    }
  }
  return kExitOk;
}

}  // namespace ocean::cli::bench
