// Simulation engine: whole runs of the reference scenarios (examples/), the stiff LuGre case and
// the hybrid stick/slip case, plus a batch of independent runs on 1 and 2 threads.
// Targets: Canudas stick-slip (LuGre, 30 s, rtol 1e-8) under 6 ms and the Craig trapezoid (140 s)
// under 5 ms; against scipy (bench/compare, same run): Canudas >= 5x faster than the fastest scipy
// integrator (stretch 50x); batch speed-up from 1 to 2 threads >= 1.8x.
// Each iteration builds and frees a whole Trajectory, as a loop of runs in a user's program does
// (the columns are allocated for each run and freed with it). BM_ScenarioFirstRun runs each on a
// new thread, as a process's first run or a batch worker's.

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/plants/spring_base.hpp"
#include "frictionlab/simulate/batch.hpp"
#include "frictionlab/simulate/simulate.hpp"

namespace {

namespace fl = frictionlab;

fl::Scenario example(const std::string& name) {
  return fl::load_scenario(std::string(FRICTIONLAB_SOURCE_DIR) + "/examples/" + name + ".yaml");
}

void BM_Scenario(benchmark::State& state, const char* name, const char* target) {
  const fl::Scenario s = example(name);
  long steps = 0;
  for (auto _ : state) {
    const fl::Trajectory t = fl::simulate(s);
    steps = t.stats.steps;
    benchmark::DoNotOptimize(t.velocity.data());
  }
  state.counters["steps"] = static_cast<double>(steps);
  state.SetLabel(target);
}

// The same run on a new thread each time (a new thread's own allocator arena), as in a process's
// first run: the difference to BM_Scenario is what a thread's start and first pages cost.
void BM_ScenarioFirstRun(benchmark::State& state, const char* name) {
  const fl::Scenario s = example(name);
  for (auto _ : state) {
    std::thread([&] { benchmark::DoNotOptimize(fl::simulate(s).velocity.data()); }).join();
  }
  state.SetLabel("no target: what a first run costs here");
}

// Stiff LuGre at a given rtol (the accuracy/speed trade-off of the Canudas case).
void BM_CanudasRtol(benchmark::State& state) {
  fl::Scenario s = example("canudas_stick_slip");
  s.options.rtol = std::pow(10.0, -static_cast<double>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(fl::simulate(s).velocity.data());
  state.SetLabel("rtol 1e-" + std::to_string(state.range(0)) + "; no target (trade-off curve)");
}

// A grid of shorter stick-slip runs (5 s) over drive velocity and stiffness; range(0) = threads.
void BM_BatchStickSlip(benchmark::State& state) {
  fl::Scenario base = example("canudas_stick_slip");
  base.options.duration = 5.0;
  base.options.output_rate = 100.0;
  std::vector<fl::Scenario> runs;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      fl::Scenario s = base;
      fl::SpringBaseParams p;
      p.V0 = 0.01 + 0.04 * i;
      p.k = 0.5 + 1.3 * j;
      s.plant = std::make_shared<fl::SpringBase>(p);
      runs.push_back(s);
    }
  fl::BatchOptions o;
  o.threads = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(fl::simulate_batch(runs, o).data());
  state.counters["runs_per_s"] = benchmark::Counter(static_cast<double>(runs.size()) * state.iterations(),
                                                    benchmark::Counter::kIsRate);
  state.SetLabel("target: 2 threads >= 1.8x the 1-thread rate");
}

}  // namespace

BENCHMARK_CAPTURE(BM_Scenario, canudas_stick_slip_30s_stiff, "canudas_stick_slip",
                  "target < 6 ms; >= 5x faster than fastest scipy (bench/compare)")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Scenario, craig_motor_trapezoid_hybrid, "craig_motor_trapezoid",
                  "target < 5 ms; peer in bench/compare")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ScenarioFirstRun, canudas_stick_slip_30s_stiff, "canudas_stick_slip")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_Scenario, canudas_pid_hunting_stiff, "canudas_pid_hunting", "no target")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CanudasRtol)->Arg(6)->Arg(8)->Arg(10)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BatchStickSlip)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
