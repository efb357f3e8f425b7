// SIGINT, SIGTERM and SIGHUP as the cancellation flag of a long call (bake, merge) made from the
// main thread, so that it stops between two files and cleans up as `ocean bake` does (no
// temporary left, a manifest saying "complete": false) instead of running on with the GIL
// released (SIGINT) or dying in the middle of a file (SIGTERM, SIGHUP).
//
// After the call, with the previous handlers back, the first signal received is raised:
//   - SIGINT with Python's default handler: KeyboardInterrupt, with the call's message
//     ("bake interrupted: SIGINT; bake cancelled after 3 of 100 frames; ...").
//   - a signal with a handler of the program's own (signal.signal): that handler runs, as the
//     signal had arrived just then, and what it raises is raised;
//   - otherwise (the default action, or a handler that returned): KeyboardInterrupt for SIGINT,
//     SystemExit(128 + the signal) for SIGTERM (143) and SIGHUP (129), the call's message as
//     its note: uncaught, the interpreter exits with the shell's status for a job a signal
//     ended (`ocean bake`'s on SIGTERM), after finally blocks and atexit handlers have run.
// A signal that was ignored (SIG_IGN, as under nohup) stays ignored. A second signal changes
// nothing: the call is already stopping. Off the main thread nothing is installed: the call runs
// to its end and signals keep Python's handling (they reach the main thread).
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <csignal>
#include <iterator>
#include <string_view>

#include "ocean/core.hpp"

namespace ocean::python {

/// Installs the handlers for its lifetime (see the top of the file). Construct and finish() with
/// the GIL held; run the call without it. One at a time per process (the main thread's).
class StopOnSignals {
 public:
  /// Raises a signal Python already has pending (a Ctrl-C just before the call) before
  /// installing anything; then installs the handlers when on the main thread of the main
  /// interpreter.
  StopOnSignals();
  /// Restores the previous handlers if finish() has not.
  ~StopOnSignals();
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

  /// The flag the handlers set (BakeParams::cancel, MergeParams::cancel); null when no handler
  /// was installed, so that a call off the main thread is never cancelled by another's signal.
  [[nodiscard]] const std::atomic<bool>* flag() const;

  /// After the call returned `status`: restores the previous handlers, then raises for the
  /// first signal received, as the top of the file says, naming `what` ("bake", "merge");
  /// without a signal, raises `status` when it is not ok.
  void finish(const Status& status, std::string_view what);

 private:
  void restore() noexcept;

  static constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
  bool installed_ = false;                // on the main thread: the flag is ours
  bool replaced_[std::size(kSignals)]{};  // our handler is in place of old_[i]
  struct sigaction old_[std::size(kSignals)]{};
};

}  // namespace ocean::python
