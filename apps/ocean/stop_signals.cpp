// SIGINT/SIGTERM/SIGHUP as a cancellation flag (see stop_signals.hpp).
#include "stop_signals.hpp"

#include <iostream>

namespace ocean::cli {
namespace {

static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "the signal handler's stores must be lock-free to be async-signal-safe");

std::atomic<bool> g_stop{false};
std::atomic<int> g_signal{0};

extern "C" void on_stop_signal(int signal) {
  int none = 0;  // the first signal is the one reported
  g_signal.compare_exchange_strong(none, signal, std::memory_order_relaxed);
  g_stop.store(true, std::memory_order_relaxed);
}

// Installs `handler` for `signal`, saving the old action in `old`. A signal the parent chose to
// ignore stays ignored (a shell starts background jobs with SIGINT ignored, so that Ctrl-C
// reaches only the foreground job).
void install(int signal, void (*handler)(int), int flags, struct sigaction& old) {
  if (::sigaction(signal, nullptr, &old) != 0 || old.sa_handler == SIG_IGN) return;
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  action.sa_flags = flags;
  (void)::sigaction(signal, &action, nullptr);
}

}  // namespace

StopSignals::StopSignals() {
  g_stop.store(false);
  g_signal.store(0);
  install(SIGINT, on_stop_signal, SA_RESTART | SA_RESETHAND, old_int_);
  install(SIGTERM, on_stop_signal, SA_RESTART | SA_RESETHAND, old_term_);
  install(SIGHUP, on_stop_signal, SA_RESTART | SA_RESETHAND, old_hup_);
  install(SIGXFSZ, SIG_IGN, 0, old_xfsz_);
}

StopSignals::~StopSignals() {
  (void)::sigaction(SIGXFSZ, &old_xfsz_, nullptr);
  (void)::sigaction(SIGHUP, &old_hup_, nullptr);
  (void)::sigaction(SIGTERM, &old_term_, nullptr);
  (void)::sigaction(SIGINT, &old_int_, nullptr);
}

const std::atomic<bool>* StopSignals::flag() const { return &g_stop; }

int StopSignals::received() const { return g_signal.load(); }

std::string signal_name(int signal) {
  switch (signal) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "signal " + std::to_string(signal);
  }
}

int report_interrupted(const StopSignals& stop, std::string_view what, std::string_view detail) {
  std::cerr << "ocean: error: " << what << " interrupted: " << signal_name(stop.received()) << "; "
            << detail << "\n";
  return 128 + stop.received();
}

}  // namespace ocean::cli
