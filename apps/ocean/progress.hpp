// A progress bar on stderr for long jobs: redrawn in place on a terminal, a single summary line
// otherwise (logs and CI stay readable).
#pragma once

#include <chrono>
#include <string>

namespace ocean::cli {

class Progress {
 public:
  Progress(std::string label, long long total);
  /// Marks `done` of `total` units complete and redraws (at most ~20 times a second).
  void update(long long done);
  /// Final line: the total and the rate.
  void finish();
  /// Ends a bar left unfinished (a newline on a terminal), so that a message printed next
  /// starts on its own line.
  void end_line();

 private:
  std::string label_;
  long long total_;
  long long done_ = 0;
  bool terminal_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  void draw();
};

}  // namespace ocean::cli
