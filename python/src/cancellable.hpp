#pragma once
// Long work called from Python: run with the GIL released, and stopped by Ctrl-C.
//
// Python delivers a signal only to its main thread, when that thread runs Python code or calls
// PyErr_CheckSignals. So on the main thread the work runs on a worker thread with its own
// cancellation token (frictionlab/cancellation.hpp), while the main thread waits in slices of
// kSignalPoll and checks signals after each. When a signal handler raises (KeyboardInterrupt for
// Ctrl-C), the token is cancelled, the worker stops at its next poll (a solver step, a batch run,
// a fit iteration), and the handler's exception is raised from the call. Off the main thread (a
// Dask worker thread, a thread pool) PyErr_CheckSignals does nothing: the work runs in place with
// the GIL released.
//
// `work` must not touch Python objects (it runs without the GIL): convert the arguments first.

#include <pybind11/pybind11.h>

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <type_traits>
#include <utility>

#include "frictionlab/cancellation.hpp"

namespace frictionlab::python {

/// How often the waiting main thread checks for signals: short enough that Ctrl-C feels
/// immediate, long enough that the check costs nothing (one GIL round trip per slice).
inline constexpr std::chrono::milliseconds kSignalPoll{50};

/// True on the interpreter's main thread (the one signal handlers run on). Set at import.
bool on_python_main_thread();

/// Records the interpreter's main thread (threading.main_thread()); called once at import.
void remember_python_main_thread();

/// Runs `work()` without the GIL, cancellable by a signal (above); returns what it returns.
/// \throws what `work` throws; pybind11::error_already_set with the signal handler's exception
///         (KeyboardInterrupt) when a signal stopped it.
template <class Work>
auto run_cancellable(Work&& work) -> std::invoke_result_t<Work&> {
  using R = std::invoke_result_t<Work&>;
  if (!on_python_main_thread()) {
    pybind11::gil_scoped_release release;
    return work();
  }
  CancelToken token;
  std::conditional_t<std::is_void_v<R>, bool, std::optional<R>> result{};
  std::exception_ptr error;
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  bool interrupted = false;
  {
    pybind11::gil_scoped_release release;
    std::thread worker([&] {
      const CancelScope scope(&token);
      try {
        if constexpr (std::is_void_v<R>)
          work();
        else
          result.emplace(work());
      } catch (...) {
        error = std::current_exception();
      }
      const std::lock_guard lock(mutex);
      done = true;
      finished.notify_one();
    });
    std::unique_lock lock(mutex);
    while (!finished.wait_for(lock, kSignalPoll, [&] { return done; })) {
      if (interrupted) continue;  // cancelled: wait for the worker to reach its next poll
      lock.unlock();
      {
        pybind11::gil_scoped_acquire acquire;
        interrupted = PyErr_CheckSignals() != 0;  // the handler's exception stays set
      }
      if (interrupted) token.cancel();
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  if (interrupted) throw pybind11::error_already_set();
  if (error) std::rethrow_exception(error);
  if constexpr (!std::is_void_v<R>) return std::move(*result);
}

}  // namespace frictionlab::python
