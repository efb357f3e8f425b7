// Axis logic for the plot module: data ranges with padding, 1-2-5 and decade ticks, tick labels.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "plot_internal.hpp"

namespace ocean::plot::detail {

double nice_step(double lo, double hi, int max_ticks) {
  const double span = hi - lo;
  if (!(span > 0.0) || !std::isfinite(span)) return 1.0;
  const int n = std::max(max_ticks, 2);
  const double raw = span / static_cast<double>(n - 1) * (1.0 - 1e-9);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  // The smallest 1-2-5 step giving at most n ticks; but rather one step too many ticks than a
  // single tick, which would leave the axis unreadable.
  double previous = 0.0;
  for (const double m : {1.0, 2.0, 5.0, 10.0}) {
    const double step = m * mag;
    const double count = std::floor(hi / step + 1e-9) - std::ceil(lo / step - 1e-9) + 1.0;
    if (count <= static_cast<double>(n)) return count < 2.0 && previous > 0.0 ? previous : step;
    previous = step;
  }
  return 10.0 * mag;
}

std::vector<double> nice_linear_ticks(double lo, double hi, int max_ticks) {
  std::vector<double> ticks;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return ticks;
  const double step = nice_step(lo, hi, max_ticks);
  const double first = std::ceil(lo / step - 1e-9), last = std::floor(hi / step + 1e-9);
  if (!(last - first < 1000.0) || !(last >= first)) return ticks;  // precision exhausted
  const auto count = static_cast<int>(last - first) + 1;
  for (int i = 0; i < count; ++i) {
    double v = (first + i) * step;
    if (std::fabs(v) < step * 1e-9) v = 0.0;  // no "-0" or 5.55e-17
    ticks.push_back(v);
  }
  return ticks;
}

LogTicks log_ticks(double lo, double hi, int max_major) {
  LogTicks t;
  if (!(lo > 0.0) || !(hi > lo) || !std::isfinite(hi)) return t;
  const double eps = 1e-9;
  const int d0 = static_cast<int>(std::ceil(std::log10(lo) - eps));
  const int d1 = static_cast<int>(std::floor(std::log10(hi) + eps));
  const auto in_range = [&](double v) { return v >= lo * (1.0 - eps) && v <= hi * (1.0 + eps); };
  const int first_decade = d0 - 1;  // minor ticks of the partial decade below d0 count too
  const int budget = std::max(max_major, 2);
  if (d1 - d0 + 1 >= 2) {
    // Label every `every`-th decade: 1, 2, 3, 5, 10, 20, 25, 50, ... aligned on multiples of
    // it (10^-6, 10^-3, 10^0, ...); unaligned if alignment would leave a single label.
    const int count = d1 - d0 + 1;
    int every = 0;
    const auto aligned = [&](int d) { return ((d % every) + every) % every == 0; };
    const auto labels = [&] {
      int n = 0;
      for (int d = d0; d <= d1; ++d) n += aligned(d) ? 1 : 0;
      return n;
    };
    for (const int e : {1, 2, 3, 5, 10, 20, 25, 50, 100}) {
      every = e;
      if (labels() <= budget) break;
    }
    const bool use_alignment = labels() >= 2 && labels() <= budget;
    if (!use_alignment) every = (count + budget - 1) / budget;
    for (int d = d0; d <= d1; ++d) {
      const double v = std::pow(10.0, d);
      const bool major = use_alignment ? aligned(d) : (d - d0) % every == 0;
      (major ? t.major : t.minor).push_back(v);
    }
    if (every == 1) {
      for (int d = first_decade; d <= d1; ++d) {
        for (int m = 2; m <= 9; ++m) {
          const double v = m * std::pow(10.0, d);
          if (in_range(v)) t.minor.push_back(v);
        }
      }
    }
    std::sort(t.minor.begin(), t.minor.end());
    return t;
  }
  // Narrow range: label 1-2-5 x 10^k, or every mantissa, or fall back to linear ticks.
  const auto pick = [&](const std::vector<int>& mantissas) {
    LogTicks p;
    p.kind = LogTicks::Kind::mantissas;
    for (int d = first_decade; d <= d1 + 1; ++d) {
      for (int m = 1; m <= 9; ++m) {
        const double v = m * std::pow(10.0, d);
        if (!in_range(v)) continue;
        const bool major = std::find(mantissas.begin(), mantissas.end(), m) != mantissas.end();
        (major ? p.major : p.minor).push_back(v);
      }
    }
    return p;
  };
  const LogTicks one_two_five = pick({1, 2, 5});
  const LogTicks all = pick({1, 2, 3, 4, 5, 6, 7, 8, 9});
  const auto n125 = static_cast<int>(one_two_five.major.size());
  const auto nall = static_cast<int>(all.major.size());
  if (n125 >= 3 && n125 <= budget) return one_two_five;
  if (nall >= 2 && nall <= budget) return all;
  if (n125 >= 2) return one_two_five;
  t.major = nice_linear_ticks(lo, hi, max_major);
  t.kind = LogTicks::Kind::linear;
  t.linear_step = nice_step(lo, hi, max_major);
  return t;
}

namespace {
// "1.5e-05" -> "1.5e-5", "2e+06" -> "2e6"; strings without an exponent pass through.
std::string compact_exponent(std::string s) {
  const std::size_t e = s.find('e');
  if (e == std::string::npos) return s;
  std::string mant = s.substr(0, e), exp = s.substr(e + 1), sign;
  if (!exp.empty() && (exp[0] == '+' || exp[0] == '-')) {
    if (exp[0] == '-') sign = "-";
    exp.erase(0, 1);
  }
  while (exp.size() > 1 && exp[0] == '0') exp.erase(0, 1);
  return mant + "e" + sign + exp;
}
}  // namespace

std::string compact_number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", value);
  return compact_exponent(buf);
}

std::string format_linear_tick(double value, double step) {
  step = std::fabs(step);
  if (std::fabs(value) < step * 1e-6) return "0";
  char buf[64];
  if (step >= 1e5 || step < 1e-4) {
    // Scientific, with only as many mantissa digits as the step needs.
    const int decimals =
        std::clamp(static_cast<int>(std::floor(std::log10(std::fabs(value)) + 1e-9)) -
                       static_cast<int>(std::floor(std::log10(step) + 1e-9)),
                   0, 6);
    std::snprintf(buf, sizeof buf, "%.*e", decimals, value);
    std::string s = buf;
    const std::size_t e = s.find('e');
    std::string mant = s.substr(0, e);
    if (mant.find('.') != std::string::npos) {
      while (mant.back() == '0') mant.pop_back();
      if (mant.back() == '.') mant.pop_back();
    }
    return compact_exponent(mant + s.substr(e));
  }
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  std::string s = buf;
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  return s == "-0" ? "0" : s;
}

std::string format_decade(double value) {
  const auto k = static_cast<int>(std::lround(std::log10(value)));
  return "10^{" + std::to_string(k) + "}";
}

Result<AxisRange> compute_range(const std::vector<double>& values, bool log,
                                const std::optional<double>& lo, const std::optional<double>& hi,
                                const std::string& what) {
  for (const auto& [lim, name] : {std::pair{lo, "_min"}, std::pair{hi, "_max"}}) {
    if (!lim) continue;
    if (!std::isfinite(*lim)) {
      return invalid_argument(what + name + " = " + compact_number(*lim) + " must be finite");
    }
    if (log && !(*lim > 0.0)) {
      return invalid_argument(what + name + " = " + compact_number(*lim) +
                              " is out of range: must be > 0 on a log axis");
    }
  }
  if (lo && hi && !(*lo < *hi)) {
    return invalid_argument(what + "_min = " + compact_number(*lo) + " must be < " + what +
                            "_max = " + compact_number(*hi));
  }
  AxisRange r;
  r.log = log;
  if (lo && hi) {
    if (!(*hi - *lo > 1e-12 * std::max(std::fabs(*lo), std::fabs(*hi)))) {
      return invalid_argument(what + "_min = " + compact_number(*lo) + " and " + what +
                              "_max = " + compact_number(*hi) + " are too close to tell apart");
    }
    r.lo = *lo;
    r.hi = *hi;
    return r;
  }
  // Work in log10 space on log axes, so padding is multiplicative.
  const auto fwd = [&](double v) { return log ? std::log10(v) : v; };
  const auto inv = [&](double v) { return log ? std::pow(10.0, v) : v; };
  if (values.empty() && log && !lo && !hi) {
    return invalid_argument(what +
                            " axis is logarithmic but has no positive finite data: give it "
                            "values > 0 or set " +
                            what + "_min and " + what + "_max");
  }
  // Data extent, with explicit limits taking the place of the data on their side; padding is
  // applied only to the sides that were not given, relative to the resulting span.
  double dlo = 0.0, dhi = 1.0;
  if (!values.empty()) {
    const auto [mn, mx] = std::minmax_element(values.begin(), values.end());
    dlo = fwd(*mn);
    dhi = fwd(*mx);
  } else if (log) {
    dlo = lo ? fwd(*lo) : fwd(*hi) - 1.0;
    dhi = dlo + 1.0;
  }
  if (lo) dlo = fwd(*lo);
  if (hi) dhi = fwd(*hi);
  if (dhi > dlo) {
    const double pad = 0.04 * (dhi - dlo);
    if (!lo) dlo -= pad;
    if (!hi) dhi += pad;
  } else if (lo) {  // all data at or below the explicit minimum
    dhi = dlo + (log ? 1.0 : (dlo == 0.0 ? 1.0 : 0.2 * std::fabs(dlo)));
  } else if (hi) {  // all data at or above the explicit maximum
    dlo = dhi - (log ? 1.0 : (dhi == 0.0 ? 1.0 : 0.2 * std::fabs(dhi)));
  } else {  // a single distinct value
    const double half = log ? 0.5 : (dlo == 0.0 ? 1.0 : 0.1 * std::fabs(dlo));
    dlo -= half;
    dhi += half;
  }
  r.lo = inv(dlo);
  r.hi = inv(dhi);
  if (!std::isfinite(r.lo) || !std::isfinite(r.hi) || !(r.hi > r.lo) ||
      !(r.hi - r.lo > 1e-12 * std::max(std::fabs(r.lo), std::fabs(r.hi)))) {
    return invalid_argument(what + " axis range cannot be shown: values too large or too close");
  }
  return r;
}

}  // namespace ocean::plot::detail
