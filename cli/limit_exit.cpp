#include "limit_exit.h"

#include "exit_cleanup.h"

#include <unistd.h>

#include <cstdio>
#include <mutex>

namespace gmcc::cli {
namespace {

std::mutex activity_mutex;
std::string activity;

}  // namespace

void set_activity(std::string what) {
  std::lock_guard<std::mutex> lock(activity_mutex);
  activity.swap(what);  // the old string is freed outside the lock, with `what`
}

void exit_at_limit(const char* reached) noexcept {
  char message[1024];
  int n = std::snprintf(message, sizeof message, "gmcc: error: %s", reached);
  // Not waited for: the thread holding the lock may be the one that ran out of memory.
  if (activity_mutex.try_lock()) {
    if (!activity.empty() && n > 0 && static_cast<std::size_t>(n) < sizeof message)
      n += std::snprintf(message + n, sizeof message - static_cast<std::size_t>(n), " while %.400s",
                         activity.c_str());
    activity_mutex.unlock();
  }
  end_progress_line();
  write_stderr(message);
  write_stderr("\n");
  remove_temporaries();
  ::_exit(limit_exit_status);
}

}  // namespace gmcc::cli
