#include "python_interrupt.h"

#include <exception>

namespace gmcc::python {
namespace {

extern "C" void on_sigint(int) { gmcc::interrupt_requested.store(true, std::memory_order_relaxed); }

}  // namespace

unsigned long& main_thread_ident() {
  static unsigned long ident = 0;
  return ident;
}

InterruptibleRelease::InterruptibleRelease() {
  if (PyThread_get_thread_ident() == main_thread_ident()) {
    gmcc::interrupt_requested.store(false);
    struct sigaction a {};
    a.sa_handler = on_sigint;
    sigemptyset(&a.sa_mask);
    installed_ = sigaction(SIGINT, &a, &saved_) == 0;
  }
  state_ = PyEval_SaveThread();
}

InterruptibleRelease::~InterruptibleRelease() {
  PyEval_RestoreThread(state_);
  if (installed_) {
    sigaction(SIGINT, &saved_, nullptr);
    // Seen by no check (or the call is ending with Interrupted, which the translator raises):
    // hand a pending Ctrl-C back to Python.
    if (gmcc::interrupt_requested.exchange(false) && std::uncaught_exceptions() == 0) PyErr_SetInterrupt();
  }
}

void register_interrupt(py::module_& m) {
  main_thread_ident() = py::module_::import("threading").attr("main_thread")().attr("ident").cast<unsigned long>();
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const gmcc::Interrupted&) {
      gmcc::interrupt_requested.store(false);
      PyErr_SetNone(PyExc_KeyboardInterrupt);
    }
  });
  (void)m;
}

}  // namespace gmcc::python
