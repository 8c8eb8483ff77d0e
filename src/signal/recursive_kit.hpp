#pragma once
// What both recursive-filter kernel files share (recursive_kernels_fma.cpp four lanes wide,
// recursive_kernels_avx512.cpp eight): one sample through a cascade of second-order sections in
// fused multiply-adds at any vector width, and the run-time choice of a compile-time count.
// Private to those two files and in an anonymous namespace on purpose: each gets its own copy,
// built with its own instruction set (recursive_kernels.hpp says why no inline function may be
// shared between them).

#include <immintrin.h>

// GCC drops the vector types' alignment attribute from template arguments and says so; the
// members of SectionOf keep it.
#pragma GCC diagnostic ignored "-Wignored-attributes"

namespace frictionlab::detail {
namespace {

// F<n>::run(args...) for the n in 1..Max given at run time; false for any other n.
template <template <int> class F, int Max, class... Args>
bool by_count(int n, Args... args) {
  if constexpr (Max == 0) {
    return false;
  } else {
    return n == Max ? F<Max>::run(args...) : by_count<F, Max - 1>(n, args...);
  }
}

inline __m256d fmadd(__m256d a, __m256d b, __m256d c) { return _mm256_fmadd_pd(a, b, c); }
inline __m256d mul(__m256d a, __m256d b) { return _mm256_mul_pd(a, b); }
inline __m256d broadcast(double v, __m256d) { return _mm256_set1_pd(v); }
#if defined(__AVX512F__)
inline __m512d fmadd(__m512d a, __m512d b, __m512d c) { return _mm512_fmadd_pd(a, b, c); }
inline __m512d mul(__m512d a, __m512d b) { return _mm512_mul_pd(a, b); }
inline __m512d broadcast(double v, __m512d) { return _mm512_set1_pd(v); }
#endif

// One section's normalised coefficients (row b0 b1 b2 a0 a1 a2) broadcast to the lanes; a1 and
// a2 negated so that each state update is one fused multiply-add.
template <class V>
struct SectionOf {
  V b0, b1, b2, na1, na2;
};

template <class V, int NS>
void load_sections(const double* c, SectionOf<V> (&s)[NS]) {
  for (int r = 0; r < NS; ++r) {
    const double* row = c + 6 * r;
    const V like{};
    s[r] = {broadcast(row[0], like), broadcast(row[1], like), broadcast(row[2], like), broadcast(-row[4], like),
            broadcast(-row[5], like)};
  }
}

// One sample through the NS sections. The chain from one sample to the next runs through
// out = b0 x + z0 and z0 = -a1 out + (b1 x + z1): two fused multiply-adds per section; the
// other products wait on nothing of this sample's recursion.
template <class V, int NS>
inline V link(const SectionOf<V> (&s)[NS], V (&z0)[NS], V (&z1)[NS], V cur) {
  for (int r = 0; r < NS; ++r) {
    const V out = fmadd(s[r].b0, cur, z0[r]);
    z0[r] = fmadd(s[r].na1, out, fmadd(s[r].b1, cur, z1[r]));
    z1[r] = fmadd(s[r].na2, out, mul(s[r].b2, cur));
    cur = out;
  }
  return cur;
}

}  // namespace
}  // namespace frictionlab::detail
