#pragma once
// Temporary files removed on every way out of the program, signals included (docs/cli.md,
// "Files, special paths, signals and time limits"). Output is written under a temporary name
// and renamed (PendingFile); a destructor removes it on an error, but a signal (Ctrl-C,
// `kill`, a closed terminal or pipe) ends the process without destructors, and the time and
// memory limits end it from another thread. So every temporary file is also registered here,
// and the signal handlers, the watchdog and the out-of-memory path remove what is registered.
// The registry is read in signal handlers: fixed slots, atomics, no allocation, no locks.

#include <sys/types.h>

#include <string>

namespace gmcc::cli {

/// Install the handlers of the signals that end a process (SIGHUP, SIGINT, SIGQUIT, SIGTERM,
/// SIGPIPE, SIGALRM, SIGUSR1, SIGUSR2, SIGXCPU, SIGXFSZ, SIGVTALRM, SIGPROF, and SIGABRT,
/// SIGSEGV, SIGBUS, SIGFPE, SIGILL for crashes): each kills the registered child, removes the
/// registered temporary files, restores the action gmcc started with (the default, or a
/// sanitizer's reporter) and lets the signal take it, so the exit status still says which
/// signal it was. A signal ignored when gmcc starts (`nohup`) stays ignored. Call first in
/// main, before any thread is started.
void install_exit_cleanup();

/// Register a temporary file (removed on a signal or a limit). Returns the handle for
/// untrack_temporary, which frees the slot for another file. \throws std::length_error beyond 64
/// registrations alive at once or for a path longer than 4095 bytes (a bug: a run writes a
/// handful of files at a time).
int track_temporary(const std::string& path);

/// Register a family of temporary files named prefix + "0", prefix + "1", … (family_member), of
/// which family_members says how many may exist: any number of staged outputs in one slot.
/// Returns the handle for family_members and untrack_temporary. \throws as track_temporary.
int track_temporary_family(const std::string& prefix);
/// Members 0 … members − 1 of the family may exist (call before creating the next one).
void family_members(int handle, int members) noexcept;
/// The name of member k of the family `prefix`.
std::string family_member(const std::string& prefix, int k);
/// The file is renamed into place or removed: no longer remove it.
void untrack_temporary(int handle) noexcept;

/// Whether `path` is a registered temporary file of this process.
bool is_tracked(const std::string& path) noexcept;

/// Register the child process gmcc waits for (gnuplot): killed and reaped before the files
/// are removed, so it cannot write a temporary file after they are.
void track_child(pid_t pid) noexcept;

/// The child has exited and is not yet reaped. Returns false if a cleanup has taken it (and
/// will kill and reap it: the process is ending); then the caller must not reap it.
bool untrack_child(pid_t pid) noexcept;

/// fork() for a child that will exec: signals are blocked across the fork, and the child
/// restores the default actions before unblocking them, so no cleanup handler ever runs in the
/// child (it would remove the parent's files). Returns fork()'s result.
pid_t fork_for_exec() noexcept;

/// Kill and reap the registered child, remove the registered temporary files. Async-signal-safe.
void remove_temporaries() noexcept;

/// Write `text` to stderr with write(2): async-signal-safe, no allocation.
void write_stderr(const char* text) noexcept;

/// A progress line on stderr left open (`\r…` without its newline, true) or ended (false).
void set_progress_line_open(bool open) noexcept;

/// Ends an open progress line with a newline, so that an error message starts a line of its own
/// (async-signal-safe).
void end_progress_line() noexcept;

}  // namespace gmcc::cli
