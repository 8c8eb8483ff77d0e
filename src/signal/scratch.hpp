#pragma once
// Per-thread work buffers for the signal pipelines (private to the library).
//
// Why: IDIM and decimation run over records of 1e4 to 1e6 samples. On the virtual machines our
// users and CI run on, first-touching freshly mapped pages (what every new buffer of that size
// costs, since the allocator hands large blocks back to the system when they are freed) took
// longer than the filtering itself. Buffers here grow, are kept for the thread's life (up to
// kScratchKeepDoubles in all) and are reused, so a repeated identification maps no new memory.
// A caller that can be re-entered (IDIM runs user column functions) must not hand out its slots
// to a nested call of itself: it uses buffers of its own then.

#include <Eigen/Core>

namespace frictionlab::detail {

/// Who uses which buffer; a caller owns its slots while it runs (IDIM columns take
/// idim_columns + term index).
enum ScratchSlot : int { decimation_block = 0, filtfilt_padded, idim_qd, idim_qdd, idim_columns };

/// Buffers larger than this in all (doubles: 64 MiB) are released at the end of the outermost
/// ScratchScope.
inline constexpr Eigen::Index kScratchKeepDoubles = Eigen::Index(8) << 20;

/// A buffer of `size` doubles for `slot` on this thread (contents unspecified), valid until
/// the next scratch() call with the same slot on this thread or the end of the outermost
/// ScratchScope. Asking for a new slot may move the others' Eigen vectors, never their data.
Eigen::Map<Eigen::VectorXd> scratch(int slot, Eigen::Index size);

/// Marks a stretch of work that uses the buffers (an identification, a filtering call). When
/// the outermost scope on the thread ends, buffers holding more than kScratchKeepDoubles in all
/// (after a very long record) are freed, so a long-lived thread does not keep its largest
/// record's memory; scopes opened inside it (the 41 regressions of a vs search) keep them.
class ScratchScope {
 public:
  ScratchScope();
  ~ScratchScope();
  ScratchScope(const ScratchScope&) = delete;
  ScratchScope& operator=(const ScratchScope&) = delete;
};

}  // namespace frictionlab::detail
