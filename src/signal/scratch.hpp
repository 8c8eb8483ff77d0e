#pragma once
// Per-thread work buffers for long signal pipelines (private to the library).
//
// Why: decimation and the identification pipelines built on it run over records of 1e4 to 1e6
// samples. On the virtual machines our users and CI run on, first-touching freshly mapped pages
// (what every new buffer of that size costs, since the allocator hands large blocks back to the
// system when they are freed) took longer than the filtering itself. The buffers here grow, are
// kept for the thread's life (up to kScratchKeepDoubles in all) and are reused, so a repeated
// computation maps no new memory.
//
// The arena knows nothing of its users: a ScratchFrame takes the next free buffers of the
// thread's stack of buffers and gives them back when it ends. Frames nest like calls, so a
// computation re-entered from inside itself (a user's callback calling it again) gets buffers
// above its caller's without any bookkeeping; a caller names its own buffers (a struct of the
// Maps its frame handed out).

#include <Eigen/Core>
#include <cstddef>

namespace frictionlab::detail {

/// Buffers larger than this in all (doubles: 64 MiB) are released when the outermost frame on
/// the thread ends, so a long-lived thread does not keep its largest record's memory.
inline constexpr Eigen::Index kScratchKeepDoubles = Eigen::Index(8) << 20;

/// A stretch of work that uses the thread's buffers (a filtering call, an identification).
/// Buffers come from get() in order and stay valid until the frame ends; frames opened inside
/// it (by functions it calls) take buffers above its own and give them back when they end, so
/// the 41 regressions of a vs search inside one outer frame reuse the same memory.
/// Only the innermost frame of a thread may call get() (a frame is not handed to a callee that
/// opens its own); a frame lives on the stack of one thread.
class ScratchFrame {
 public:
  ScratchFrame();
  ~ScratchFrame();
  ScratchFrame(const ScratchFrame&) = delete;
  ScratchFrame& operator=(const ScratchFrame&) = delete;

  /// The frame's next buffer of `size` doubles (contents unspecified). Its data never moves
  /// while the frame lives.
  Eigen::Map<Eigen::VectorXd> get(Eigen::Index size);

 private:
  std::size_t base_;  // the thread's first buffer this frame may hand out
  ScratchFrame* outer_;
};

}  // namespace frictionlab::detail
