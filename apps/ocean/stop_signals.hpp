// SIGINT, SIGTERM and SIGHUP turned into a cancellation flag while a long job writes files, so
// that it stops between two files and cleans up (no temporary left, a manifest saying what was
// written) instead of dying in the middle; SIGXFSZ ignored, so that a write past the file size
// limit fails with EFBIG and is reported like a full disk. SIGHUP (the terminal closed: a logout,
// a lost ssh connection) would otherwise end the job as abruptly as an unhandled Ctrl-C.
#pragma once

#include <atomic>
#include <csignal>
#include <string>
#include <string_view>

namespace ocean::cli {

/// Installs the handlers for its lifetime and restores the previous ones when destroyed; a
/// signal already ignored when it starts (SIGINT of a shell's background job, SIGHUP under
/// nohup) stays ignored. The
/// handlers only store to lock-free atomics (async-signal-safe). Each handler resets itself on
/// its first signal (SA_RESETHAND), so a second Ctrl-C kills at once; system calls interrupted
/// by a signal restart (SA_RESTART), so an atomic write in flight completes. One instance at a
/// time per process; not thread-safe to construct.
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  /// The flag the handlers set; what the job polls (ocean::bake::BakeParams::cancel).
  [[nodiscard]] const std::atomic<bool>* flag() const;
  /// The first signal that arrived (SIGINT, SIGTERM or SIGHUP), 0 if none.
  [[nodiscard]] int received() const;

 private:
  struct sigaction old_int_ {
  }, old_term_{}, old_hup_{}, old_xfsz_{};
};

/// "SIGINT", "SIGTERM", "SIGHUP", or "signal <n>" for others.
std::string signal_name(int signal);

/// Reports a job that `stop` interrupted: "ocean: error: <what> interrupted: SIGINT; <detail>" on
/// stderr, and returns the exit status 128 + the signal (the shell's convention for a job ended
/// by one). Call only when stop.received() != 0.
int report_interrupted(const StopSignals& stop, std::string_view what, std::string_view detail);

}  // namespace ocean::cli
