// Built with -mavx512f -mavx2 -mfma where CMakeLists.txt can (x86-64, GCC or Clang); see
// recursive_kernels.hpp. Nothing here may call an inline function of another header (see there)
// but recursive_kit.hpp, whose functions are private to each file that includes it.
#include "recursive_kernels.hpp"

#if defined(__AVX512F__) && defined(__AVX2__) && defined(__FMA__)
// GCC 12's avx512fintrin.h passes an undefined vector (_mm512_undefined_pd) into the casts,
// inserts and extracts below, and -Wall then warns of an uninitialised variable in its code.
#pragma GCC diagnostic ignored "-Wuninitialized"
#if !defined(__clang__)  // a GCC-only warning
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include "recursive_kit.hpp"
#endif

namespace frictionlab::detail {

#if defined(__AVX512F__) && defined(__AVX2__) && defined(__FMA__)
namespace {

using Index = std::ptrdiff_t;

inline __m512d join(__m256d low, __m256d high) { return _mm512_insertf64x4(_mm512_castpd256_pd512(low), high, 1); }

// Samples after which the cascade's state, run with no input from any unit state, stays below
// 2^-70 (and below 2^-64 for a quarter as long again); 0 when that takes more than 2^16.
// Lane u starts from unit state u (lanes are the 2 NS <= 8 states: at most 4 sections), so one run covers them all.
// The last filter's answer is kept per thread: the same decimation filter comes back every call.
template <int NS>
Index decay_length(const double* c) {
  thread_local double last_c[6 * 8];
  thread_local int last_ns = 0;
  thread_local Index last_decay = 0;
  bool same = last_ns == NS;
  for (int i = 0; same && i < 6 * NS; ++i) same = last_c[i] == c[i];
  if (same) return last_decay;
  SectionOf<__m512d> s[NS];
  load_sections(c, s);
  __m512d z0[NS], z1[NS];
  alignas(64) double unit[8];
  for (int r = 0; r < NS; ++r) {
    for (int u = 0; u < 8; ++u) unit[u] = u == 2 * r ? 1.0 : 0.0;
    z0[r] = _mm512_load_pd(unit);
    for (int u = 0; u < 8; ++u) unit[u] = u == 2 * r + 1 ? 1.0 : 0.0;
    z1[r] = _mm512_load_pd(unit);
  }
  const auto largest = [&] {
    __m512d m = _mm512_setzero_pd();
    for (int r = 0; r < NS; ++r) m = _mm512_max_pd(m, _mm512_max_pd(_mm512_abs_pd(z0[r]), _mm512_abs_pd(z1[r])));
    return _mm512_reduce_max_pd(m);
  };
  constexpr Index kEvery = 16, kLongest = Index{1} << 16;
  Index decay = 0;
  bool verified = false;  // quiet for a quarter as long again
  for (Index n = 0; n < kLongest + kLongest / 4 + kEvery; n += kEvery) {
    for (Index i = 0; i < kEvery; ++i) link(s, z0, z1, _mm512_setzero_pd());
    const double size = largest();
    if (decay == 0 && size < 0x1p-70) decay = n + kEvery;
    if (decay > 0 && size >= 0x1p-64) decay = -1;  // came back: not a filter to split
    if (decay < 0) break;
    if (decay > 0 && n + kEvery >= decay + decay / 4) {
      verified = true;
      break;
    }
  }
  const Index found = verified && decay <= kLongest ? decay : 0;
  for (int i = 0; i < 6 * NS; ++i) last_c[i] = c[i];
  last_ns = NS;
  last_decay = found;
  return found;
}

// The cascade over samples 0..count-1 as two halves at once: lanes 0-3 run samples n and lanes
// 4-7 samples h + n (h = count / 2) of the four channels, the second half from a zero state; then
// the response to the second half's true initial state (the first half's final state) with no
// input is added over the `decay` samples the filter takes to forget it. read(n) gives the four
// channels' input at n, write(n, y) stores their output, add(n, y) adds to it.
template <int NS, class Read, class Write, class Add>
bool halves(const double* c, double* z, Index count, Read read, Write write, Add add) {
  const Index h = count / 2;
  const Index decay = decay_length<NS>(c);
  if (decay == 0 || decay > h / 2) return false;  // the correction would cost more than half saves
  SectionOf<__m512d> s[NS];
  load_sections(c, s);
  __m512d z0[NS], z1[NS];
  const __m256d zero4 = _mm256_setzero_pd();
  for (int r = 0; r < NS; ++r) {
    z0[r] = join(_mm256_loadu_pd(z + 8 * r), zero4);
    z1[r] = join(_mm256_loadu_pd(z + 8 * r + 4), zero4);
  }
  for (Index n = 0; n < h; ++n) {
    const __m512d y = link(s, z0, z1, join(read(n), read(h + n)));
    write(n, _mm512_castpd512_pd256(y));
    write(h + n, _mm512_extractf64x4_pd(y, 1));
  }
  // The first half's final state: the second half's true initial state.
  __m256d f0[NS], f1[NS];
  for (int r = 0; r < NS; ++r) {
    f0[r] = _mm512_castpd512_pd256(z0[r]);
    f1[r] = _mm512_castpd512_pd256(z1[r]);
  }
  if (count - h > h) {  // an odd count: the second half's last sample (its input in the high lanes)
    const __m512d y = link(s, z0, z1, join(zero4, read(count - 1)));
    write(count - 1, _mm512_extractf64x4_pd(y, 1));
  }
  // The final state: the second half's (its correction has died out by its end).
  for (int r = 0; r < NS; ++r) {
    _mm256_storeu_pd(z + 8 * r, _mm512_extractf64x4_pd(z0[r], 1));
    _mm256_storeu_pd(z + 8 * r + 4, _mm512_extractf64x4_pd(z1[r], 1));
  }
  // The correction: the cascade from the first half's final state, with no input.
  SectionOf<__m256d> s4[NS];
  load_sections(c, s4);
  for (Index n = 0; n < decay; ++n) add(h + n, link(s4, f0, f1, zero4));
  return true;
}

template <int NS>
struct InPlace {
  static bool run(const double* c, double* z, double* x, Index count, int step) {
    const auto at = [=](Index n) { return x + n * step * 4; };  // never one past either end
    return halves<NS>(
        c, z, count, [=](Index n) { return _mm256_loadu_pd(at(n)); }, [=](Index n, __m256d y) { _mm256_storeu_pd(at(n), y); },
        [=](Index n, __m256d y) { _mm256_storeu_pd(at(n), _mm256_add_pd(_mm256_loadu_pd(at(n)), y)); });
  }
};

template <int NS>
struct Gather {
  static bool run(const double* c, double* z, const double* const* in, Index count, double* out) {
    const double *in0 = in[0], *in1 = in[1], *in2 = in[2], *in3 = in[3];
    return halves<NS>(
        c, z, count, [=](Index n) { return _mm256_set_pd(in3[n], in2[n], in1[n], in0[n]); },
        [=](Index n, __m256d y) { _mm256_storeu_pd(out + 4 * n, y); },
        [=](Index n, __m256d y) { _mm256_storeu_pd(out + 4 * n, _mm256_add_pd(_mm256_loadu_pd(out + 4 * n), y)); });
  }
};

}  // namespace

bool cascade4_halves_avx512(const double* coefficients, int sections, double* z, double* x, std::ptrdiff_t count, int step) {
  constexpr std::ptrdiff_t kShortest = 8192;  // below this, halves save less than the correction costs
  return count >= kShortest && by_count<InPlace, 4>(sections, coefficients, z, x, count, step);
}

bool cascade4_gather_halves_avx512(const double* coefficients, int sections, double* z, const double* const in[4],
                                   std::ptrdiff_t count, double* out) {
  constexpr std::ptrdiff_t kShortest = 8192;
  return count >= kShortest && by_count<Gather, 4>(sections, coefficients, z, in, count, out);
}

#else  // not built for AVX-512: the AVX2 kernels or the portable loops run

bool cascade4_halves_avx512(const double*, int, double*, double*, std::ptrdiff_t, int) { return false; }
bool cascade4_gather_halves_avx512(const double*, int, double*, const double* const[4], std::ptrdiff_t, double*) { return false; }

#endif

}  // namespace frictionlab::detail
