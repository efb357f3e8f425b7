// `ocean bench --pacing` (see pacing.hpp).
#include "bench/pacing.hpp"

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

#include "bench/harness.hpp"
#include "bench/report.hpp"
#include "cli_common.hpp"
#include "ocean/task_runner.hpp"
#include "progress.hpp"

namespace ocean::cli::bench {

RatioSpread spread_of(std::vector<double> ratios) {
  std::sort(ratios.begin(), ratios.end());
  const std::size_t n = ratios.size();
  const double median = n % 2 ? ratios[n / 2] : 0.5 * (ratios[n / 2 - 1] + ratios[n / 2]);
  return {median, ratios.front(), ratios.back()};
}

namespace {

struct PacingRow {
  double interval_ms = 0.0;
  int threads = 0;
  std::string runner;
  PacedResult result;
  RatioSpread rounds;
};

}  // namespace

int run_pacing(const PacingOptions& o) {
  const SimulationConfig config = bench_config(o.resolution, o.cascades, o.outputs);
  std::vector<PacingRow> rows;
  Progress progress(
      "bench", static_cast<long long>(o.intervals_ms.size() * o.threads.size() * o.runners.size()));
  long long done = 0;
  for (double interval_ms : o.intervals_ms) {
    for (int t : o.threads) {
      for (const std::string& runner_name : o.runners) {
        std::shared_ptr<TaskRunner> runner =
            runner_name == "ready" ? make_ready_runner({.threads = t}) : make_tbb_runner(t);
        Result<PacedResult> r =
            run_paced_pipeline(config, {}, *runner, o.min_time, interval_ms * 1e-3);
        if (!r.ok()) return report(r.status());
        PacingRow row{.interval_ms = interval_ms,
                      .threads = runner->concurrency(),
                      .runner = runner_name,
                      .result = r.value(),
                      .rounds = spread_of(r.value().round_ratios)};
        rows.push_back(std::move(row));
        progress.update(++done);
      }
    }
  }
  progress.finish();
  if (o.json) {
    nlohmann::ordered_json out;
    out["resolution"] = o.resolution;
    out["cascades"] = o.cascades;
    out["outputs"] = o.outputs_name;
    out["wake_lead_ms"] = kWakeLead_s * 1e3;
    out["rounds"] = kPacedRounds;
    out["rows"] = nlohmann::ordered_json::array();
    for (const PacingRow& r : rows) {
      out["rows"].push_back(
          {{"frame_interval_ms", r.interval_ms},
           {"threads", r.threads},
           {"runner", r.runner},
           {"paced_ms", r.result.paced.frame.median_ms},
           {"back_to_back_ms", r.result.back_to_back.frame.median_ms},
           {"paced_ratio", r.result.paced.frame.median_ms / r.result.back_to_back.frame.median_ms},
           {"round_ratio_median", r.rounds.median},
           {"round_ratio_min", r.rounds.min},
           {"round_ratio_max", r.rounds.max},
           {"paced_frames", r.result.paced.frames},
           {"back_to_back_frames", r.result.back_to_back.frames}});
    }
    print_json(out);
    return kExitOk;
  }
  std::cout << "N = " << o.resolution << ", " << o.cascades << " cascades, outputs "
            << o.outputs_name << "; paced frames start a period apart, the runner woken "
            << fixed(kWakeLead_s * 1e3, 1) << " ms ahead; " << kPacedRounds
            << " rounds alternate back-to-back and paced frames; times are medians in ms\n";
  std::cout << std::setw(9) << "period" << std::setw(6) << "Hz" << std::setw(5) << "thr"
            << std::setw(7) << "runner" << std::setw(9) << "paced" << std::setw(9) << "b2b"
            << std::setw(7) << "ratio"
            << "   rounds: median [min, max]\n";
  for (const PacingRow& r : rows) {
    std::cout << std::setw(9) << fixed(r.interval_ms, 2) << std::setw(6)
              << fixed(1000.0 / r.interval_ms, 0) << std::setw(5) << r.threads << std::setw(7)
              << r.runner << std::setw(9) << fixed(r.result.paced.frame.median_ms, 3)
              << std::setw(9) << fixed(r.result.back_to_back.frame.median_ms, 3) << std::setw(7)
              << fixed(r.result.paced.frame.median_ms / r.result.back_to_back.frame.median_ms, 2)
              << "   " << fixed(r.rounds.median, 2) << " [" << fixed(r.rounds.min, 2) << ", "
              << fixed(r.rounds.max, 2) << "]\n";
  }
  return kExitOk;
}

}  // namespace ocean::cli::bench
