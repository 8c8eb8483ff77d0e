#include "scratch.hpp"

#include <vector>

namespace frictionlab::detail {
namespace {

std::vector<Eigen::VectorXd>& buffers() {
  thread_local std::vector<Eigen::VectorXd> b;
  return b;
}

}  // namespace

Eigen::Map<Eigen::VectorXd> scratch(int slot, Eigen::Index size) {
  auto& all = buffers();
  if (all.size() <= static_cast<std::size_t>(slot)) all.resize(static_cast<std::size_t>(slot) + 1);
  Eigen::VectorXd& b = all[static_cast<std::size_t>(slot)];
  if (b.size() < size) b.resize(size);  // grows only: a smaller request reuses the head
  return {b.data(), size};
}

namespace {
thread_local int g_scope_depth = 0;
}  // namespace

ScratchScope::ScratchScope() { ++g_scope_depth; }

ScratchScope::~ScratchScope() {
  if (--g_scope_depth > 0) return;
  auto& all = buffers();
  Eigen::Index total = 0;
  for (const auto& b : all) total += b.size();
  if (total > kScratchKeepDoubles) all.clear();
}

}  // namespace frictionlab::detail
