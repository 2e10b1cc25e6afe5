#pragma once
/// \file interrupt.h
/// Stopping a long computation early at a caller's request (Ctrl-C in the Python module,
/// docs/python.md "Interrupting"): a caller sets the flag from another thread or a signal
/// handler (a lock-free atomic store, async-signal-safe); long loops call check_interrupt() at
/// points where unwinding leaves nothing half-made (every 2^16 Monte Carlo samples, every scene
/// of an experiment, every image of a benchmark), which throws Interrupted. Interrupted derives
/// from no standard exception, so the `catch (const std::exception&)` of input and option
/// handling does not swallow it. Nothing sets the flag unless a front end does.

#include <atomic>

namespace gmcc {

/// Thrown by check_interrupt once an interrupt is requested.
struct Interrupted {};

/// The request, process-wide. Lock-free on every platform gmcc builds for.
inline std::atomic<bool> interrupt_requested{false};

/// Throw Interrupted if an interrupt was requested. O(1): one relaxed atomic load.
inline void check_interrupt() {
  if (interrupt_requested.load(std::memory_order_relaxed)) throw Interrupted{};
}

}  // namespace gmcc
