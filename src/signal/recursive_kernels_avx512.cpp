// Built with -mavx512f -mavx2 -mfma where CMakeLists.txt can (x86-64, GCC or Clang); see
// recursive_kernels.hpp. Nothing here may call an inline function of another header (see there).
#include "recursive_kernels.hpp"

#if defined(__AVX512F__) && defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#endif

namespace frictionlab::detail {

#if defined(__AVX512F__) && defined(__AVX2__) && defined(__FMA__)
namespace {

using Index = std::ptrdiff_t;

// One section's coefficients broadcast to eight lanes, a1 and a2 negated (as in the FMA file).
struct Section8 {
  __m512d b0, b1, b2, na1, na2;
};

template <int NS>
inline __m512d link8(const Section8 (&s)[NS], __m512d (&z0)[NS], __m512d (&z1)[NS], __m512d cur) {
  for (int r = 0; r < NS; ++r) {
    const __m512d out = _mm512_fmadd_pd(s[r].b0, cur, z0[r]);
    z0[r] = _mm512_fmadd_pd(s[r].na1, out, _mm512_fmadd_pd(s[r].b1, cur, z1[r]));
    z1[r] = _mm512_fmadd_pd(s[r].na2, out, _mm512_mul_pd(s[r].b2, cur));
    cur = out;
  }
  return cur;
}

template <int NS>
void load_sections(const double* c, Section8 (&s)[NS]) {
  for (int r = 0; r < NS; ++r) {
    const double* row = c + 6 * r;
    s[r] = {_mm512_set1_pd(row[0]), _mm512_set1_pd(row[1]), _mm512_set1_pd(row[2]), _mm512_set1_pd(-row[4]),
            _mm512_set1_pd(-row[5])};
  }
}

inline __m512d join(__m256d low, __m256d high) { return _mm512_insertf64x4(_mm512_castpd256_pd512(low), high, 1); }

// Samples after which the cascade's state, run with no input from any unit state, stays below
// 2^-70 (and below 2^-64 for a quarter as long again); 0 when that takes more than 2^16.
// Lane u starts from unit state u (lanes are the 2 NS <= 8 states), so one run covers them all.
// The last filter's answer is kept per thread: the same decimation filter comes back every call.
template <int NS>
Index decay_length(const double* c) {
  thread_local double last_c[6 * 8];
  thread_local int last_ns = 0;
  thread_local Index last_decay = 0;
  bool same = last_ns == NS;
  for (int i = 0; same && i < 6 * NS; ++i) same = last_c[i] == c[i];
  if (same) return last_decay;
  Section8 s[NS];
  load_sections<NS>(c, s);
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
  for (Index n = 0; n < kLongest; n += kEvery) {
    for (Index i = 0; i < kEvery; ++i) link8<NS>(s, z0, z1, _mm512_setzero_pd());
    const double size = largest();
    if (decay == 0 && size < 0x1p-70) decay = n + kEvery;
    if (decay > 0 && size >= 0x1p-64) decay = -1;  // came back: not a filter to split
    if (decay != 0 && (decay < 0 || n + kEvery >= decay + decay / 4)) break;
  }
  const Index found = decay > 0 ? decay : 0;
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
  Section8 s[NS];
  load_sections<NS>(c, s);
  __m512d z0[NS], z1[NS];
  const __m256d zero4 = _mm256_setzero_pd();
  for (int r = 0; r < NS; ++r) {
    z0[r] = join(_mm256_loadu_pd(z + 8 * r), zero4);
    z1[r] = join(_mm256_loadu_pd(z + 8 * r + 4), zero4);
  }
  for (Index n = 0; n < h; ++n) {
    const __m512d y = link8<NS>(s, z0, z1, join(read(n), read(h + n)));
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
    const __m512d y = link8<NS>(s, z0, z1, join(zero4, read(count - 1)));
    write(count - 1, _mm512_extractf64x4_pd(y, 1));
  }
  // The final state: the second half's (its correction has died out by its end).
  for (int r = 0; r < NS; ++r) {
    _mm256_storeu_pd(z + 8 * r, _mm512_extractf64x4_pd(z0[r], 1));
    _mm256_storeu_pd(z + 8 * r + 4, _mm512_extractf64x4_pd(z1[r], 1));
  }
  // The correction: the cascade from the first half's final state, with no input.
  for (Index n = 0; n < decay; ++n) {
    __m256d cur = zero4;
    for (int r = 0; r < NS; ++r) {
      const __m256d b0 = _mm512_castpd512_pd256(s[r].b0), b1 = _mm512_castpd512_pd256(s[r].b1),
                    b2 = _mm512_castpd512_pd256(s[r].b2), na1 = _mm512_castpd512_pd256(s[r].na1),
                    na2 = _mm512_castpd512_pd256(s[r].na2);
      const __m256d out = _mm256_fmadd_pd(b0, cur, f0[r]);
      f0[r] = _mm256_fmadd_pd(na1, out, _mm256_fmadd_pd(b1, cur, f1[r]));
      f1[r] = _mm256_fmadd_pd(na2, out, _mm256_mul_pd(b2, cur));
      cur = out;
    }
    add(h + n, cur);
  }
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

// F<n>::run(args...) for n = 1..4 (the eight lanes hold the 2 n states of the decay search);
// false for any other n.
template <template <int> class F, class... Args>
bool by_sections(int n, Args... args) {
  switch (n) {
    case 1: return F<1>::run(args...);
    case 2: return F<2>::run(args...);
    case 3: return F<3>::run(args...);
    case 4: return F<4>::run(args...);
    default: return false;
  }
}

}  // namespace

bool cascade4_halves_avx512(const double* coefficients, int sections, double* z, double* x, std::ptrdiff_t count, int step) {
  constexpr std::ptrdiff_t kShortest = 8192;  // below this, halves save less than the correction costs
  return count >= kShortest && by_sections<InPlace>(sections, coefficients, z, x, count, step);
}

bool cascade4_gather_halves_avx512(const double* coefficients, int sections, double* z, const double* const in[4],
                                   std::ptrdiff_t count, double* out) {
  constexpr std::ptrdiff_t kShortest = 8192;
  return count >= kShortest && by_sections<Gather>(sections, coefficients, z, in, count, out);
}

#else  // not built for AVX-512: the AVX2 kernels or the portable loops run

bool cascade4_halves_avx512(const double*, int, double*, double*, std::ptrdiff_t, int) { return false; }
bool cascade4_gather_halves_avx512(const double*, int, double*, const double* const[4], std::ptrdiff_t, double*) { return false; }

#endif

}  // namespace frictionlab::detail
