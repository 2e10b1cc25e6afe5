#pragma once
// --memory-limit and running out of memory: exit status 3 with a message, never an abort or an
// "internal error" (docs/cli.md, "Files, special paths, signals and time limits").
//
// The limit is RLIMIT_AS (address space, the only memory limit a process can set on itself):
// allocations beyond it fail. Two kinds of allocation then fail differently. operator new
// throws std::bad_alloc, which main maps to the message and exit status 3. GMP (and MPFR and
// MPFI, which allocate through GMP's functions) would print its own message and abort();
// throwing through GMP's C code instead would leave its objects half-made, so gmcc's GMP
// allocation functions, on failure, end the process on the spot through exit_at_limit.

#include <cstdint>

namespace gmcc::cli {

/// Make GMP allocate through functions that end the run with exit status 3 when memory runs
/// out. Call first in main, before any GMP number is made.
void install_gmp_allocation_failure_exit();

/// Keep freed memory for reuse instead of returning it to the system after every image: glibc's
/// default trims the heap above 128 KiB of free memory and maps blocks over 128 KiB afresh, so a
/// run over many images faults the same pages in again for each (about 3% of `gmcc estimate
/// --space 3d` on 64 × 64 photographs, docs/performance-history.md). Memory held is at most what the run
/// already needed at its peak, plus 64 MiB. Call first in main.
void keep_freed_memory();

/// Limit the address space to `mib` MiB (setrlimit RLIMIT_AS).
/// \throws InputError naming --memory-limit if the system refuses (above the hard limit).
void limit_memory(std::uint64_t mib);

/// The limit set by limit_memory in MiB, 0 if none.
std::uint64_t memory_limit_mib();

/// Report that memory ran out (naming --memory-limit when one is set), remove the temporary
/// files and _exit(3).
[[noreturn]] void exit_out_of_memory() noexcept;

}  // namespace gmcc::cli
