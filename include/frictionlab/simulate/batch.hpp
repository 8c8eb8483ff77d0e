#pragma once
// Batches of independent simulations (parameter studies, stick-slip maps, Monte Carlo runs) on
// several threads. Each scenario is simulated exactly as simulate(scenario) would, on its own
// CVODE context, so a result does not depend on the thread count or on the other runs.

#include <cstddef>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "frictionlab/simulate/scenario.hpp"
#include "frictionlab/simulate/trajectory.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The outcome of one run of a batch: a trajectory, or the exception simulate() threw.
struct BatchResult {
  Trajectory trajectory;     ///< empty when the run failed
  std::exception_ptr error;  ///< null on success; rethrow with std::rethrow_exception
  std::string message;       ///< what() of the error ("" on success)

  bool ok() const { return error == nullptr; }
};

/// Options of simulate_batch().
struct BatchOptions {
  /// Worker threads, >= 0. 0 (default): std::thread::hardware_concurrency() (1 if unknown).
  /// Never more threads than scenarios. 1 runs everything on the calling thread.
  int threads = 0;
  /// Called after each finished run (from the worker that ran it, so it must be thread-safe)
  /// with the index of the scenario and the number finished so far. Optional.
  std::function<void(std::size_t index, std::size_t finished)> progress;
  /// Called after each successful run, before `progress`, from the worker that ran it (so it must
  /// be thread-safe across indices), with the run's result, which it may move from or reduce:
  /// simulate_batch returns whatever is left in it. A caller that keeps a few figures of each
  /// run instead of its trajectory (a map over a large grid) then holds one trajectory per
  /// thread, not one per run. Optional. An exception it throws is captured in the result as a
  /// failed run's;
  /// a failed run is not passed to it (its error stays in the returned result).
  std::function<void(std::size_t index, BatchResult& result)> on_result;
};

/// Simulates every scenario (simulate(scenarios[i])) on options.threads threads. Runs are handed
/// out one at a time from a shared counter, so uneven run times balance out.
/// \returns one BatchResult per scenario, in the order of `scenarios`. An exception of one run
///          (bad options, a null plant, an integrator failure) is captured in its result and the
///          other runs go on; nothing is thrown for them.
/// \throws std::invalid_argument when options.threads < 0.
std::vector<BatchResult> simulate_batch(const std::vector<Scenario>& scenarios, const BatchOptions& options = {});

/// The thread count simulate_batch uses for `requested` threads and `runs` runs: requested, or
/// hardware_concurrency() when 0, capped at runs (at least 1).
int batch_threads(int requested, std::size_t runs);

}  // namespace frictionlab
