// The 8-wide AVX-512 kernels of FrictionLaw::sliding(v, F): the kernel body of
// sliding_kernels_impl.hpp on __m512d with libmvec's AVX-512 functions. Compiled with -mavx512f
// -mavx2 -mfma (CMakeLists.txt); called only on CPUs with AVX-512F, AVX2 and FMA
// (sliding_batch.cpp).

#include <immintrin.h>

#include "sliding_kernels.hpp"

extern "C" {
__m512d _ZGVeN8v_exp(__m512d x);
__m512d _ZGVeN8v_expm1(__m512d x);
__m512d _ZGVeN8v_log(__m512d x);
__m512d _ZGVeN8v_atan(__m512d x);
}

namespace frictionlab::detail {
namespace {

// What sliding_kernels_impl.hpp needs: AVX-512 vectors and libmvec's 8-wide functions.
struct Isa {
  using vec = __m512d;
  static vec broadcast(double x) { return _mm512_set1_pd(x); }
  static vec fma(vec a, vec b, vec c) { return _mm512_fmadd_pd(a, b, c); }
  // The masked forms with every lane set: GCC 12's _mm512_min_pd reads an uninitialised
  // register (_mm512_undefined_pd) and warns at every call.
  static vec min(vec a, vec b) { return _mm512_mask_min_pd(a, 0xFF, a, b); }
  static vec max(vec a, vec b) { return _mm512_mask_max_pd(a, 0xFF, a, b); }
  static vec exp(vec x) { return _ZGVeN8v_exp(x); }
  static vec expm1(vec x) { return _ZGVeN8v_expm1(x); }
  static vec log(vec x) { return _ZGVeN8v_log(x); }
  static vec atan(vec x) { return _ZGVeN8v_atan(x); }
};

}  // namespace
}  // namespace frictionlab::detail

#include "sliding_kernels_impl.hpp"

namespace frictionlab::detail {
constinit const KernelSet avx512_kernels = kKernels;
}  // namespace frictionlab::detail
