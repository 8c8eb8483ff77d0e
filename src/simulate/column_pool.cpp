#include "column_pool.hpp"

#include <algorithm>
#include <utility>

namespace frictionlab::detail {
namespace {

struct Pool {
  std::vector<std::vector<double>> columns;  // sorted by capacity, smallest first
  std::size_t doubles = 0;
  Pool();
  ~Pool();
};

// Whether this thread's pool was destroyed: a Trajectory destroyed by another thread_local's
// destructor after the pool's own must not touch it. (A trivially destructible thread_local,
// readable at any time.)
thread_local bool g_pool_gone = false;

Pool::Pool() = default;
Pool::~Pool() { g_pool_gone = true; }

Pool& pool(Shelf shelf) {
  thread_local Pool p[2];
  return p[static_cast<int>(shelf)];
}

}  // namespace

std::vector<double> take_column(std::size_t rows, Shelf shelf) {
  if (rows >= kColumnPoolMinDoubles && !g_pool_gone) {
    Pool& p = pool(shelf);
    auto it = std::lower_bound(p.columns.begin(), p.columns.end(), rows,
                               [](const std::vector<double>& c, std::size_t n) { return c.capacity() < n; });
    // A column much larger than asked for stays for a longer run.
    if (it != p.columns.end() && it->capacity() <= 4 * rows) {
      std::vector<double> c = std::move(*it);
      p.columns.erase(it);
      p.doubles -= c.capacity();
      return c;
    }
  }
  std::vector<double> c;
  c.reserve(rows);
  return c;
}

void recycle_column(std::vector<double>&& column, Shelf shelf) noexcept {
  const std::size_t cap = column.capacity();
  if (g_pool_gone || cap < kColumnPoolMinDoubles || cap > kColumnPoolKeepDoubles) return;
  Pool& p = pool(shelf);
  try {
    column.clear();
    auto it = std::lower_bound(p.columns.begin(), p.columns.end(), cap,
                               [](const std::vector<double>& c, std::size_t n) { return c.capacity() < n; });
    p.columns.insert(it, std::move(column));
    p.doubles += cap;
    while (p.doubles > kColumnPoolKeepDoubles) {
      p.doubles -= p.columns.front().capacity();
      p.columns.erase(p.columns.begin());
    }
  } catch (...) {
    // Out of memory for the pool's own list: the column is simply freed.
  }
}

std::size_t pooled_doubles(Shelf shelf) noexcept { return g_pool_gone ? 0 : pool(shelf).doubles; }

}  // namespace frictionlab::detail
