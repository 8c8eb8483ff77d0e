// LuGre output-error identification (identify_lugre) on the record of tests/identify/
// test_lugre.cpp (tests/identify/lugre_record.hpp: Table I, 10 s of 1 kHz data). Targets: the whole fit
// (static part identified, then all six parameters) under 2 s; with the static part given
// (sigma0, sigma1 only, the work the scipy peer bench/peers/lugre_fit.py does) >= 3x faster than
// scipy at equal or better parameter error (stretch 20x), measured by bench/compare.

#include <benchmark/benchmark.h>

#include <string>

#include "../tests/identify/lugre_record.hpp"

namespace {

namespace fl = frictionlab;

// Arg 0: static part identified from the record (the test's default mode). Arg 1: static part given.
void BM_LugreFit(benchmark::State& state) {
  const fl::LugreData d = fl::testing::lugre_record();
  fl::LugreOptions o;
  o.inertia = 1.0;
  const bool given = state.range(0) == 1;
  if (given) o.static_law = fl::testing::lugre_static_part();
  for (auto _ : state) {
    const fl::Result r = fl::identify_lugre(d, o);
    if (!r.ok()) {
      state.SkipWithError(("identify_lugre failed: " + r.message).c_str());
      break;
    }
    benchmark::DoNotOptimize(r.value("sigma0"));
  }
  state.SetLabel(given ? "static given: target >= 3x faster than scipy (bench/compare lugre_fit)"
                       : "target < 2 s; >= 3x faster than scipy (bench/compare)");
}

}  // namespace

BENCHMARK(BM_LugreFit)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
