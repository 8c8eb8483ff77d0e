#pragma once
// Cooperative cancellation of long work: a Ctrl-C in Python, a host application's Stop button.
//
// The caller owns a CancelToken (an atomic flag) and makes it the current one of the thread that
// runs the work with a CancelScope. The work polls the current token at its natural steps and
// unwinds with `Cancelled` once it is set:
//   - the simulation engine before each solver call (so within one step of the integrator),
//   - simulate_batch (and so maps and fleet runs) before each run, on every worker thread,
//   - plan's Monte Carlo loop before each run,
//   - the Ceres fits (LuGre, static laws) after each iteration, through an iteration callback
//     that aborts the solve,
//   - reading a file for its SHA-256 before each block.
// Polling costs one relaxed atomic load. Work that is never given a token is never cancelled.
//
// The token is found through a thread-local pointer rather than an option of every function, so
// that cancellation reaches every layer without changing their signatures; simulate_batch hands
// its caller's token to its worker threads.

#include <atomic>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// What cancelled work throws. Deliberately not a std::exception: the handlers that turn a
/// failure into a result (a failed batch run, a failed candidate of a method comparison) catch
/// std::exception, and a cancellation must pass through them to the caller. The Python module
/// turns it into KeyboardInterrupt.
class Cancelled {
 public:
  /// "cancelled", for a catch (...) that wants a message.
  const char* what() const noexcept { return "cancelled"; }
};

/// A flag one thread sets (cancel()) and long work on another thread polls. Never reset: use a
/// new token for new work. Thread-safe.
class CancelToken {
 public:
  /// Asks the work polling this token to stop. May be called from any thread, also a signal
  /// handler (a lock-free atomic store).
  void cancel() noexcept { flag_.store(true, std::memory_order_relaxed); }
  /// True once cancel() was called.
  bool cancelled() const noexcept { return flag_.load(std::memory_order_relaxed); }

 private:
  std::atomic<bool> flag_{false};
};

/// Makes `token` (may be null: no cancellation) the current token of the calling thread for the
/// scope's lifetime. Scopes nest: the previous token is current again when the scope ends. The
/// token must outlive the scope.
class CancelScope {
 public:
  explicit CancelScope(const CancelToken* token) noexcept;
  ~CancelScope();
  CancelScope(const CancelScope&) = delete;
  CancelScope& operator=(const CancelScope&) = delete;

 private:
  const CancelToken* previous_;
};

/// The calling thread's current token (its innermost CancelScope's), or null.
const CancelToken* current_cancel_token() noexcept;

/// True when the calling thread's current token is set.
inline bool cancel_requested() noexcept {
  const CancelToken* t = current_cancel_token();
  return t != nullptr && t->cancelled();
}

/// \throws Cancelled when the calling thread's current token is set.
inline void throw_if_cancelled() {
  if (cancel_requested()) throw Cancelled{};
}

}  // namespace frictionlab
