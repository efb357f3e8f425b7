// Surface statistics over several seeds (see ocean/statistics.hpp).
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/fft.hpp"
#include "ocean/plan.hpp"
#include "ocean/statistics.hpp"

namespace ocean {

namespace {

// E|h̃(k)|² = (F(k) + F(−k))·Δk²/2 for every wave vector cascade 0 fills (M.6.2, M.6.3): the
// grid without DC, the Nyquist row and column, and wave vectors outside the band. Index n·N + m.
std::vector<double> expected_power(const SeaState& sea, int n, double patch_size_m,
                                   const std::array<double, 2>& band) {
  const double dk = 2.0 * kPi / patch_size_m;
  const int half = n / 2;
  const auto count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  std::vector<double> f(count, 0.0);
  for (int row = 1; row < n; ++row) {
    for (int col = 1; col < n; ++col) {
      if (row == half && col == half) continue;
      const double kx = dk * (col - half);
      const double kz = dk * (row - half);
      const double k = std::hypot(kx, kz);
      if (k < band[0] || k >= band[1]) continue;  // exactly make_initial_spectrum's test
      f[static_cast<std::size_t>(row * n + col)] = sea.wave_vector_spectrum(kx, kz) * dk * dk;
    }
  }
  // The filled set is symmetric under k → −k: (col, row) → (N − col, N − row).
  std::vector<double> power(count, 0.0);
  for (int row = 1; row < n; ++row) {
    for (int col = 1; col < n; ++col) {
      const auto i = static_cast<std::size_t>(row * n + col);
      const auto j = static_cast<std::size_t>((n - row) * n + (n - col));
      power[i] = 0.5 * (f[i] + f[j]);
    }
  }
  return power;
}

// The height spectrum h̃(k, t) of cascade 0 evolved exactly as the CPU backend does (M.6.5,
// M.7.3), transformed alone; returns the largest |imaginary part| of the field.
double max_imaginary_height(const InitialSpectrum& spectrum, double time_s, double loop_period_s,
                            const fft::Plan2D& plan, TaskRunner& runner) {
  const std::size_t count = spectrum.packed.size();
  std::vector<float> re(count), im(count);
  const EvolutionPhase phase_of(time_s, loop_period_s);
  for (std::size_t i = 0; i < count; ++i) {
    const double phase = phase_of(spectrum.omega[i]);
    const auto c = static_cast<float>(std::cos(phase));
    const auto s = static_cast<float>(std::sin(phase));
    const auto& p = spectrum.packed[i];
    re[i] = p[0] * c + p[2] * s;
    im[i] = p[1] * c + p[3] * s;
  }
  const fft::SplitComplex plane{re.data(), im.data()};
  plan.inverse({&plane, 1}, runner, true);
  float largest = 0.0f;
  for (float v : im) largest = std::max(largest, std::abs(v));
  return largest;
}

}  // namespace

double cox_munk_mean_square_slope(double wind_speed_mps) {
  return 0.003 + 5.12e-3 * wind_speed_mps;
}

double monahan_whitecap_coverage(double wind_speed_mps) {
  return 3.84e-6 * std::pow(wind_speed_mps, 3.41);
}

SlopeVariance cox_munk_slope_variance(double wind_speed_mps) {
  return {.upwind = 3.16e-3 * wind_speed_mps, .crosswind = 0.003 + 1.92e-3 * wind_speed_mps};
}

Result<SurfaceStats> compute_surface_stats(const SimulationConfig& config, int seeds, double time_s,
                                           TaskRunner& runner_ref) {
  if (seeds < 1) {
    return invalid_argument("seeds = " + std::to_string(seeds) + " is out of range: must be >= 1");
  }
  if (Status s = require_finite("time_s", time_s); !s.ok()) return s;
  Result<SimulationPlan> resolved = SimulationPlan::make(config);
  if (!resolved.ok()) return resolved.status();
  const SeaState& sea = resolved.value().sea();
  const int n = config.resolution;
  const double patch = config.cascade_patch_sizes_m.front();
  const std::array<double, 2> band = resolved.value().cascades().front().band_radpm;
  const auto texels = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);

  SurfaceStats out;
  const FrequencySpectrumParams& wind = config.sea.wind_sea.spectrum;
  out.resolution = n;
  out.patch_size_m = patch;
  out.cascades = static_cast<int>(config.cascade_patch_sizes_m.size());
  out.seeds = seeds;
  out.first_seed = config.seed;
  out.time_s = time_s;
  out.choppiness = config.choppiness;
  out.loop_period_s = config.loop_period_s;
  out.model = std::string(to_string(wind.model));
  if (std::isfinite(wind.wind_speed_mps)) {
    out.wind_speed_mps = wind.wind_speed_mps;
    out.cox_munk_mss = cox_munk_mean_square_slope(wind.wind_speed_mps);
    out.cox_munk_slope_variance = cox_munk_slope_variance(wind.wind_speed_mps);
    // Monahan's U10: Pierson–Moskowitz's wind is at 19.5 m (Stewart 2008, §16.5).
    out.monahan_whitecap_coverage = monahan_whitecap_coverage(
        wind.model == SpectrumModel::pierson_moskowitz ? wind.wind_speed_mps / 1.026
                                                       : wind.wind_speed_mps);
  }
  out.unresolved_slope_variance = resolved.value().unresolved_slope_variance();

  // What the spectrum promises: Σ F·Δk² over the filled wave vectors, and the spread.
  const std::vector<double> power = expected_power(sea, n, patch, band);
  double sum_power = 0.0, sum_power2 = 0.0;
  for (double p : power) {
    sum_power += p;
    sum_power2 += p * p;
  }
  const double m0 = sea.variance_m2();
  out.hs_spectrum_m = 4.0 * std::sqrt(sum_power);
  out.hs_closed_form_m = 4.0 * std::sqrt(m0);
  out.resolved_variance_fraction = m0 > 0.0 ? sum_power / m0 : 0.0;
  // Pairs (k, −k) carry one complex Gaussian each: Σ_pairs σ⁴ = Σ_k σ⁴/2 with σ² = 2·power.
  if (sum_power2 > 0.0) {
    out.independent_wave_vectors = sum_power * sum_power / (2.0 * sum_power2);
    out.hs_sampling_rel_std = 0.5 / std::sqrt(out.independent_wave_vectors * seeds);
  }

  // The caller's runner, not owned: the simulators below end before this call returns.
  const std::shared_ptr<TaskRunner> runner(std::shared_ptr<TaskRunner>(), &runner_ref);
  Result<fft::Plan2D> plan = fft::Plan2D::make(n);
  if (!plan.ok()) return plan.status();

  double variance_sum = 0.0;
  double s1 = 0.0, s2 = 0.0, s3 = 0.0, s4 = 0.0;  // pooled raw power sums of h
  double slope_sum = 0.0;
  std::size_t slope_count = 0, folded = 0, fold_j = 0;
  double foam_sum = 0.0, whitecap_sum = 0.0;
  const double wind_dir = config.sea.wind_sea.direction_rad;
  const double cos_w = std::cos(wind_dir), sin_w = std::sin(wind_dir);
  double up_sum = 0.0, cross_sum = 0.0;  // Σ over cascades of each one's area-weighted mean
  double min_j = std::numeric_limits<double>::infinity();
  double max_imag = 0.0;
  for (int s = 0; s < seeds; ++s) {
    SimulationConfig c = config;
    c.seed = config.seed + static_cast<std::uint64_t>(s);
    Result<std::unique_ptr<Simulator>> sim_result = make_simulator(c, "cpu", runner);
    if (!sim_result.ok()) return sim_result.status();
    Simulator& sim = *sim_result.value();
    sim.step(time_s);
    const CascadeFrame& f = sim.frame().cascades.front();
    double seed_sum = 0.0, seed_sum2 = 0.0;
    for (std::size_t i = 0; i < texels; ++i) {
      const double h = f.displacement[3 * i + 1];
      const double h2 = h * h;
      seed_sum += h;
      seed_sum2 += h2;
      s3 += h2 * h;
      s4 += h2 * h2;
      const double nx = f.normal[3 * i], ny = f.normal[3 * i + 1], nz = f.normal[3 * i + 2];
      if (ny > 0.0) {
        slope_sum += (nx * nx + nz * nz) / (ny * ny);
        ++slope_count;
      } else {
        ++folded;
      }
      const double j = f.jacobian[i];
      min_j = std::min(min_j, j);
      if (j < 0.0) ++fold_j;
      foam_sum += f.foam[i];
    }
    const double count = static_cast<double>(texels);
    const double seed_mean = seed_sum / count;
    variance_sum += std::max(0.0, seed_sum2 / count - seed_mean * seed_mean);
    s1 += seed_sum;
    s2 += seed_sum2;

    const std::vector<double>& weights = sim.plan().foam().weights;
    double weighted = 0.0, united = 1.0;
    for (std::size_t k = 0; k < sim.frame().cascades.size(); ++k) {
      const LargeVector<float>& foam = sim.frame().cascades[k].foam;
      double sum = 0.0;
      for (float v : foam) sum += v;
      const double mean = sum / static_cast<double>(foam.size());
      if (!weights.empty()) weighted += weights[k] * mean;
      united *= 1.0 - mean / (1.0 + 0.6 * static_cast<double>(k));
    }
    whitecap_sum += weights.empty() ? 1.0 - united : weighted;

    for (const CascadeFrame& cascade : sim.frame().cascades) {
      double up = 0.0, cross = 0.0, area = 0.0;
      for (std::size_t i = 0; i < texels; ++i) {
        const double ny = cascade.normal[3 * i + 1];
        const double w = std::max(static_cast<double>(cascade.jacobian[i]), 0.0);
        if (ny <= 0.0 || w == 0.0) continue;
        const double sx = -cascade.normal[3 * i] / ny, sz = -cascade.normal[3 * i + 2] / ny;
        const double su = sx * cos_w + sz * sin_w, sc = sz * cos_w - sx * sin_w;
        up += w * su * su;
        cross += w * sc * sc;
        area += w;
      }
      if (area > 0.0) {
        up_sum += up / area;
        cross_sum += cross / area;
      }
    }

    // Loop error, first seed: the surface at t + T against the one at t.
    if (s == 0 && config.loop_period_s > 0.0 && out.hs_spectrum_m > 0.0) {
      std::vector<float> first(texels);
      for (std::size_t i = 0; i < texels; ++i) first[i] = f.displacement[3 * i + 1];
      sim.step(time_s + config.loop_period_s);
      const CascadeFrame& later = sim.frame().cascades.front();
      double largest = 0.0;
      for (std::size_t i = 0; i < texels; ++i) {
        largest = std::max(largest, std::abs(static_cast<double>(later.displacement[3 * i + 1]) -
                                             static_cast<double>(first[i])));
      }
      out.loop_error_rel_hs = largest / out.hs_spectrum_m;
    }

    // Imaginary residue of the height transform, independent of the backend: cascade 0's
    // spectrum exactly as the backends generate it.
    Result<InitialSpectrum> spectrum =
        make_initial_spectrum(sim.plan().sea(), sim.plan().cascades().front().spectrum);
    if (!spectrum.ok()) return spectrum.status();
    max_imag =
        std::max(max_imag, max_imaginary_height(spectrum.value(), time_s, config.loop_period_s,
                                                plan.value(), *runner));
  }

  const double total = static_cast<double>(texels) * seeds;
  out.hs_measured_m = 4.0 * std::sqrt(variance_sum / seeds);
  const double mean = s1 / total;
  const double e2 = s2 / total, e3 = s3 / total, e4 = s4 / total;
  const double m2 = e2 - mean * mean;
  const double m3 = e3 - 3.0 * mean * e2 + 2.0 * mean * mean * mean;
  const double m4 = e4 - 4.0 * mean * e3 + 6.0 * mean * mean * e2 - 3.0 * mean * mean * mean * mean;
  out.mean_height_m = mean;
  if (m2 > 0.0) {
    out.height_skewness = m3 / (m2 * std::sqrt(m2));
    out.height_kurtosis = m4 / (m2 * m2);
  }
  out.mean_square_slope = slope_count > 0 ? slope_sum / static_cast<double>(slope_count) : 0.0;
  out.folded_fraction = static_cast<double>(folded) / total;
  out.resolved_slope_variance = {.upwind = up_sum / seeds, .crosswind = cross_sum / seeds};
  out.min_jacobian = min_j;
  out.foam_coverage = static_cast<double>(fold_j) / total;
  out.mean_foam = foam_sum / total;
  out.whitecap_coverage = whitecap_sum / seeds;
  if (out.hs_spectrum_m > 0.0) out.max_imaginary_rel_hs = max_imag / out.hs_spectrum_m;
  return out;
}

}  // namespace ocean
