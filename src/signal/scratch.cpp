#include "scratch.hpp"

#include <cstdlib>
#include <deque>

namespace frictionlab::detail {
namespace {

// A deque: growing it never moves the vectors (nor their data) handed out before.
struct Arena {
  std::deque<Eigen::VectorXd> buffers;
  std::size_t top = 0;              // buffers [0, top) are held by open frames
  ScratchFrame* innermost = nullptr;
};

Arena& arena() {
  thread_local Arena a;
  return a;
}

}  // namespace

ScratchFrame::ScratchFrame() : base_(arena().top), outer_(arena().innermost) { arena().innermost = this; }

ScratchFrame::~ScratchFrame() {
  Arena& a = arena();
  a.top = base_;
  a.innermost = outer_;
  if (outer_ != nullptr) return;
  Eigen::Index total = 0;
  for (const auto& b : a.buffers) total += b.size();
  if (total > kScratchKeepDoubles) a.buffers.clear();
}

Eigen::Map<Eigen::VectorXd> ScratchFrame::get(Eigen::Index size) {
  Arena& a = arena();
  if (a.innermost != this) std::abort();  // a broken invariant of the library, not bad input
  if (a.buffers.size() <= a.top) a.buffers.resize(a.top + 1);
  Eigen::VectorXd& b = a.buffers[a.top++];
  if (b.size() < size) b.resize(size);  // grows only: a smaller request reuses the head
  return {b.data(), size};
}

}  // namespace frictionlab::detail
