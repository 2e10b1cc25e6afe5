#include "exit_cleanup.h"

#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace gmcc::cli {
namespace {

// A slot is written once, before it is published (live = true), and never reused: a handler
// reading a live slot in one thread cannot see it rewritten by another. A run registers a
// handful of files; 64 slots of 4 KiB are zero pages until used.
// A slot is one file, or a family of numbered files (path + "0", path + "1", …: members of
// them), so that a run may stage any number of outputs in one slot.
struct Slot {
  std::atomic<bool> claimed{false};  // held by a registration (live or being written)
  std::atomic<bool> live{false};
  std::atomic<int> members{-1};  // -1: one file, `path`; otherwise a family of this many
  char path[4096];
};
Slot slots[64];
std::atomic<int> slots_used{0};
std::atomic<pid_t> child{0};

const int fatal_signals[] = {SIGHUP, SIGINT,  SIGQUIT,   SIGTERM, SIGPIPE, SIGALRM, SIGUSR1,
                             SIGUSR2, SIGXCPU, SIGXFSZ, SIGVTALRM, SIGPROF, SIGABRT, SIGSEGV,
                             SIGBUS, SIGFPE, SIGILL};

// The actions before install_exit_cleanup: the default, or a sanitizer's crash reporter.
struct sigaction previous[NSIG];

extern "C" void on_fatal_signal(int signal_number, siginfo_t* info, void*) {
  remove_temporaries();
  ::sigaction(signal_number, &previous[signal_number], nullptr);
  // A fault (not a kill(2) of a fault signal) is left to recur: returning runs the faulting
  // instruction again, and the previous action meets it with its own siginfo (a core dump, or
  // a sanitizer's report).
  const bool fault = (signal_number == SIGSEGV || signal_number == SIGBUS ||
                      signal_number == SIGFPE || signal_number == SIGILL) &&
                     info != nullptr && info->si_code > 0;
  // Otherwise the signal, blocked while this handler runs, is delivered again when it returns.
  if (!fault) ::raise(signal_number);
}

}  // namespace

void install_exit_cleanup() {
  static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<pid_t>::is_always_lock_free,
                "read in signal handlers");
  struct sigaction action {};
  action.sa_sigaction = on_fatal_signal;
  action.sa_flags = SA_SIGINFO;
  sigfillset(&action.sa_mask);  // one cleanup at a time: every other signal waits for it
  for (int s : fatal_signals) {
    if (::sigaction(s, nullptr, &previous[s]) != 0 || previous[s].sa_handler == SIG_IGN) continue;
    ::sigaction(s, &action, nullptr);
  }
}

int track_temporary(const std::string& path) {
  if (path.size() >= sizeof slots[0].path)
    throw std::length_error("temporary file name of " + std::to_string(path.size()) + " bytes");
  // The first free slot: a slot is freed when its file is committed or removed, so 64 bound the
  // temporaries alive at once, not those of a whole process (a library or a fuzzer runs many).
  constexpr int count = static_cast<int>(sizeof slots / sizeof slots[0]);
  int i = 0;
  while (i < count && slots[i].claimed.exchange(true)) ++i;
  if (i == count) throw std::length_error("more than 64 temporary files at once");
  std::memcpy(slots[i].path, path.c_str(), path.size() + 1);  // not live yet: handlers skip it
  slots[i].members.store(-1);
  slots[i].live.store(true);
  for (int used = slots_used.load(); used < i + 1 && !slots_used.compare_exchange_weak(used, i + 1);) {
  }
  return i;
}

int track_temporary_family(const std::string& prefix) {
  const int i = track_temporary(prefix);
  slots[i].members.store(0);
  return i;
}

void family_members(int handle, int members) noexcept {
  if (handle >= 0 && handle < static_cast<int>(sizeof slots / sizeof slots[0])) slots[handle].members.store(members);
}

std::string family_member(const std::string& prefix, int k) { return prefix + std::to_string(k); }

void untrack_temporary(int handle) noexcept {
  if (handle >= 0 && handle < static_cast<int>(sizeof slots / sizeof slots[0])) {
    slots[handle].live.store(false);
    slots[handle].claimed.store(false);
  }
}

bool is_tracked(const std::string& path) noexcept {
  const int used = slots_used.load();
  for (int i = 0; i < used && i < static_cast<int>(sizeof slots / sizeof slots[0]); ++i)
    if (slots[i].live.load() && path == slots[i].path) return true;
  return false;
}

pid_t fork_for_exec() noexcept {
  sigset_t all, old;
  sigfillset(&all);
  ::pthread_sigmask(SIG_SETMASK, &all, &old);
  const pid_t pid = ::fork();
  if (pid == 0) {
    for (int s : fatal_signals) {
      struct sigaction current {};
      if (::sigaction(s, nullptr, &current) == 0 && (current.sa_flags & SA_SIGINFO) &&
          current.sa_sigaction == on_fatal_signal)
        ::sigaction(s, &previous[s], nullptr);
    }
  }
  ::pthread_sigmask(SIG_SETMASK, &old, nullptr);
  return pid;
}

void track_child(pid_t pid) noexcept { child.store(pid); }

bool untrack_child(pid_t pid) noexcept {
  pid_t expected = pid;
  return child.compare_exchange_strong(expected, 0);
}

void remove_temporaries() noexcept {
  const int saved_errno = errno;
  // The child first: once it is reaped it cannot create a file after we removed it. It stays a
  // zombie (its pid not reusable) until whoever takes it from `child` reaps it.
  if (const pid_t pid = child.exchange(0); pid > 0) {
    ::kill(pid, SIGKILL);
    while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
  const int used = slots_used.load();
  for (int i = 0; i < used && i < static_cast<int>(sizeof slots / sizeof slots[0]); ++i)
    if (slots[i].live.exchange(false)) {
      const int members = slots[i].members.load();
      if (members < 0) {
        ::unlink(slots[i].path);
        continue;
      }
      // A family: path followed by each member's decimal number, built without allocation.
      char name[sizeof slots[0].path + 12];
      const std::size_t n = std::strlen(slots[i].path);
      std::memcpy(name, slots[i].path, n);
      for (int k = 0; k < members; ++k) {
        char digits[12];
        int d = 0;
        for (int v = k; d == 0 || v > 0; v /= 10) digits[d++] = static_cast<char>('0' + v % 10);
        for (int j = 0; j < d; ++j) name[n + j] = digits[d - 1 - j];
        name[n + d] = '\0';
        ::unlink(name);
      }
    }
  errno = saved_errno;
}

namespace {
std::atomic<bool> progress_line_open{false};
}  // namespace

void set_progress_line_open(bool open) noexcept { progress_line_open.store(open); }

void end_progress_line() noexcept {
  if (progress_line_open.exchange(false)) write_stderr("\n");
}

void write_stderr(const char* text) noexcept {
  for (std::size_t left = std::strlen(text); left > 0;) {
    const ssize_t n = ::write(STDERR_FILENO, text, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    text += n;
    left -= static_cast<std::size_t>(n);
  }
}

}  // namespace gmcc::cli
