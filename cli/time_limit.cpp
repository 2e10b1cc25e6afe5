#include "time_limit.h"

#include "limit_exit.h"

#include <chrono>
#include <string>

namespace gmcc::cli {

TimeLimit::TimeLimit(std::uint64_t seconds) {
  // Formatted now: when the deadline comes, the memory may be gone too.
  const std::string reached =
      "time limit of " + std::to_string(seconds) + " s reached (--time-limit)";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  watchdog_ = std::thread([this, reached, deadline] {
    std::unique_lock<std::mutex> lock(mutex_);
    if (stopped_.wait_until(lock, deadline, [this] { return stop_; })) return;
    exit_at_limit(reached.c_str());
  });
}

TimeLimit::~TimeLimit() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  stopped_.notify_all();
  watchdog_.join();
}

}  // namespace gmcc::cli
