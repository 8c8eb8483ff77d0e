// Simulation engine: whole runs of the reference scenarios (examples/), the stiff LuGre case and
// the hybrid stick/slip case, plus a batch of independent runs on 1 and 2 threads.
// Targets (ratios against scipy, measured by bench/compare in the same run; here the absolute
// times they imply on this kind of machine): Canudas stick-slip 30 s at rtol 1e-8 >= 5x faster than
// the fastest scipy integrator (stretch 50x); batch speed-up from 1 to 2 threads >= 1.8x.

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "frictionlab/io/scenario.hpp"
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
                  "target >= 5x faster than fastest scipy (bench/compare), stretch 50x")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Scenario, craig_motor_trapezoid_hybrid, "craig_motor_trapezoid",
                  "no ratio target; peer in bench/compare")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Scenario, canudas_pid_hunting_stiff, "canudas_pid_hunting", "no target")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CanudasRtol)->Arg(6)->Arg(8)->Arg(10)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BatchStickSlip)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
