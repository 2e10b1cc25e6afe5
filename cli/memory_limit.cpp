#include "memory_limit.h"

#include "limit_exit.h"

#include <gmcc/input/input_error.h>

#include <gmp.h>
#include <malloc.h>
#include <sys/resource.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace gmcc::cli {
namespace {

std::atomic<std::uint64_t> limit_mib{0};

// GMP's own defaults are malloc, realloc and free: these are the same, except on failure.
void* gmp_allocate(std::size_t size) {
  void* p = std::malloc(size);
  if (!p && size) exit_out_of_memory();
  return p;
}
void* gmp_reallocate(void* old, std::size_t, std::size_t size) {
  void* p = std::realloc(old, size);
  if (!p && size) exit_out_of_memory();
  return p;
}
void gmp_free(void* p, std::size_t) { std::free(p); }

}  // namespace

void install_gmp_allocation_failure_exit() {
  mp_set_memory_functions(gmp_allocate, gmp_reallocate, gmp_free);
}

void keep_freed_memory() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 64 << 20);
  mallopt(M_TOP_PAD, 16 << 20);
}

void limit_memory(std::uint64_t mib) {
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) != 0)
    throw InputError("--memory-limit", 0, std::string("cannot be set: ") + std::strerror(errno));
  limit.rlim_cur = static_cast<rlim_t>(mib) << 20;
  if (::setrlimit(RLIMIT_AS, &limit) != 0)
    throw InputError("--memory-limit", 0,
                     std::string("cannot be set: ") + std::strerror(errno) +
                         (errno == EINVAL ? " (above the hard limit, ulimit -Hv)" : ""));
  limit_mib.store(mib);
}

std::uint64_t memory_limit_mib() { return limit_mib.load(); }

void exit_out_of_memory() noexcept {
  char reached[128];
  if (const std::uint64_t mib = limit_mib.load())
    std::snprintf(reached, sizeof reached, "memory limit of %llu MiB reached (--memory-limit)",
                  static_cast<unsigned long long>(mib));
  else
    std::snprintf(reached, sizeof reached, "out of memory");
  exit_at_limit(reached);
}

}  // namespace gmcc::cli
