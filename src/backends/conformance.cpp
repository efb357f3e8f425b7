// Backend conformance: bounds, comparison and cases (see ocean/conformance.hpp).
#include "ocean/conformance.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "ocean/half.hpp"

namespace ocean::conformance {

namespace {

// Largest |a − b| over the elements first, first + stride, … of both arrays.
double max_abs_diff(std::span<const float> a, std::span<const float> b, std::size_t first = 0,
                    std::size_t stride = 1) {
  double m = 0.0;
  for (std::size_t i = first; i < a.size(); i += stride)
    m = std::max(m, std::abs(static_cast<double>(a[i]) - static_cast<double>(b[i])));
  return m;
}

}  // namespace

const Bounds& bounds_for(std::string_view backend) {
  return backend == "cpu" ? kCpuBounds : kDeviceBounds;
}

void Errors::merge(const Errors& e) {
  height_rel_hs = std::max(height_rel_hs, e.height_rel_hs);
  displacement_rel_hs = std::max(displacement_rel_hs, e.displacement_rel_hs);
  displacement_half_rel_bound =
      std::max(displacement_half_rel_bound, e.displacement_half_rel_bound);
  normal = std::max(normal, e.normal);
  jacobian = std::max(jacobian, e.jacobian);
  foam = std::max(foam, e.foam);
  packed_lsb = std::max(packed_lsb, e.packed_lsb);
  packed_fraction = std::max(packed_fraction, e.packed_fraction);
}

bool Errors::pass(const Bounds& b) const {
  return height_rel_hs <= b.height_rel_hs && displacement_rel_hs <= b.displacement_rel_hs &&
         displacement_half_rel_bound <= b.displacement_half_rel_bound && normal <= b.normal &&
         jacobian <= b.jacobian && foam <= b.foam && packed_lsb <= b.packed_lsb &&
         packed_fraction <= b.packed_fraction;
}

double significant_height(const Frame& f) {
  double var = 0.0;
  for (const CascadeFrame& c : f.cascades) {
    double sum = 0.0, sum2 = 0.0;
    const std::size_t texels = c.jacobian.size();
    for (std::size_t i = 0; i < texels; ++i) {
      const double h = c.displacement[3 * i + 1];
      sum += h, sum2 += h * h;
    }
    const double mean = sum / static_cast<double>(texels);
    var += sum2 / static_cast<double>(texels) - mean * mean;
  }
  return 4.0 * std::sqrt(var);
}

Errors compare(const Frame& ref, const Frame& got, const Bounds& bounds) {
  Errors e;
  const double hs = significant_height(ref);
  std::size_t packed_total = 0, packed_differ = 0;
  for (std::size_t c = 0; c < ref.cascades.size(); ++c) {
    const CascadeFrame& r = ref.cascades[c];
    const CascadeFrame& g = got.cascades[c];
    e.height_rel_hs =
        std::max(e.height_rel_hs, max_abs_diff(r.displacement, g.displacement, 1, 3) / hs);
    e.displacement_rel_hs =
        std::max(e.displacement_rel_hs, max_abs_diff(r.displacement, g.displacement) / hs);
    e.normal = std::max(e.normal, max_abs_diff(r.normal, g.normal));
    e.jacobian = std::max(e.jacobian, max_abs_diff(r.jacobian, g.jacobian));
    e.foam = std::max(e.foam, max_abs_diff(r.foam, g.foam));
    for (std::size_t i = 0; i < r.displacement_half.size(); ++i) {
      const double a = half_to_float(r.displacement_half[i]);
      const double b = half_to_float(g.displacement_half[i]);
      const double allowed = std::ldexp(std::abs(a), -10) + bounds.displacement_rel_hs * hs;
      e.displacement_half_rel_bound =
          std::max(e.displacement_half_rel_bound, std::abs(a - b) / allowed);
    }
    for (std::size_t i = 0; i < r.packed_mips.size(); ++i) {
      int worst = 0;
      for (int shift = 0; shift < 32; shift += 8) {
        const int a = static_cast<int>((r.packed_mips[i] >> shift) & 0xffu);
        const int b = static_cast<int>((g.packed_mips[i] >> shift) & 0xffu);
        worst = std::max(worst, std::abs(a - b));
      }
      e.packed_lsb = std::max(e.packed_lsb, worst);
      packed_differ += worst > 0 ? 1 : 0;
    }
    packed_total += r.packed_mips.size();
  }
  if (packed_total > 0) {
    e.packed_fraction = static_cast<double>(packed_differ) / static_cast<double>(packed_total);
  }
  return e;
}

const std::vector<Case>& cases() {
  using M = SpectrumModel;
  using N = NormalMethod;
  const double day3 = 3 * 86400.0 + 17.25;  // exact looping phase long after the start
  static const std::vector<Case> list = {
      {"64_phillips_3cascades_central",
       64,
       {800.0, 190.0, 47.0},
       M::phillips,
       N::central_difference,
       200.0,
       {0.0, 0.5, 1.0}},
      {"256_jonswap_2cascades_central",
       256,
       {1000.0, 233.0},
       M::jonswap,
       N::central_difference,
       200.0,
       {day3, day3 + 1.0 / 30}},
      {"256_jonswap_2cascades_analytic",
       256,
       {1000.0, 233.0},
       M::jonswap,
       N::analytic,
       200.0,
       {3 * 86400.0, 3 * 86400.0 + 1.0 / 30}},
      {"256_tma_3cascades_sobel", 256, {600.0, 140.0, 33.0}, M::tma, N::sobel, 200.0, {2.0, 2.1}},
      {"128_jonswap_2cascades_analytic_noloop",
       128,
       {500.0, 110.0},
       M::jonswap,
       N::analytic,
       0.0,
       {1000.0, 1000.05}},
      {"1024_jonswap_1cascade_central",
       1024,
       {1000.0},
       M::jonswap,
       N::central_difference,
       200.0,
       {7.5}},
  };
  return list;
}

SimulationConfig make_config(const Case& c) {
  SimulationConfig config;
  config.resolution = c.resolution;
  config.cascade_patch_sizes_m = c.patches_m;
  config.normals = c.normals;
  config.loop_period_s = c.loop_period_s;
  config.choppiness = 1.2;
  FrequencySpectrumParams& s = config.sea.wind_sea.spectrum;
  s.model = c.model;
  s.wind_speed_mps = 14.0;
  s.fetch_m = c.model == SpectrumModel::phillips ? kUnset : 80e3;
  if (c.model == SpectrumModel::tma) {
    s.depth_m = 20.0;
    config.sea.dispersion.depth_m = 20.0;
  }
  return config;
}

Result<std::vector<FrameResult>> run_case(const Case& c, Backend& reference, Backend& other,
                                          TaskRunner& runner, const Bounds& bounds) {
  const SimulationConfig config = make_config(c);
  if (Status s = reference.configure(config, runner); !s.ok()) return s;
  if (Status s = other.configure(config, runner); !s.ok()) return s;
  Frame ref, got;
  reference.allocate(ref);
  other.allocate(got);
  std::vector<FrameResult> results;
  for (const double t : c.times_s) {
    reference.step(t, ref);
    other.step(t, got);
    results.push_back(
        {.time_s = t, .other_time_s = got.time_s, .errors = compare(ref, got, bounds)});
  }
  return results;
}

}  // namespace ocean::conformance
