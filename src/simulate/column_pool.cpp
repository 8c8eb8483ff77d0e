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

// Data set columns: Eigen vectors, sorted by size, smallest first.
struct VectorPool {
  std::vector<Eigen::VectorXd> vectors;
  std::size_t doubles = 0;
  VectorPool();
  ~VectorPool();
};

thread_local bool g_vector_pool_gone = false;

VectorPool::VectorPool() = default;
VectorPool::~VectorPool() { g_vector_pool_gone = true; }

VectorPool& vector_pool() {
  thread_local VectorPool p;
  return p;
}

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

Eigen::VectorXd take_vector(Eigen::Index rows) {
  const auto n = static_cast<std::size_t>(std::max<Eigen::Index>(rows, 0));
  if (n >= kColumnPoolMinDoubles && !g_vector_pool_gone) {
    VectorPool& p = vector_pool();
    auto it = std::lower_bound(p.vectors.begin(), p.vectors.end(), rows,
                               [](const Eigen::VectorXd& v, Eigen::Index k) { return v.size() < k; });
    if (it != p.vectors.end() && it->size() == rows) {  // an Eigen vector cannot shrink in place
      Eigen::VectorXd v = std::move(*it);
      p.vectors.erase(it);
      p.doubles -= n;
      return v;
    }
  }
  return Eigen::VectorXd(rows);
}

void recycle_vector(Eigen::VectorXd&& v) noexcept {
  const auto n = static_cast<std::size_t>(v.size());
  if (g_vector_pool_gone || n < kColumnPoolMinDoubles || n > kColumnPoolKeepDoubles) return;
  VectorPool& p = vector_pool();
  try {
    auto it = std::lower_bound(p.vectors.begin(), p.vectors.end(), v.size(),
                               [](const Eigen::VectorXd& w, Eigen::Index k) { return w.size() < k; });
    p.vectors.insert(it, std::move(v));
    p.doubles += n;
    while (p.doubles > kColumnPoolKeepDoubles) {
      p.doubles -= static_cast<std::size_t>(p.vectors.front().size());
      p.vectors.erase(p.vectors.begin());
    }
  } catch (...) {
    // Out of memory for the pool's own list: the vector is simply freed.
  }
}

std::size_t pooled_vector_doubles() noexcept { return g_vector_pool_gone ? 0 : vector_pool().doubles; }

std::size_t pooled_doubles(Shelf shelf) noexcept { return g_pool_gone ? 0 : pool(shelf).doubles; }

}  // namespace frictionlab::detail
