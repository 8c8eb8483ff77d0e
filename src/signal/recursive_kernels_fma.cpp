// Built with -mavx2 -mfma where CMakeLists.txt can (x86-64, GCC or Clang); see recursive_kernels.hpp.
// Nothing here may call an inline function of another header (see there): plain arrays, intrinsics
// and recursive_kit.hpp, whose functions are private to each file that includes it.
#include "recursive_kernels.hpp"

#if defined(__AVX2__) && defined(__FMA__)
#include "recursive_kit.hpp"
#endif

namespace frictionlab::detail {

#if defined(__AVX2__) && defined(__FMA__)
namespace {

using Index = std::ptrdiff_t;

// The cascade over `count` samples from `read(n)` to `write(n, y)`: interleaved in place, or
// gathered from four arrays. States and coefficients stay in registers for the loop.
template <int NS, class Read, class Write>
void run_cascade(const double* c, double* z, Index count, Read read, Write write) {
  SectionOf<__m256d> s[NS];
  load_sections(c, s);
  __m256d z0[NS], z1[NS];
  for (int r = 0; r < NS; ++r) {
    z0[r] = _mm256_loadu_pd(z + 8 * r);
    z1[r] = _mm256_loadu_pd(z + 8 * r + 4);
  }
  for (Index n = 0; n < count; ++n) write(n, link(s, z0, z1, read(n)));
  for (int r = 0; r < NS; ++r) {
    _mm256_storeu_pd(z + 8 * r, z0[r]);
    _mm256_storeu_pd(z + 8 * r + 4, z1[r]);
  }
}

template <int NS>
struct InPlace {
  static bool run(const double* c, double* z, double* x, Index count, int step) {
    run_cascade<NS>(
        c, z, count, [=](Index n) { return _mm256_loadu_pd(x + n * step * 4); },  // never one past either end
        [=](Index n, __m256d y) { _mm256_storeu_pd(x + n * step * 4, y); });
    return true;
  }
};

template <int NS>
struct Gather {
  static bool run(const double* c, double* z, const double* const* in, Index count, double* out) {
    const double *in0 = in[0], *in1 = in[1], *in2 = in[2], *in3 = in[3];
    run_cascade<NS>(
        c, z, count, [=](Index n) { return _mm256_set_pd(in3[n], in2[n], in1[n], in0[n]); },
        [=](Index n, __m256d y) { _mm256_storeu_pd(out + 4 * n, y); });
    return true;
  }
};

// Direct form II transposed of order K, one channel: y = b0 x + z0 and z0 = -a1 y + (b1 x + z1)
// are the chain, one fused multiply-add each.
template <int K>
struct Order {
  static bool run(const double* bc, const double* ac, double* zp, double* x, Index count, int step) {
    double b[K + 1], na[K + 1], z[K];
    for (int i = 0; i <= K; ++i) {
      b[i] = bc[i];
      na[i] = -ac[i];
    }
    for (int i = 0; i < K; ++i) z[i] = zp[i];
    for (Index n = 0; n < count; ++n) {
      double* const at = x + n * step;  // never formed one past either end
      const double xn = *at;
      const double yn = __builtin_fma(b[0], xn, z[0]);
      for (int i = 0; i + 1 < K; ++i) z[i] = __builtin_fma(na[i + 1], yn, __builtin_fma(b[i + 1], xn, z[i + 1]));
      z[K - 1] = __builtin_fma(na[K], yn, b[K] * xn);
      *at = yn;
    }
    for (int i = 0; i < K; ++i) zp[i] = z[i];
    return true;
  }
};

// The same filter over four stretches of x at once (one per lane), for one long channel. Lane j
// filters block j from a zero state (block 0 from z); block j's true output adds the response
// to its true initial state with no input, which the filter forgets: after `decay` samples it is
// below 2^-70 of that state (decay_length), so only that stretch is added, and each block's true
// initial state is the previous block's zero-state final state (the previous correction having
// died out within its block). Exact but for those forgotten 2^-70 and rounding; four times
// fewer links on the chain. Declines (false) when the record is short or the filter's memory long.
template <int K>
struct Blocks {
  // Samples after which the state of the input-free recursion, started from any unit state,
  // stays below 2^-70 (checked over a further `decay` samples); 0 when longer than `limit`.
  static Index decay_length(const double* na, Index limit) {
    // The last filter's answer is kept per thread: the same low-pass comes back every call.
    thread_local double last_na[K + 1];
    thread_local Index last_limit = -1, last_decay = 0;
    bool same = last_limit == limit;
    for (int i = 0; same && i <= K; ++i) same = last_na[i] == na[i];
    if (same) return last_decay;
    const Index found = search_decay(na, limit);
    for (int i = 0; i <= K; ++i) last_na[i] = na[i];
    last_limit = limit;
    last_decay = found;
    return found;
  }

  static Index search_decay(const double* na, Index limit) {
    Index longest = 0;
    for (int unit = 0; unit < K; ++unit) {
      double z[K] = {};
      z[unit] = 1.0;
      Index quiet_since = -1;
      for (Index n = 0; n < 2 * limit + 2; ++n) {  // a quiet_since up to limit gets its whole check
        const double y = z[0];
        double size = 0;
        for (int i = 0; i + 1 < K; ++i) {
          z[i] = __builtin_fma(na[i + 1], y, z[i + 1]);
          size = size > __builtin_fabs(z[i]) ? size : __builtin_fabs(z[i]);
        }
        z[K - 1] = na[K] * y;
        size = size > __builtin_fabs(z[K - 1]) ? size : __builtin_fabs(z[K - 1]);
        constexpr double kForgotten = 0x1p-70;
        if (size >= kForgotten) quiet_since = -1;
        else if (quiet_since < 0) quiet_since = n;
        if (quiet_since >= 0 && n >= 2 * quiet_since + 1) break;  // quiet as long again as it took
      }
      if (quiet_since < 0 || quiet_since > limit) return 0;  // never quiet, or not checked to the end
      longest = longest > quiet_since + 1 ? longest : quiet_since + 1;
    }
    return longest;
  }

  static bool run(const double* bc, const double* ac, double* zp, double* x, Index count, int step) {
    constexpr Index kShortest = 4096;  // below this, four blocks save less than the corrections cost
    if (count < kShortest) return false;
    double b[K + 1], na[K + 1];
    for (int i = 0; i <= K; ++i) {
      b[i] = bc[i];
      na[i] = -ac[i];
    }
    const Index L = count / 4;
    const Index decay = decay_length(na, L / 2);
    if (decay == 0) return false;
    // Pass 1: block j = samples [j L, (j + 1) L) in lane j; block 3 goes on to the end below.
    __m256d bv[K + 1], nav[K + 1], z[K];
    for (int i = 0; i <= K; ++i) {
      bv[i] = _mm256_set1_pd(b[i]);
      nav[i] = _mm256_set1_pd(na[i]);
    }
    for (int i = 0; i < K; ++i) z[i] = _mm256_set_pd(0.0, 0.0, 0.0, zp[i]);
    double* const p0 = x;
    double* const p1 = x + L * step;
    double* const p2 = x + 2 * L * step;
    double* const p3 = x + 3 * L * step;
    for (Index n = 0; n < L; ++n) {
      const Index o = n * step;
      const __m256d xn = _mm256_set_pd(p3[o], p2[o], p1[o], p0[o]);
      const __m256d yn = _mm256_fmadd_pd(bv[0], xn, z[0]);
      for (int i = 0; i + 1 < K; ++i) z[i] = _mm256_fmadd_pd(nav[i + 1], yn, _mm256_fmadd_pd(bv[i + 1], xn, z[i + 1]));
      z[K - 1] = _mm256_fmadd_pd(nav[K], yn, _mm256_mul_pd(bv[K], xn));
      alignas(32) double y[4];
      _mm256_store_pd(y, yn);
      p0[o] = y[0];
      p1[o] = y[1];
      p2[o] = y[2];
      p3[o] = y[3];
    }
    // The zero-state final states: block j + 1's true initial state is block j's.
    alignas(32) double end[K][4];
    for (int i = 0; i < K; ++i) _mm256_store_pd(end[i], z[i]);
    // Block 3's last count - 4 L samples (0 to 3), on from lane 3's state.
    double z3[K];
    for (int i = 0; i < K; ++i) z3[i] = end[i][3];
    for (Index n = 4 * L; n < count; ++n) {
      double* const at = x + n * step;
      const double xn = *at;
      const double yn = __builtin_fma(b[0], xn, z3[0]);
      for (int i = 0; i + 1 < K; ++i) z3[i] = __builtin_fma(na[i + 1], yn, __builtin_fma(b[i + 1], xn, z3[i + 1]));
      z3[K - 1] = __builtin_fma(na[K], yn, b[K] * xn);
      *at = yn;
    }
    // Pass 2: blocks 1..3 (lanes 1..3) add the input-free response to their true initial state.
    for (int i = 0; i < K; ++i) z[i] = _mm256_set_pd(end[i][2], end[i][1], end[i][0], 0.0);
    for (Index n = 0; n < decay; ++n) {
      const Index o = n * step;
      const __m256d yn = z[0];
      for (int i = 0; i + 1 < K; ++i) z[i] = _mm256_fmadd_pd(nav[i + 1], yn, z[i + 1]);
      z[K - 1] = _mm256_mul_pd(nav[K], yn);
      alignas(32) double y[4];
      _mm256_store_pd(y, yn);
      p1[o] += y[1];
      p2[o] += y[2];
      p3[o] += y[3];
    }
    for (int i = 0; i < K; ++i) zp[i] = z3[i];  // block 3's correction has died out by its end
    return true;
  }
};

}  // namespace

bool cascade4_fma(const double* coefficients, int sections, double* z, double* x, std::ptrdiff_t count, int step) {
  return by_count<InPlace, 8>(sections, coefficients, z, x, count, step);
}

bool cascade4_gather_fma(const double* coefficients, int sections, double* z, const double* const in[4],
                         std::ptrdiff_t count, double* out) {
  return by_count<Gather, 8>(sections, coefficients, z, in, count, out);
}

bool lfilter_fma(const double* b, const double* a, int order, double* z, double* x, std::ptrdiff_t count, int step) {
  return by_count<Order, 8>(order, b, a, z, x, count, step);
}

bool lfilter_blocks_fma(const double* b, const double* a, int order, double* z, double* x, std::ptrdiff_t count, int step) {
  return by_count<Blocks, 8>(order, b, a, z, x, count, step);
}

#else  // not built for AVX2 and FMA: filtfilt.cpp runs its portable loops

bool cascade4_fma(const double*, int, double*, double*, std::ptrdiff_t, int) { return false; }
bool cascade4_gather_fma(const double*, int, double*, const double* const[4], std::ptrdiff_t, double*) { return false; }
bool lfilter_fma(const double*, const double*, int, double*, double*, std::ptrdiff_t, int) { return false; }
bool lfilter_blocks_fma(const double*, const double*, int, double*, double*, std::ptrdiff_t, int) { return false; }

#endif

}  // namespace frictionlab::detail
