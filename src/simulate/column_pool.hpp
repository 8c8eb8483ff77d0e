#pragma once
// Per-thread recycling of the storage of Trajectory columns (private to the library).
//
// Why: a 30 s run at 1 kHz returns ten columns of 240 KiB. The allocator hands blocks of that
// size back to the system when they are freed, and on the virtual machines our users and CI run
// on, first-touching the fresh pages of the next run's columns cost about 10 us a page: more
// than the integration itself (a Canudas stick-slip run took 15.8 ms instead of 5.4 ms). A
// Trajectory's destructor gives its columns back here, and the engine takes them again, so a
// loop of simulations (a parameter study, a fit, a benchmark) maps no new memory.

#include <cstddef>
#include <vector>

namespace frictionlab::detail {

/// Columns smaller than this (doubles: 32 KiB) are not kept. (Larger ones are worth keeping even
/// below the allocator's mmap threshold: it trims the freed top of its heap beyond 128 KiB.)
inline constexpr std::size_t kColumnPoolMinDoubles = std::size_t(4) << 10;
/// At most this many doubles (64 MiB) are kept per thread; the smallest columns go first.
inline constexpr std::size_t kColumnPoolKeepDoubles = std::size_t(8) << 20;

/// An empty vector with capacity >= `rows`: a recycled column of this thread (the smallest that
/// fits) or a new one. \throws std::bad_alloc.
std::vector<double> take_column(std::size_t rows);

/// Keeps the storage of `column` for this thread's next take_column() when it is large enough
/// and fits in the pool; otherwise frees it. Safe during thread exit (then it just frees).
void recycle_column(std::vector<double>&& column) noexcept;

/// Doubles of capacity kept for this thread now (for tests).
std::size_t pooled_doubles() noexcept;

}  // namespace frictionlab::detail
