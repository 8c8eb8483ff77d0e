// 4-wide AVX2 kernels of FrictionLaw::sliding(v, F) for the laws with transcendental functions
// (stribeck, stribeck-asymmetric, smooth). Compiled with -mavx2 -mfma (CMakeLists.txt); called
// only on CPUs with both (sliding_batch.cpp). The formulas, cut-offs and parameterisation are the
// scalar laws' (stribeck.hpp, smooth.hpp, scalar.hpp); only the rounding differs.
//
// Vector exp, log, expm1 and atan come from glibc's libmvec, called explicitly (GCC 12 does not
// vectorise these loops reliably by itself): at most 4 ulp, part of glibc (libc6-dev), no extra
// package. Each function takes a slow scalar path (3 to 30 times slower) for lanes outside its
// fast range (exp below -708 or above 708, log of 0, of a subnormal, of inf or NaN; atan and
// expm1 below about 1e-30 in magnitude), so the kernels keep common arguments inside it: exp
// arguments are clamped and lanes whose value is known (a decay of 0 or 1) are selected
// afterwards, and log gets 1 in place of 0, inf and NaN. Only velocities below 1e-30 (times vt)
// take the slow paths, with correct results.
//
// Values go through in blocks, one vector function over the whole block at a time (the chain
// log, exp, exp of delta = 1.5 then takes 2.4 instead of 3.7 ns per value on the development
// machine: one function in a loop runs at its full throughput, several in turn do not).
//
// Only constants are taken from the law headers (see sliding_kernels.hpp for why no inline
// function is called here).

#include <immintrin.h>

#include <limits>
#include <numbers>

#include "frictionlab/models/scalar.hpp"
#include "frictionlab/models/smooth.hpp"
#include "sliding_kernels.hpp"

extern "C" {
__m256d _ZGVdN4v_exp(__m256d x);
__m256d _ZGVdN4v_expm1(__m256d x);
__m256d _ZGVdN4v_log(__m256d x);
__m256d _ZGVdN4v_atan(__m256d x);
}

namespace frictionlab::detail {
namespace {

constexpr std::size_t kBlock = 64;  // values per pass: 512 bytes per buffer, in L1 throughout
constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Past this, exp(y) is 0 or huge for the decay either way (exp(-exp(-700)) rounds to 1, and
// exp(700) > 40 cuts the decay to 0); inside it libmvec's exp stays on its fast path.
constexpr double kExpArgumentLimit = 700.0;

__m256d broadcast(double x) { return _mm256_set1_pd(x); }
__m256d load(const double* p) { return _mm256_loadu_pd(p); }
void store(double* p, __m256d x) { _mm256_storeu_pd(p, x); }

// Sign-bit operations: exact.
__m256d abs(__m256d x) { return _mm256_andnot_pd(broadcast(-0.0), x); }
__m256d negate(__m256d x) { return _mm256_xor_pd(broadcast(-0.0), x); }
__m256d copysign(__m256d magnitude, __m256d sign) {
  return _mm256_or_pd(magnitude, _mm256_and_pd(broadcast(-0.0), sign));
}

// v >= 0: the lanes of an asymmetric law's positive side (-0 is positive, NaN negative, as in
// Asymmetric::sliding).
__m256d is_positive_side(__m256d v) { return _mm256_cmp_pd(v, _mm256_setzero_pd(), _CMP_GE_OQ); }

// One Stribeck parameter set in every lane. v / vs is computed as v (1 / vs): one rounding more
// (x within an ulp of the quotient) for a multiplication in place of a division per value.
struct Side {
  __m256d Fc, dF, inv_vs, delta, Fv;

  explicit Side(const StribeckSide& s)
      : Fc(broadcast(s.Fc)), dF(broadcast(s.Fs - s.Fc)), inv_vs(broadcast(1.0 / s.vs)), delta(broadcast(s.delta)),
        Fv(broadcast(s.Fv)) {}
  Side(__m256d Fc_, __m256d dF_, __m256d inv_vs_, __m256d delta_, __m256d Fv_)
      : Fc(Fc_), dF(dF_), inv_vs(inv_vs_), delta(delta_), Fv(Fv_) {}

  const Side& at(__m256d) const { return *this; }
};

// Two sets, each lane taking the one of its velocity's sign.
struct Sides {
  Side pos, neg;

  Side at(__m256d v) const {
    const __m256d p = is_positive_side(v);
    return {_mm256_blendv_pd(neg.Fc, pos.Fc, p), _mm256_blendv_pd(neg.dF, pos.dF, p),
            _mm256_blendv_pd(neg.inv_vs, pos.inv_vs, p), _mm256_blendv_pd(neg.delta, pos.delta, p),
            _mm256_blendv_pd(neg.Fv, pos.Fv, p)};
  }
};

// exp(-min(u, 40)), then 0 where u > 40 (stribeck_decay's cut-off): exp never sees an argument
// below -40. A NaN u gives min = 40 (minpd returns its second operand); the NaN reaches F
// through Fv v.
__m256d cut_decay(__m256d u) {
  const __m256d limit = broadcast(kNegligibleDecayExponent);
  const __m256d e = _ZGVdN4v_exp(negate(_mm256_min_pd(u, limit)));
  return _mm256_andnot_pd(_mm256_cmp_pd(u, limit, _CMP_GT_OQ), e);
}

// decay[i] = exp(-|v[i]/vs|^delta) for i < m (a multiple of 4), as stribeck_decay computes it;
// 0 for Decay::none (whose dF is 0). `scratch` holds m values.
template <Decay D, class Params>
void decay_block(const Params& params, const double* v, std::size_t m, double* decay, double* scratch) {
  if constexpr (D == Decay::none) {
    for (std::size_t i = 0; i < m; i += 4) store(decay + i, _mm256_setzero_pd());
  } else if constexpr (D == Decay::power) {
    // |x|^delta = exp(delta log|x|) in three passes: y = delta log|x| (clamped), u = exp(y), the
    // decay. Lanes with |x| = 0, inf or NaN take u = |x| (0 gives a decay of 1, inf one of 0, as
    // the scalar's), and log gets 1 there.
    auto finite_positive = [](__m256d a) {
      return _mm256_and_pd(_mm256_cmp_pd(a, _mm256_setzero_pd(), _CMP_GT_OQ),
                           _mm256_cmp_pd(a, broadcast(kInfinity), _CMP_LT_OQ));
    };
    for (std::size_t i = 0; i < m; i += 4) {
      const __m256d vi = load(v + i);
      const Side& p = params.at(vi);
      const __m256d a = abs(_mm256_mul_pd(vi, p.inv_vs));
      const __m256d y = _mm256_mul_pd(p.delta, _ZGVdN4v_log(_mm256_blendv_pd(broadcast(1.0), a, finite_positive(a))));
      store(scratch + i, a);
      store(decay + i, _mm256_min_pd(_mm256_max_pd(y, broadcast(-kExpArgumentLimit)), broadcast(kExpArgumentLimit)));
    }
    for (std::size_t i = 0; i < m; i += 4) {
      const __m256d a = load(scratch + i);
      store(decay + i, _mm256_blendv_pd(a, _ZGVdN4v_exp(load(decay + i)), finite_positive(a)));
    }
    for (std::size_t i = 0; i < m; i += 4) store(decay + i, cut_decay(load(decay + i)));
  } else {
    for (std::size_t i = 0; i < m; i += 4) {
      const __m256d vi = load(v + i);
      const __m256d x = _mm256_mul_pd(vi, params.at(vi).inv_vs);
      store(decay + i, cut_decay(D == Decay::gaussian ? _mm256_mul_pd(x, x) : abs(x)));
    }
  }
}

// F where v != 0, the scalar law's value for that sign of zero where v == 0.
__m256d with_zero(__m256d v, __m256d F, AtZero zero) {
  const __m256d at_zero = _mm256_blendv_pd(broadcast(zero.plus), broadcast(zero.minus), v);  // by v's sign bit
  return _mm256_blendv_pd(F, at_zero, _mm256_cmp_pd(v, _mm256_setzero_pd(), _CMP_EQ_OQ));
}

// sign(v) (Fc + (Fs - Fc) decay) + Fv v, for one side (Side) or two (Sides).
template <Decay D, class Params>
void stribeck_loop(const Params& params, AtZero zero, const double* v, double* F, std::size_t n) {
  alignas(32) double decay[kBlock], scratch[kBlock];
  for (std::size_t b = 0; b < n; b += kBlock) {
    const std::size_t m = n - b < kBlock ? n - b : kBlock;
    const double* vb = v + b;
    decay_block<D>(params, vb, m, decay, scratch);
    for (std::size_t i = 0; i < m; i += 4) {
      const __m256d vi = load(vb + i);
      const Side& p = params.at(vi);
      const __m256d level = _mm256_fmadd_pd(p.dF, load(decay + i), p.Fc);
      const __m256d Fi = _mm256_fmadd_pd(copysign(broadcast(1.0), vi), level, _mm256_mul_pd(p.Fv, vi));
      store(F + b + i, with_zero(vi, Fi, zero));
    }
  }
}

// The smooth sign s(x): (2/pi) atan(x), or tanh(x) as smooth.hpp computes it: -m / (2 + m) with
// m = expm1(-2|x|), the argument clamped at -40 (tanh rounds to 1 there), the sign of x applied
// last. libmvec's expm1 and a division cost less than half its tanh.
template <bool kAtan>
__m256d smooth_sign(__m256d x) {
  if constexpr (kAtan) {
    return _mm256_mul_pd(broadcast(2.0 / std::numbers::pi), _ZGVdN4v_atan(x));
  } else {
    const __m256d two = broadcast(2.0);
    const __m256d m = _ZGVdN4v_expm1(negate(_mm256_min_pd(_mm256_mul_pd(two, abs(x)), broadcast(kTanhSaturation))));
    return copysign(_mm256_div_pd(negate(m), _mm256_add_pd(two, m)), x);
  }
}

// s(v/vt) (Fc + (Fs - Fc) decay) + Fv v; with Decay::none the level is Fc.
template <Decay D, bool kAtan>
void smooth_loop(const Side& p, double vt, AtZero zero, const double* v, double* F, std::size_t n) {
  alignas(32) double decay[kBlock], sign[kBlock], scratch[kBlock];
  const __m256d inv_vt = broadcast(1.0 / vt);  // v / vt as v (1 / vt), as v / vs (Side)
  for (std::size_t b = 0; b < n; b += kBlock) {
    const std::size_t m = n - b < kBlock ? n - b : kBlock;
    const double* vb = v + b;
    if constexpr (D != Decay::none) decay_block<D>(p, vb, m, decay, scratch);
    for (std::size_t i = 0; i < m; i += 4) store(sign + i, smooth_sign<kAtan>(_mm256_mul_pd(load(vb + i), inv_vt)));
    for (std::size_t i = 0; i < m; i += 4) {
      const __m256d vi = load(vb + i);
      const __m256d s = load(sign + i);
      __m256d level = p.Fc;
      if constexpr (D != Decay::none) level = _mm256_fmadd_pd(p.dF, load(decay + i), p.Fc);
      store(F + b + i, with_zero(vi, _mm256_fmadd_pd(s, level, _mm256_mul_pd(p.Fv, vi)), zero));
    }
  }
}

// Calls f.template operator()<D>() with the run-time decay form d as a template argument.
template <class Fn>
void with_decay(Decay d, Fn&& f) {
  switch (d) {
    case Decay::none: return f.template operator()<Decay::none>();
    case Decay::exponential: return f.template operator()<Decay::exponential>();
    case Decay::gaussian: return f.template operator()<Decay::gaussian>();
    case Decay::power: return f.template operator()<Decay::power>();
  }
}

}  // namespace

void stribeck_sliding_avx2(const StribeckSide& law, AtZero zero, const double* v, double* F, std::size_t n) {
  with_decay(law.decay, [&]<Decay D>() { stribeck_loop<D>(Side(law), zero, v, F, n); });
}

void asymmetric_stribeck_sliding_avx2(const StribeckSide& pos, const StribeckSide& neg, AtZero zero, const double* v,
                                      double* F, std::size_t n) {
  // One decay pass on per-lane parameters, in a form both sides can take: a side without a dip
  // (none: Fs = Fc) takes any, and two different forms take power, which gives the scalar's
  // |x| and x^2 for delta = 1 and 2 up to rounding (within the power form's own error bound).
  const Decay shared = pos.decay == neg.decay || neg.decay == Decay::none ? pos.decay
                       : pos.decay == Decay::none                       ? neg.decay
                                                                        : Decay::power;
  with_decay(shared, [&]<Decay D>() { stribeck_loop<D>(Sides{Side(pos), Side(neg)}, zero, v, F, n); });
}

void smooth_sliding_avx2(const StribeckSide& level, double vt, bool atan_shape, AtZero zero, const double* v, double* F,
                         std::size_t n) {
  with_decay(level.decay, [&]<Decay D>() {
    if (atan_shape) {
      smooth_loop<D, true>(Side(level), vt, zero, v, F, n);
    } else {
      smooth_loop<D, false>(Side(level), vt, zero, v, F, n);
    }
  });
}

}  // namespace frictionlab::detail
