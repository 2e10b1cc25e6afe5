#pragma once
// Work items 0 … n−1 made by worker threads and handed on strictly in order, with at most
// `window` made and not yet handed on (`gmcc select --images --threads`: a scene's record can
// take megabytes against a large canonical gamut, so only a few are held at once).

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace gmcc::cli {

/// make(k) for k = 0 … n−1 on `threads` threads (1: in this thread, one item at a time), then
/// take(item) in order of k in this thread. An exception from make is rethrown here in its
/// item's turn, after the workers have stopped; one from take stops them too.
template <class Item, class Make, class Take>
void in_order(std::size_t n, unsigned threads, Make&& make, Take&& take) {
  auto made = [&](std::size_t k) {
    try {
      return std::pair<std::optional<Item>, std::exception_ptr>{make(k), nullptr};
    } catch (...) {
      return std::pair<std::optional<Item>, std::exception_ptr>{std::nullopt, std::current_exception()};
    }
  };
  if (threads <= 1 || n <= 1) {
    for (std::size_t k = 0; k < n; ++k) take(make(k));
    return;
  }
  const std::size_t window = 4 * std::size_t(threads);
  std::vector<std::pair<std::optional<Item>, std::exception_ptr>> slot(window);
  std::vector<bool> ready(window, false);
  std::mutex m;
  std::condition_variable changed;
  std::size_t next = 0, taken = 0;
  bool stop = false;
  auto work = [&] {
    std::unique_lock<std::mutex> lock(m);
    for (;;) {
      changed.wait(lock, [&] { return stop || next >= n || next < taken + window; });
      if (stop || next >= n) return;
      const std::size_t k = next++;
      lock.unlock();
      auto result = made(k);
      lock.lock();
      slot[k % window] = std::move(result);
      ready[k % window] = true;
      changed.notify_all();
    }
  };
  std::vector<std::thread> workers;
  struct Join {  // stops and joins the workers however this function is left
    std::vector<std::thread>& w;
    std::mutex& m;
    std::condition_variable& c;
    bool& stop;
    ~Join() {
      {
        std::lock_guard<std::mutex> l(m);
        stop = true;
      }
      c.notify_all();
      for (std::thread& t : w) t.join();
    }
  } join{workers, m, changed, stop};
  for (unsigned t = 0; t < threads; ++t) workers.emplace_back(work);
  for (std::size_t k = 0; k < n; ++k) {
    std::pair<std::optional<Item>, std::exception_ptr> item;
    {
      std::unique_lock<std::mutex> lock(m);
      changed.wait(lock, [&] { return bool(ready[k % window]); });
      item = std::move(slot[k % window]);
      ready[k % window] = false;
      ++taken;
    }
    changed.notify_all();
    if (item.second) std::rethrow_exception(item.second);
    take(std::move(*item.first));
  }
}

}  // namespace gmcc::cli
