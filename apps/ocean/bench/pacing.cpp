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
  RatioSpread rounds, warmed_rounds;
};

// "synthesis, surface, mips" medians of one kind of frame, ms.
std::string stages(const PipelineResult& r) {
  return fixed(r.synthesis.median_ms, 3) + ", " + fixed(r.finalize.median_ms, 3) + ", " +
         fixed(r.mips.median_ms, 3);
}

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
                      .rounds = spread_of(r.value().round_ratios),
                      .warmed_rounds = spread_of(r.value().warmed_round_ratios)};
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
    out["warm_lead_ms"] = kWarmLead_s * 1e3;
    out["rounds"] = kPacedRounds;
    out["rows"] = nlohmann::ordered_json::array();
    const auto stage_json = [](const PipelineResult& p) {
      return nlohmann::ordered_json{{"synthesis_ms", p.synthesis.median_ms},
                                    {"surface_ms", p.finalize.median_ms},
                                    {"mips_ms", p.mips.median_ms}};
    };
    for (const PacingRow& r : rows) {
      const PacedResult& p = r.result;
      const double b2b = p.back_to_back.frame.median_ms;
      out["rows"].push_back({{"frame_interval_ms", r.interval_ms},
                             {"threads", r.threads},
                             {"runner", r.runner},
                             {"paced_ms", p.paced.frame.median_ms},
                             {"warmed_ms", p.warmed.frame.median_ms},
                             {"back_to_back_ms", b2b},
                             {"paced_ratio", p.paced.frame.median_ms / b2b},
                             {"warmed_ratio", p.warmed.frame.median_ms / b2b},
                             {"round_ratio_median", r.rounds.median},
                             {"round_ratio_min", r.rounds.min},
                             {"round_ratio_max", r.rounds.max},
                             {"warmed_round_ratio_median", r.warmed_rounds.median},
                             {"warmed_round_ratio_min", r.warmed_rounds.min},
                             {"warmed_round_ratio_max", r.warmed_rounds.max},
                             {"warm_up_ms", p.warm_up.median_ms},
                             {"paced_stages", stage_json(p.paced)},
                             {"warmed_stages", stage_json(p.warmed)},
                             {"back_to_back_stages", stage_json(p.back_to_back)},
                             {"paced_frames", p.paced.frames},
                             {"warmed_frames", p.warmed.frames},
                             {"back_to_back_frames", p.back_to_back.frames}});
    }
    print_json(out);
    return kExitOk;
  }
  std::cout << "N = " << o.resolution << ", " << o.cascades << " cascades, outputs "
            << o.outputs_name << "; paced frames start a period apart, the runner woken "
            << fixed(kWakeLead_s * 1e3, 1) << " ms ahead; warmed: paced, and the backend's cache "
            << "warm-up called " << fixed(kWarmLead_s * 1e3, 1) << " ms ahead; " << kPacedRounds
            << " rounds alternate back-to-back, paced and warmed frames; medians in ms, ratios "
               "to back to back (rounds' median [min, max])\n";
  std::cout << std::setw(7) << "period" << std::setw(5) << "Hz" << std::setw(5) << "thr"
            << std::setw(7) << "runner" << std::setw(8) << "b2b" << std::setw(8) << "paced" << std::setw(7) << "ratio"
            << std::setw(20) << "rounds" << std::setw(8) << "warmed" << std::setw(7) << "ratio"
            << std::setw(20) << "rounds" << std::setw(9) << "warm-up\n";
  const auto spread = [](const RatioSpread& r) {
    return fixed(r.median, 2) + " [" + fixed(r.min, 2) + ", " + fixed(r.max, 2) + "]";
  };
  for (const PacingRow& r : rows) {
    const PacedResult& p = r.result;
    const double b2b = p.back_to_back.frame.median_ms;
    std::cout << std::setw(7) << fixed(r.interval_ms, 2) << std::setw(5)
              << fixed(1000.0 / r.interval_ms, 0) << std::setw(5) << r.threads << std::setw(7)
              << r.runner << std::setw(8) << fixed(b2b, 3) << std::setw(8)
              << fixed(p.paced.frame.median_ms, 3) << std::setw(7)
              << fixed(p.paced.frame.median_ms / b2b, 2) << std::setw(20) << spread(r.rounds)
              << std::setw(8) << fixed(p.warmed.frame.median_ms, 3) << std::setw(7)
              << fixed(p.warmed.frame.median_ms / b2b, 2) << std::setw(20)
              << spread(r.warmed_rounds) << std::setw(9) << fixed(p.warm_up.median_ms, 3) << "\n";
  }
  std::cout << "stages (synthesis, surface, mips; ms):\n";
  for (const PacingRow& r : rows) {
    std::cout << std::setw(6) << fixed(1000.0 / r.interval_ms, 0) << std::setw(5) << r.threads
              << std::setw(7) << r.runner << "  b2b " << stages(r.result.back_to_back)
              << "; paced " << stages(r.result.paced) << "; warmed " << stages(r.result.warmed)
              << "\n";
  }
  return kExitOk;
}

}  // namespace ocean::cli::bench
