// SIGINT, SIGTERM and SIGHUP as a cancellation flag (see signals.hpp).
#include "signals.hpp"

#include <string>

#include "errors.hpp"

namespace py = pybind11;

namespace ocean::python {
namespace {

static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "the signal handler's stores must be lock-free to be async-signal-safe");

std::atomic<bool> g_stop{false};
std::atomic<int> g_signal{0};

extern "C" void on_stop_signal(int signal) {
  int none = 0;  // the first signal is the one raised
  g_signal.compare_exchange_strong(none, signal, std::memory_order_relaxed);
  g_stop.store(true, std::memory_order_relaxed);
}

// Python runs signal handlers on the main thread of the main interpreter only, and only there
// may they be changed (signal.signal raises ValueError elsewhere).
bool on_main_thread() {
  if (PyInterpreterState_Get() != PyInterpreterState_Main()) return false;
  const py::module_ threading = py::module_::import("threading");
  return threading.attr("current_thread")().is(threading.attr("main_thread")());
}

std::string signal_name(int signal) {
  switch (signal) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "signal " + std::to_string(signal);
  }
}

[[noreturn]] void raise_system_exit(int code, const std::string& note) {
  const auto exit =
      py::reinterpret_steal<py::object>(PyObject_CallFunction(PyExc_SystemExit, "i", code));
  if (!exit) throw py::error_already_set();
  if (py::hasattr(exit, "add_note")) exit.attr("add_note")(note);  // Python 3.11
  PyErr_SetObject(PyExc_SystemExit, exit.ptr());
  throw py::error_already_set();
}

}  // namespace

StopOnSignals::StopOnSignals() {
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  if (!on_main_thread()) return;
  installed_ = true;
  g_stop.store(false);
  g_signal.store(0);
  for (std::size_t i = 0; i < std::size(kSignals); ++i) {
    // A signal the process ignores stays ignored (nohup, a shell's background job).
    if (::sigaction(kSignals[i], nullptr, &old_[i]) != 0 || old_[i].sa_handler == SIG_IGN) continue;
    struct sigaction action {};
    action.sa_handler = on_stop_signal;
    sigemptyset(&action.sa_mask);
    // SA_RESTART: a write the signal interrupts completes, and the call stops after it. No
    // SA_RESETHAND (unlike the tool): a second Ctrl-C must not kill an interactive session.
    action.sa_flags = SA_RESTART;
    replaced_[i] = ::sigaction(kSignals[i], &action, nullptr) == 0;
  }
}

StopOnSignals::~StopOnSignals() { restore(); }

void StopOnSignals::restore() noexcept {
  for (std::size_t i = 0; i < std::size(kSignals); ++i) {
    if (replaced_[i]) (void)::sigaction(kSignals[i], &old_[i], nullptr);
    replaced_[i] = false;
  }
}

const std::atomic<bool>* StopOnSignals::flag() const { return installed_ ? &g_stop : nullptr; }

void StopOnSignals::finish(const Status& status, std::string_view what) {
  restore();
  const int signal = installed_ ? g_signal.load() : 0;
  if (signal == 0) {
    check(status);
    return;
  }
  std::string message = std::string(what) + " interrupted: " + signal_name(signal);
  message += status.ok() ? " as it completed" : "; " + status.message();

  const py::module_ signal_module = py::module_::import("signal");
  const py::object handler = signal_module.attr("getsignal")(signal);
  const bool default_sigint =
      signal == SIGINT && handler.is(signal_module.attr("default_int_handler"));
#if PY_VERSION_HEX >= 0x030A0000  // PyErr_SetInterruptEx: Python 3.10
  if (!default_sigint && PyCallable_Check(handler.ptr()) != 0) {
    // The program's own handler gets the signal, as it would have without the call.
    if (PyErr_SetInterruptEx(signal) == 0 && PyErr_CheckSignals() != 0)
      throw py::error_already_set();
  }
#else
  (void)default_sigint;
#endif
  if (signal == SIGINT) {
    PyErr_SetString(PyExc_KeyboardInterrupt, message.c_str());
    throw py::error_already_set();
  }
  raise_system_exit(128 + signal, message);
}

}  // namespace ocean::python
