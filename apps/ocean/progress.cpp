// Progress bar on stderr (see progress.hpp).
#include "progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace ocean::cli {

Progress::Progress(std::string label, long long total)
    : label_(std::move(label)),
      total_(total),
      terminal_(::isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

void Progress::update(long long done) {
  done_ = done;
  const auto now = std::chrono::steady_clock::now();
  if (terminal_ && (now - last_draw_ > std::chrono::milliseconds(50) || done_ == total_)) {
    last_draw_ = now;
    draw();
  }
}

void Progress::draw() {
  constexpr int kWidth = 30;
  const int filled = total_ > 0 ? static_cast<int>(kWidth * done_ / total_) : kWidth;
  std::string bar(static_cast<std::size_t>(filled), '=');
  if (filled < kWidth) bar += '>';
  bar.resize(kWidth, ' ');
  std::fprintf(stderr, "\r%s [%s] %lld/%lld", label_.c_str(), bar.c_str(), done_, total_);
  std::fflush(stderr);
}

void Progress::finish() {
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (terminal_) {
    draw();
    std::fputc('\n', stderr);
  }
  std::fprintf(stderr, "%s: %lld/%lld done in %.2f s (%.1f per second)\n", label_.c_str(), done_,
               total_, seconds, seconds > 0 ? static_cast<double>(done_) / seconds : 0.0);
}

void Progress::end_line() {
  if (terminal_ && done_ > 0) std::fputc('\n', stderr);
}

}  // namespace ocean::cli
