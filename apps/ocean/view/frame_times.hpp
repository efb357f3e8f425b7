// view/frame_times.hpp — the median of the last 60 frame times, measured on the CPU (what the
// `ocean view` panel shows: robust to the odd slow frame of a reconfiguration).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

namespace ocean::cli::view {

class FrameTimes {
 public:
  static constexpr std::size_t kWindow = 60;

  /// Adds one frame's duration, ms. Allocates nothing.
  void add(double ms) {
    times_[next_] = ms;
    next_ = (next_ + 1) % kWindow;
    count_ = std::min(count_ + 1, kWindow);
  }
  /// Median of the last min(count, 60) frames (the upper median of an even count); 0 when empty.
  [[nodiscard]] double median_ms() const {
    if (count_ == 0) return 0.0;
    std::array<double, kWindow> sorted = times_;
    const auto end = sorted.begin() + static_cast<std::ptrdiff_t>(count_);
    const auto mid = sorted.begin() + static_cast<std::ptrdiff_t>(count_ / 2);
    std::nth_element(sorted.begin(), mid, end);
    return *mid;
  }
  [[nodiscard]] std::size_t count() const { return count_; }

 private:
  std::array<double, kWindow> times_{};
  std::size_t next_ = 0, count_ = 0;
};

}  // namespace ocean::cli::view
