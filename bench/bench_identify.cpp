// Identification pipelines. Targets (ratios against scipy, measured by bench/compare):
// EMPS IDIM pipeline under 50 ms end to end, and its compute (both files in memory) >= 10x
// faster than scipy with the same parameters to 1e-6 relative;
// Stribeck fit of 100 000 points >= 3x faster than scipy.optimize.least_squares.

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>

#include "frictionlab/identify/idim.hpp"
#include "frictionlab/identify/static_fit.hpp"
#include "frictionlab/identify/idim_record.hpp"
#include "frictionlab/io/mat.hpp"

namespace {

namespace fl = frictionlab;

fl::IdimData emps(const std::string& name) {
  return fl::idim_record(fl::read_mat(std::string(FRICTIONLAB_SOURCE_DIR) + "/data/emps/" + name), {"t", "qm", "vir", "gtau"});
}

// read .mat + filter + differentiate + decimate + solve + cross-test on the second file.
void BM_EmpsIdimPipeline(benchmark::State& state) {
  for (auto _ : state) {
    const fl::Result r = fl::identify_idim(emps("DATA_EMPS.mat"));
    benchmark::DoNotOptimize(fl::cross_test(r, emps("DATA_EMPS_PULSES.mat")).relative_error_percent);
  }
  state.SetLabel("target < 50 ms (reading both files included)");
}

// The pipeline without file reading: filter + differentiate + decimate + solve.
void BM_EmpsIdimSolveOnly(benchmark::State& state) {
  const fl::IdimData d = emps("DATA_EMPS.mat");
  for (auto _ : state) benchmark::DoNotOptimize(fl::identify_idim(d).fit.rmse);
  state.SetLabel("one file; with the cross-test, target >= 10x faster than scipy (bench/compare)");
}

// What bench/compare's "EMPS compute" row times: both files in memory, identification and
// cross-test (filter, differentiate, decimate, solve, on both).
void BM_EmpsIdimCompute(benchmark::State& state) {
  const fl::IdimData ident = emps("DATA_EMPS.mat"), pulses = emps("DATA_EMPS_PULSES.mat");
  for (auto _ : state) {
    const fl::Result r = fl::identify_idim(ident);
    benchmark::DoNotOptimize(fl::cross_test(r, pulses).relative_error_percent);
  }
  state.SetLabel("target >= 10x faster than scipy (bench/compare)");
}

// Noisy Stribeck map with the truth of bench/peers/common.py (not the same random stream).
void BM_StribeckFit(benchmark::State& state) {
  const auto n = static_cast<Eigen::Index>(state.range(0));
  const fl::Stribeck truth{0.02, 0.035, 0.8, 1.6, 1.5e-4};
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-3.0, 0.0);
  std::normal_distribution<double> noise(0.0, 0.01 * truth.Fc);
  Eigen::VectorXd v(n), f(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    v[i] = 300.0 * std::pow(10.0, u(rng)) * (i % 2 ? -1.0 : 1.0);
    f[i] = truth.sliding(v[i]) + noise(rng);
  }
  for (auto _ : state) benchmark::DoNotOptimize(fl::fit_static_law(v, f).rmse);
  state.SetLabel(n == 100000 ? "target >= 3x faster than scipy least_squares (bench/compare)" : "no target");
}

}  // namespace

BENCHMARK(BM_EmpsIdimPipeline)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EmpsIdimSolveOnly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EmpsIdimCompute)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StribeckFit)->Arg(1000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();
