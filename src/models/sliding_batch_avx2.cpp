// The 4-wide AVX2 kernels of FrictionLaw::sliding(v, F): the kernel body of
// sliding_kernels_impl.hpp on __m256d with libmvec's AVX2 functions. Compiled with -mavx2 -mfma
// (CMakeLists.txt); called only on CPUs with both (sliding_batch.cpp).

#include <immintrin.h>

#include "sliding_kernels.hpp"

extern "C" {
__m256d _ZGVdN4v_exp(__m256d x);
__m256d _ZGVdN4v_expm1(__m256d x);
__m256d _ZGVdN4v_log(__m256d x);
__m256d _ZGVdN4v_atan(__m256d x);
}

namespace frictionlab::detail {
namespace {

// What sliding_kernels_impl.hpp needs: AVX2 vectors and libmvec's 4-wide functions.
struct Isa {
  using vec = __m256d;
  static vec broadcast(double x) { return _mm256_set1_pd(x); }
  static vec fma(vec a, vec b, vec c) { return _mm256_fmadd_pd(a, b, c); }
  static vec min(vec a, vec b) { return _mm256_min_pd(a, b); }
  static vec max(vec a, vec b) { return _mm256_max_pd(a, b); }
  static vec exp(vec x) { return _ZGVdN4v_exp(x); }
  static vec expm1(vec x) { return _ZGVdN4v_expm1(x); }
  static vec log(vec x) { return _ZGVdN4v_log(x); }
  static vec atan(vec x) { return _ZGVdN4v_atan(x); }
};

}  // namespace
}  // namespace frictionlab::detail

#include "sliding_kernels_impl.hpp"

namespace frictionlab::detail {
constinit const KernelSet avx2_kernels = kKernels;
}  // namespace frictionlab::detail
