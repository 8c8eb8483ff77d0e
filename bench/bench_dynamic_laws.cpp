// Dynamic friction laws: one fixed-step update `step(z, v, dt)` as a 10 kHz controller runs it
// (dt = 1e-4 s). Targets: LuGre < 20 ns, GMS with 10 elements < 100 ns. The velocity cycles
// through 1024 values of both signs (through the Stribeck dip, elastic and sliding regimes).

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "frictionlab/models/friction_law.hpp"

namespace {

using namespace frictionlab;

constexpr std::size_t kInputs = 1024;
constexpr double kDt = 1e-4;

// A slow sine with a small ripple: v = 5e-3 sin(2 pi i / 1024) + 1e-4 sin(i): reversals, presliding, sliding.
const std::array<double, kInputs>& velocities() {
  static const std::array<double, kInputs> v = [] {
    std::array<double, kInputs> out{};
    for (std::size_t i = 0; i < kInputs; ++i) {
      const double x = static_cast<double>(i);
      out[i] = 5e-3 * std::sin(2 * 3.141592653589793 * x / kInputs) + 1e-4 * std::sin(x);
    }
    return out;
  }();
  return v;
}

template <class Law>
void BM_Step(benchmark::State& state, Law law, const char* target) {
  const auto& v = velocities();
  const Law* lp = &law;  // escapes: parameters are run-time values (see BM_StaticLaw)
  benchmark::DoNotOptimize(lp);
  std::vector<double> z(static_cast<std::size_t>(law.num_states()), 0.0);
  const std::span<double> zs(z);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(lp->step(zs, v[i++ & (kInputs - 1)], kDt));
  }
  state.SetLabel(target);
}

void BM_FrictionLawStep(benchmark::State& state, FrictionLaw law, const char* target) {
  const auto& v = velocities();
  std::vector<double> z(static_cast<std::size_t>(law.num_states()), 0.0);
  const std::span<double> zs(z);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(law.step(zs, v[i++ & (kInputs - 1)], kDt));
  }
  state.SetLabel(target);
}

Gms gms(int n) {
  Gms law;
  law.k.clear();
  law.alpha.clear();
  for (int i = 0; i < n; ++i) {
    law.k.push_back(1e5 / (1 + i));  // from stiff to soft elements
    law.alpha.push_back(1.0 / n);
  }
  return law;
}

}  // namespace

BENCHMARK_CAPTURE(BM_Step, lugre, LuGre{}, "target < 20 ns");
BENCHMARK_CAPTURE(BM_Step, elastoplastic, ElastoPlastic{}, "no target (a few Newton steps in the transition)");
BENCHMARK_CAPTURE(BM_Step, dahl_alpha_1, Dahl{}, "no target");
BENCHMARK_CAPTURE(BM_Step, dahl_alpha_1_5, Dahl{1e5, 1.0, 1.5}, "no target");
BENCHMARK_CAPTURE(BM_Step, gms_3, gms(3), "no target (10 elements: < 100 ns)");
BENCHMARK_CAPTURE(BM_Step, gms_10, gms(10), "target < 100 ns");
BENCHMARK_CAPTURE(BM_FrictionLawStep, lugre, FrictionLaw(LuGre{}), "target < 20 ns");
BENCHMARK_CAPTURE(BM_FrictionLawStep, gms_10, FrictionLaw(gms(10)), "target < 100 ns");
