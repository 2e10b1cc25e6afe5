#pragma once
// The exit at a resource limit (--time-limit, --memory-limit, memory exhausted): exit status 3,
// one message saying which limit and what the run was doing, temporary files removed
// (docs/cli.md, "Files, special paths, signals and time limits"). It is reached from the
// watchdog thread or from a failed allocation in any thread, with the main thread still
// running: so no allocation, no lock waited for, and _exit rather than exit (no destructors
// racing the threads that are still at work).

#include <string>

namespace gmcc::cli {

/// Exit status at a resource limit.
inline constexpr int limit_exit_status = 3;

/// Record what the run is doing ("reading C.csv", "running the synthetic experiment"), for
/// the message. Cheap; call at each phase.
void set_activity(std::string what);

/// Write `gmcc: error: <reached>[ while <activity>]`, remove the temporary files, _exit(3).
/// `reached` reads e.g. "time limit of 5 s reached (--time-limit)".
[[noreturn]] void exit_at_limit(const char* reached) noexcept;

}  // namespace gmcc::cli
