// Small numerical helpers for the spectrum tests.
#pragma once

#include <cmath>

namespace ocean_test {

/// Composite Simpson rule of f over [a, b] with n (even) intervals.
template <typename F>
double simpson(F&& f, double a, double b, int n) {
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 == 1 ? 4.0 : 2.0) * f(a + h * i);
  return sum * h / 3.0;
}

inline double relative_error(double actual, double expected) {
  return std::abs(actual - expected) / std::abs(expected);
}

}  // namespace ocean_test
