#pragma once
// --time-limit: a watchdog so that no run can hang silently (a FIFO whose writer never closes
// it, a huge input, an experiment far larger than meant). A thread, not a signal: it sleeps
// until the deadline, and then ends the run through exit_at_limit (message, temporary files
// removed, exit status 3) while the work is left where it stands (docs/cli.md, "Files,
// special paths, signals and time limits").

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>

namespace gmcc::cli {

/// The watchdog of one run: started by the constructor, stopped by the destructor (a run that
/// ends in time, normally or by an error, is not cut).
class TimeLimit {
 public:
  explicit TimeLimit(std::uint64_t seconds);
  TimeLimit(const TimeLimit&) = delete;
  TimeLimit& operator=(const TimeLimit&) = delete;
  ~TimeLimit();

 private:
  std::mutex mutex_;
  std::condition_variable stopped_;
  bool stop_ = false;
  std::thread watchdog_;
};

}  // namespace gmcc::cli
