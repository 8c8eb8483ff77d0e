#pragma once
// Per-thread recycling of the storage of Trajectory columns (private to the library).
//
// Why: a 30 s run at 1 kHz returns ten columns of 240 KiB. The allocator hands blocks of that
// size back to the system when they are freed, and on the virtual machines our users and CI run
// on, first-touching the fresh pages of the next run's columns cost about 10 us a page: more
// than the integration itself (a Canudas stick-slip run took 15.8 ms instead of 5.4 ms). A
// Trajectory's destructor gives its columns back here, and the engine takes them again, so a
// loop of simulations (a parameter study, a fit, a benchmark) maps no new memory.

#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace frictionlab::detail {

/// Columns smaller than this (doubles: 32 KiB) are not kept. (Larger ones are worth keeping even
/// below the allocator's mmap threshold: it trims the freed top of its heap beyond 128 KiB.)
inline constexpr std::size_t kColumnPoolMinDoubles = std::size_t(4) << 10;
/// At most this many doubles (64 MiB) are kept per thread; the smallest columns go first.
inline constexpr std::size_t kColumnPoolKeepDoubles = std::size_t(8) << 20;

/// Which of a thread's two pools a column lives in: the main one (the CSV columns, the law states,
/// other contacts' columns), or the side one for a trajectory's drive column, which is outside a
/// 1-DOF CSV and is recorded by every run: kept apart so that the main pool's accounting (and
/// what it evicts first) is that of the columns users see. Each pool keeps at most
/// kColumnPoolKeepDoubles.
enum class Shelf { main = 0, side = 1 };

/// An empty vector with capacity >= `rows`: a recycled column of this thread's `shelf` (the
/// smallest that fits) or a new one. \throws std::bad_alloc.
std::vector<double> take_column(std::size_t rows, Shelf shelf = Shelf::main);

/// Keeps the storage of `column` for this thread's next take_column() on `shelf` when it is large
/// enough and fits in the pool; otherwise frees it. Safe during thread exit (then it just frees).
void recycle_column(std::vector<double>&& column, Shelf shelf = Shelf::main) noexcept;

/// The same for a data set's columns (io/dataset.hpp), which are Eigen vectors: reading a file
/// again (a loop over logs, a benchmark) would otherwise first-touch fresh pages for every column,
/// as the allocator returns a freed data set's columns to the system. A vector of exactly `rows`
/// values (contents unspecified): a recycled one of this thread's, or a new one.
/// \throws std::bad_alloc.
Eigen::VectorXd take_vector(Eigen::Index rows);

/// Keeps `v`'s storage for this thread's next take_vector of its size (within the same limits as
/// the columns: at least kColumnPoolMinDoubles, at most kColumnPoolKeepDoubles in all, the
/// smallest first out); otherwise frees it. Safe during thread exit.
void recycle_vector(Eigen::VectorXd&& v) noexcept;

/// Doubles of capacity kept on this thread's `shelf` now (for tests).
std::size_t pooled_doubles(Shelf shelf = Shelf::main) noexcept;

/// Doubles kept for take_vector on this thread now (for tests).
std::size_t pooled_vector_doubles() noexcept;

}  // namespace frictionlab::detail
