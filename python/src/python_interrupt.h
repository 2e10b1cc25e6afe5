#pragma once
// Ctrl-C during a long library call (docs/python.md "Interrupting"; numerics/interrupt.h).
// InterruptibleRelease releases the GIL like py::gil_scoped_release and, on Python's main
// thread, replaces Python's SIGINT handler for the call by one that asks the library to stop
// (an atomic store, async-signal-safe). The library's long loops then throw gmcc::Interrupted at
// their next check (within 2^16 Monte Carlo samples, one scene, one image), which the module's
// translator raises as KeyboardInterrupt. A Ctrl-C that no check saw is handed back to Python
// when the call ends (PyErr_SetInterrupt), so it is never lost. Python's handler is restored.

#include <gmcc/numerics/interrupt.h>

#include <pybind11/pybind11.h>

#include <csignal>

namespace gmcc::python {

namespace py = pybind11;

/// Python's main thread, recorded when the module is imported (signals reach only it).
unsigned long& main_thread_ident();

class InterruptibleRelease {
 public:
  InterruptibleRelease();
  ~InterruptibleRelease();
  InterruptibleRelease(const InterruptibleRelease&) = delete;
  InterruptibleRelease& operator=(const InterruptibleRelease&) = delete;

 private:
  bool installed_ = false;
  struct sigaction saved_ {};
  PyThreadState* state_ = nullptr;
};

/// Register the translation of gmcc::Interrupted to KeyboardInterrupt and record the main
/// thread (called once from the module's initialisation).
void register_interrupt(py::module_& m);

}  // namespace gmcc::python
