// Static friction laws: one evaluation of the sliding force, through the concrete type (inlined,
// what a templated controller or fitter runs) and through FrictionLaw (run-time choice by name).
// Target: < 5 ns per call (BM_FrictionLawBatch: per value of an array). The velocity cycles
// through 1024 values so nothing is constant-folded.

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "frictionlab/models/friction_law.hpp"

namespace {

using namespace frictionlab;

constexpr std::size_t kInputs = 1024;  // power of two: the index wraps with a mask

// Velocities of both signs from 1e-5 to 1 m/s (through the Stribeck dip and beyond).
const std::array<double, kInputs>& velocities() {
  static const std::array<double, kInputs> v = [] {
    std::array<double, kInputs> out{};
    for (std::size_t i = 0; i < kInputs; ++i)
      out[i] = (i % 2 ? -1.0 : 1.0) * std::pow(10.0, -5.0 + 5.0 * static_cast<double>((i * 389) % kInputs) / kInputs);
    return out;
  }();
  return v;
}

template <class Law>
void BM_StaticLaw(benchmark::State& state, Law law) {
  const auto& v = velocities();
  // Parameters are run-time values: the law escapes through a pointer, so it lives in memory.
  // (DoNotOptimize(law) on the by-value object let GCC 12 read an uninitialised register copy:
  // the viscous case then multiplied garbage, often subnormal, and took 36 ns.)
  const Law* lp = &law;
  benchmark::DoNotOptimize(lp);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(lp->sliding(v[i++ & (kInputs - 1)]));
  }
  state.SetLabel("target < 5 ns");
}

void BM_FrictionLaw(benchmark::State& state, FrictionLaw law) {
  const auto& v = velocities();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(law.sliding(v[i++ & (kInputs - 1)]));
  }
  state.SetLabel("target < 5 ns");
}

// The batch call FrictionLaw::sliding(v, F) over the 1024 velocities: one dispatch per call,
// then the law's scalar formula in a loop (the compiler vectorises what it can). The
// counter time_per_eval is the time per velocity (an inverted rate of 1024 per iteration:
// seconds, printed with an SI prefix).
template <class Evaluate>
void run_batch(benchmark::State& state, Evaluate evaluate) {
  const auto& v = velocities();
  std::array<double, kInputs> F{};
  for (auto _ : state) {
    evaluate(std::span<const double>(v), std::span<double>(F));
    benchmark::DoNotOptimize(F.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(kInputs));
  state.counters["time_per_eval"] = benchmark::Counter(
      static_cast<double>(kInputs), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.SetLabel("target < 5 ns per evaluation");
}

void BM_FrictionLawBatch(benchmark::State& state, FrictionLaw law) {
  run_batch(state, [&](std::span<const double> v, std::span<double> F) { law.sliding(v, F); });
}

// With stiction: friction_force(law, v, applied) at a velocity that is zero one call in four.
template <class Law>
void BM_StaticLawWithStiction(benchmark::State& state, Law law) {
  const auto& v = velocities();
  const Law* lp = &law;  // escapes: parameters are run-time values (see BM_StaticLaw)
  benchmark::DoNotOptimize(lp);
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ & (kInputs - 1);
    const double vel = (k & 3) == 0 ? 0.0 : v[k];
    benchmark::DoNotOptimize(friction_force(*lp, vel, v[(k + 7) & (kInputs - 1)] * 1e5));
  }
  state.SetLabel("target < 5 ns");
}

const Table& table() {
  static const Table t({-1.0, -0.1, -0.01, -0.001, 0.001, 0.01, 0.1, 1.0}, {-1.4, -1.0, -1.2, -1.5, 1.5, 1.2, 1.0, 1.4});
  return t;
}

}  // namespace

BENCHMARK_CAPTURE(BM_StaticLaw, coulomb, Coulomb{});
BENCHMARK_CAPTURE(BM_StaticLaw, viscous, Viscous{});
BENCHMARK_CAPTURE(BM_StaticLaw, coulomb_viscous, CoulombViscous{});
BENCHMARK_CAPTURE(BM_StaticLaw, static_coulomb_viscous, StaticCoulombViscous{});
BENCHMARK_CAPTURE(BM_StaticLaw, stribeck, Stribeck{});
BENCHMARK_CAPTURE(BM_StaticLaw, stribeck_delta_1_5, Stribeck{1.0, 1.5, 1e-3, 1.5, 0.4});
BENCHMARK_CAPTURE(BM_StaticLaw, karnopp, Karnopp{});
BENCHMARK_CAPTURE(BM_StaticLaw, table_8_points, table());
BENCHMARK_CAPTURE(BM_StaticLaw, smooth_tanh, Smooth{1.0, 1.5, 1e-3, 2.0, 0.4, 1e-3, SmoothShape::tanh});
BENCHMARK_CAPTURE(BM_StaticLaw, smooth_atan, Smooth{1.0, 1.5, 1e-3, 2.0, 0.4, 1e-3, SmoothShape::atan});
BENCHMARK_CAPTURE(BM_StaticLaw, smooth_tanh_no_dip, Smooth{});  // the default: Fs = Fc, one expm1
BENCHMARK_CAPTURE(BM_StaticLaw, stribeck_delta_1, Stribeck{1.0, 1.5, 1e-3, 1.0, 0.4});  // exponential shape: one exp
BENCHMARK_CAPTURE(BM_StaticLaw, coulomb_asymmetric, Asymmetric<Coulomb>{Coulomb{1.0}, Coulomb{0.8}});
BENCHMARK_CAPTURE(BM_StaticLaw, viscous_asymmetric, Asymmetric<Viscous>{Viscous{0.1}, Viscous{0.2}});
BENCHMARK_CAPTURE(BM_StaticLaw, coulomb_viscous_asymmetric, Asymmetric<CoulombViscous>{});
BENCHMARK_CAPTURE(BM_StaticLaw, static_coulomb_viscous_asymmetric, Asymmetric<StaticCoulombViscous>{});
BENCHMARK_CAPTURE(BM_StaticLaw, stribeck_asymmetric, Asymmetric<Stribeck>{});
BENCHMARK_CAPTURE(BM_StaticLawWithStiction, stribeck, Stribeck{});
BENCHMARK_CAPTURE(BM_StaticLawWithStiction, karnopp, Karnopp{});

BENCHMARK_CAPTURE(BM_FrictionLaw, coulomb, FrictionLaw(Coulomb{}));
BENCHMARK_CAPTURE(BM_FrictionLaw, coulomb_viscous, FrictionLaw(CoulombViscous{}));
BENCHMARK_CAPTURE(BM_FrictionLaw, stribeck, FrictionLaw(Stribeck{}));
BENCHMARK_CAPTURE(BM_FrictionLaw, karnopp, FrictionLaw(Karnopp{}));
BENCHMARK_CAPTURE(BM_FrictionLaw, table_8_points, FrictionLaw(table()));
BENCHMARK_CAPTURE(BM_FrictionLaw, smooth_tanh, FrictionLaw(Smooth{}));
BENCHMARK_CAPTURE(BM_FrictionLaw, stribeck_asymmetric, FrictionLaw(Asymmetric<Stribeck>{}));

BENCHMARK_CAPTURE(BM_FrictionLawBatch, coulomb, FrictionLaw(Coulomb{}));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, viscous, FrictionLaw(Viscous{}));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, coulomb_viscous, FrictionLaw(CoulombViscous{}));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, static_coulomb_viscous, FrictionLaw(StaticCoulombViscous{}));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, stribeck, FrictionLaw(Stribeck{}));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, stribeck_delta_1, FrictionLaw(Stribeck{1.0, 1.5, 1e-3, 1.0, 0.4}));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, stribeck_delta_1_5, FrictionLaw(Stribeck{1.0, 1.5, 1e-3, 1.5, 0.4}));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, karnopp, FrictionLaw(Karnopp{}));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, table_8_points, FrictionLaw(table()));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, smooth_tanh,
                  FrictionLaw(Smooth{1.0, 1.5, 1e-3, 2.0, 0.4, 1e-3, SmoothShape::tanh}));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, smooth_atan,
                  FrictionLaw(Smooth{1.0, 1.5, 1e-3, 2.0, 0.4, 1e-3, SmoothShape::atan}));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, smooth_tanh_delta_1_5,
                  FrictionLaw(Smooth{1.0, 1.5, 1e-3, 1.5, 0.4, 1e-3, SmoothShape::tanh}));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, smooth_tanh_no_dip, FrictionLaw(Smooth{}));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, smooth_atan_no_dip,
                  FrictionLaw(Smooth{1.0, 1.0, 1e-3, 2.0, 0.0, 1e-3, SmoothShape::atan}));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, coulomb_asymmetric,
                  FrictionLaw(Asymmetric<Coulomb>{Coulomb{1.0}, Coulomb{0.8}}));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, viscous_asymmetric,
                  FrictionLaw(Asymmetric<Viscous>{Viscous{0.1}, Viscous{0.2}}));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, coulomb_viscous_asymmetric, FrictionLaw(Asymmetric<CoulombViscous>{}));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, static_coulomb_viscous_asymmetric,
                  FrictionLaw(Asymmetric<StaticCoulombViscous>{}));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, stribeck_asymmetric, FrictionLaw(Asymmetric<Stribeck>{}));
BENCHMARK_CAPTURE(BM_FrictionLawBatch, stribeck_asymmetric_delta_1_5_2,
                  FrictionLaw(Asymmetric<Stribeck>{{1.0, 1.5, 1e-3, 1.5, 0.4}, {0.8, 1.1, 2e-3, 2.0, 0.3}}));

