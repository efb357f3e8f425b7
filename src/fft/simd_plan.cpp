// The public SIMD plan (a shared, immutable lane plan) and the SIMD target controls: which
// instruction sets the kernels were built for, forcing one, the FMA peak probe.
#include <hwy/targets.h>

#include <algorithm>
#include <chrono>
#include <string>

#include "fft/lane_kernels.hpp"
#include "fft/lane_plan.hpp"
#include "ocean/fft.hpp"

namespace ocean::fft {

Result<SimdPlan2D> SimdPlan2D::make(int n) {
  Result<LanePlan2D> lanes = LanePlan2D::make(n);
  if (!lanes.ok()) return lanes.status();
  SimdPlan2D plan;
  plan.plan_ = std::make_shared<const LanePlan2D>(std::move(lanes).value());
  return plan;
}

int SimdPlan2D::size() const { return plan_ ? plan_->size() : 0; }

void SimdPlan2D::inverse(std::span<const SplitComplex> planes, TaskRunner& runner,
                         bool sign_correct) const {
  plan_->inverse(planes, runner, sign_correct);
}

namespace {
// The CPU's targets, read once before any forcing narrows what Highway reports.
const std::vector<std::int64_t>& all_targets() {
  static const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
  return targets;
}
}  // namespace

std::vector<std::string> simd_targets() {
  std::vector<std::string> names;
  for (const std::int64_t target : all_targets()) names.emplace_back(hwy::TargetName(target));
  return names;  // ascending bit = best first on x86 and Arm
}

std::string active_simd_target() { return detail::dispatched_target(); }

Status force_simd_target(std::string_view name) {
  if (name.empty()) {
    hwy::SetSupportedTargetsForTest(0);
    return {};
  }
  std::string known;
  for (const std::int64_t target : all_targets()) {
    if (name == hwy::TargetName(target)) {
      hwy::SetSupportedTargetsForTest(target);
      return {};
    }
    known += std::string(known.empty() ? "" : ", ") + hwy::TargetName(target);
  }
  return invalid_argument("SIMD target = '" + excerpt(name) +
                          "' is not available on this CPU: must be one of " + known);
}

double measure_fma_peak_gflops(double seconds) {
  using Clock = std::chrono::steady_clock;
  std::size_t lanes = 0, iterations = 1 << 16;
  double best = 0.0, sink = 0.0, spent = 0.0;
  while (spent < seconds) {  // best of repeated runs, growing until each takes ≥ 10 ms
    const Clock::time_point start = Clock::now();
    sink += detail::fma_loop(iterations, &lanes);
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    spent += elapsed;
    best = std::max(best, 20.0 * double(lanes) * double(iterations) / elapsed * 1e-9);
    if (elapsed < 0.01) iterations *= 2;
  }
  return sink == 0.12345 ? 0.0 : best;  // the comparison keeps the sum alive
}

}  // namespace ocean::fft
