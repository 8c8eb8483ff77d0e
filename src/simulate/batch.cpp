// Thread pool of simulate_batch: std::thread workers pulling scenario indices from an atomic
// counter. The engine keeps no shared mutable state (each run creates its own SUNContext), so
// runs are independent; results are written to distinct slots, so no lock is needed for them.
#include "frictionlab/simulate/batch.hpp"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>

#include "frictionlab/cancellation.hpp"

#include "frictionlab/simulate/simulate.hpp"

namespace frictionlab {

int batch_threads(int requested, std::size_t runs) {
  if (requested < 0)
    throw std::invalid_argument("simulate_batch: threads = " + std::to_string(requested) + " must be >= 0");
  std::size_t n = requested > 0 ? static_cast<std::size_t>(requested) : std::thread::hardware_concurrency();
  n = std::min(std::max<std::size_t>(n, 1), std::max<std::size_t>(runs, 1));
  return static_cast<int>(n);
}

std::vector<BatchResult> simulate_batch(const std::vector<Scenario>& scenarios, const BatchOptions& options) {
  const int threads = batch_threads(options.threads, scenarios.size());
  std::vector<BatchResult> results(scenarios.size());
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> finished{0};

  // The caller's cancellation token (frictionlab/cancellation.hpp) is every worker's too; a
  // cancelled run is not a failed run: the workers stop taking runs and the batch throws.
  const CancelToken* token = current_cancel_token();
  auto worker = [&] {
    const CancelScope scope(token);
    for (std::size_t i = next.fetch_add(1); i < scenarios.size() && !cancel_requested(); i = next.fetch_add(1)) {
      BatchResult& r = results[i];
      try {
        r.trajectory = simulate(scenarios[i]);
        if (options.on_result) options.on_result(i, r);
      } catch (const Cancelled&) {
        break;
      } catch (const std::exception& e) {
        r.error = std::current_exception();
        r.message = e.what();
      } catch (...) {
        r.error = std::current_exception();
        r.message = "unknown exception";
      }
      const std::size_t done = finished.fetch_add(1) + 1;
      if (options.progress) options.progress(i, done);
    }
  };

  if (threads == 1) {
    worker();
    throw_if_cancelled();
    return results;
  }
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(threads - 1));
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();  // the calling thread works too
  for (auto& th : pool) th.join();
  throw_if_cancelled();
  return results;
}

}  // namespace frictionlab
