// The one body of the vector kernels of FrictionLaw::sliding(v, F) for the laws with
// transcendental functions (stribeck, stribeck-asymmetric, smooth), private to
// sliding_batch_avx2.cpp (4 wide, compiled with -mavx2 -mfma) and sliding_batch_avx512.cpp (8
// wide, -mavx512f -mavx2 -mfma), the only files that include it. The formulas, cut-offs and
// parameterisation are the scalar laws' (stribeck.hpp, smooth.hpp, scalar.hpp); only the rounding
// differs.
//
// The including file defines, in namespace frictionlab::detail::{anonymous}, a struct `Isa`:
//   using vec = __m256d or __m512d;        a GCC / Clang vector of doubles
//   static vec broadcast(double x);        x in every lane
//   static vec fma(vec a, vec b, vec c);   a b + c, one rounding
//   static vec min(vec a, vec b), max(vec a, vec b);  minpd / maxpd: b where either is NaN
//   static vec exp(vec), log(vec), expm1(vec), atan(vec);  libmvec's functions of that width
// Everything else is written once on the vector extensions: + - * / lane by lane (a scalar
// operand stands for itself in every lane), comparisons give a lane mask (all bits set where
// true) and `mask ? a : b` selects lane by lane.
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
// log, exp, exp of delta = 1.5 then takes 2.4 instead of 3.7 ns per value 4 wide on the
// development machine: one function in a loop runs at its full throughput, several in turn do
// not).
//
// Everything here has internal linkage (anonymous namespace): each including file gets its own
// copy, compiled with its own instructions, and the linker cannot keep one file's copy for the
// other's callers. Only constants are taken from the law headers, and no library function is
// called (see sliding_kernels.hpp for why); the tables at the end are the files' entry points.

#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>

#include "frictionlab/models/scalar.hpp"
#include "frictionlab/models/smooth.hpp"
#include "sliding_kernels.hpp"

namespace frictionlab::detail {
namespace {

using vec = Isa::vec;
using Mask = decltype(vec{} < vec{});  // 64-bit integer lanes, as comparisons give them
constexpr std::size_t kWidth = sizeof(vec) / sizeof(double);

constexpr std::size_t kBlock = 64;  // values per pass: 512 bytes per buffer, in L1 throughout
static_assert(kBlock % kWidth == 0);
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr std::int64_t kSignBit = std::numeric_limits<std::int64_t>::min();
// Past this, exp(y) is 0 or huge for the decay either way (exp(-exp(-700)) rounds to 1, and
// exp(700) > 40 cuts the decay to 0); inside it libmvec's exp stays on its fast path.
constexpr double kExpArgumentLimit = 700.0;

vec broadcast(double x) { return Isa::broadcast(x); }
vec load(const double* p) {
  vec x;
  std::memcpy(&x, p, sizeof x);  // an unaligned load
  return x;
}
void store(double* p, vec x) { std::memcpy(p, &x, sizeof x); }

// Sign-bit operations: exact. (-x, the vector extensions' negation, flips the sign bit too.)
Mask bits(vec x) { return __builtin_bit_cast(Mask, x); }
vec from_bits(Mask b) { return __builtin_bit_cast(vec, b); }
vec abs(vec x) { return from_bits(bits(x) & ~kSignBit); }
vec copysign(vec magnitude, vec sign) { return from_bits(bits(magnitude) | (bits(sign) & kSignBit)); }

// One Stribeck parameter set in every lane. v / vs is computed as v (1 / vs): one rounding more
// (x within an ulp of the quotient) for a multiplication in place of a division per value.
struct Side {
  vec Fc, dF, inv_vs, delta, Fv;

  explicit Side(const StribeckSide& s)
      : Fc(broadcast(s.Fc)), dF(broadcast(s.Fs - s.Fc)), inv_vs(broadcast(1.0 / s.vs)), delta(broadcast(s.delta)),
        Fv(broadcast(s.Fv)) {}
  Side(vec Fc_, vec dF_, vec inv_vs_, vec delta_, vec Fv_) : Fc(Fc_), dF(dF_), inv_vs(inv_vs_), delta(delta_), Fv(Fv_) {}

  const Side& at(vec) const { return *this; }
};

// Two sets, each lane taking the one of its velocity's sign.
struct Sides {
  Side pos, neg;

  Side at(vec v) const {
    const Mask p = v >= 0.0;  // -0 is positive, NaN negative, as in Asymmetric::sliding
    return {p ? pos.Fc : neg.Fc, p ? pos.dF : neg.dF, p ? pos.inv_vs : neg.inv_vs, p ? pos.delta : neg.delta,
            p ? pos.Fv : neg.Fv};
  }
};

// exp(-min(u, 40)), then 0 where u > 40 (stribeck_decay's cut-off): exp never sees an argument
// below -40. A NaN u gives min = 40; the NaN reaches F through Fv v.
vec cut_decay(vec u) {
  const vec limit = broadcast(kNegligibleDecayExponent);
  const vec e = Isa::exp(-Isa::min(u, limit));
  return u > limit ? vec{} : e;
}

// decay[i] = exp(-|v[i]/vs|^delta) for i < m (a multiple of kWidth), as stribeck_decay computes
// it; 0 for Decay::none (whose dF is 0). `scratch` holds m values.
template <Decay D, class Params>
void decay_block(const Params& params, const double* v, std::size_t m, double* decay, double* scratch) {
  if constexpr (D == Decay::none) {
    for (std::size_t i = 0; i < m; i += kWidth) store(decay + i, vec{});
  } else if constexpr (D == Decay::power) {
    // |x|^delta = exp(delta log|x|) in three passes: y = delta log|x| (clamped), u = exp(y), the
    // decay. Lanes with |x| = 0, inf or NaN take u = |x| (0 gives a decay of 1, inf one of 0, as
    // the scalar's), and log gets 1 there.
    auto finite_positive = [](vec a) { return (a > 0.0) & (a < kInfinity); };
    for (std::size_t i = 0; i < m; i += kWidth) {
      const vec vi = load(v + i);
      const Side& p = params.at(vi);
      const vec a = abs(vi * p.inv_vs);
      const vec y = p.delta * Isa::log(finite_positive(a) ? a : broadcast(1.0));
      store(scratch + i, a);
      store(decay + i, Isa::min(Isa::max(y, broadcast(-kExpArgumentLimit)), broadcast(kExpArgumentLimit)));
    }
    for (std::size_t i = 0; i < m; i += kWidth) {
      const vec a = load(scratch + i);
      store(decay + i, finite_positive(a) ? Isa::exp(load(decay + i)) : a);
    }
    for (std::size_t i = 0; i < m; i += kWidth) store(decay + i, cut_decay(load(decay + i)));
  } else {
    for (std::size_t i = 0; i < m; i += kWidth) {
      const vec vi = load(v + i);
      const vec x = vi * params.at(vi).inv_vs;
      store(decay + i, cut_decay(D == Decay::gaussian ? x * x : abs(x)));
    }
  }
}

// F where v != 0, the scalar law's value for that sign of zero where v == 0.
vec with_zero(vec v, vec F, AtZero zero) {
  const vec at_zero = bits(v) < 0 ? broadcast(zero.minus) : broadcast(zero.plus);  // by v's sign bit
  return v == 0.0 ? at_zero : F;
}

// sign(v) (Fc + (Fs - Fc) decay) + Fv v, for one side (Side) or two (Sides).
template <Decay D, class Params>
void stribeck_loop(const Params& params, AtZero zero, const double* v, double* F, std::size_t n) {
  alignas(sizeof(vec)) double decay[kBlock], scratch[kBlock];
  for (std::size_t b = 0; b < n; b += kBlock) {
    const std::size_t m = n - b < kBlock ? n - b : kBlock;
    const double* vb = v + b;
    decay_block<D>(params, vb, m, decay, scratch);
    for (std::size_t i = 0; i < m; i += kWidth) {
      const vec vi = load(vb + i);
      const Side& p = params.at(vi);
      const vec level = Isa::fma(p.dF, load(decay + i), p.Fc);
      const vec Fi = Isa::fma(copysign(broadcast(1.0), vi), level, p.Fv * vi);
      store(F + b + i, with_zero(vi, Fi, zero));
    }
  }
}

// The smooth sign s(x): (2/pi) atan(x), or tanh(x) as smooth.hpp computes it: -m / (2 + m) with
// m = expm1(-2|x|), the argument clamped at -40 (tanh rounds to 1 there), the sign of x applied
// last. libmvec's expm1 and a division cost less than half its tanh.
template <bool kAtan>
vec smooth_sign(vec x) {
  if constexpr (kAtan) {
    return (2.0 / std::numbers::pi) * Isa::atan(x);
  } else {
    const vec m = Isa::expm1(-Isa::min(2.0 * abs(x), broadcast(kTanhSaturation)));
    return copysign(-m / (2.0 + m), x);
  }
}

// s(v/vt) (Fc + (Fs - Fc) decay) + Fv v; with Decay::none the level is Fc.
template <Decay D, bool kAtan>
void smooth_loop(const Side& p, double vt, AtZero zero, const double* v, double* F, std::size_t n) {
  alignas(sizeof(vec)) double decay[kBlock], sign[kBlock], scratch[kBlock];
  const vec inv_vt = broadcast(1.0 / vt);  // v / vt as v (1 / vt), as v / vs (Side)
  for (std::size_t b = 0; b < n; b += kBlock) {
    const std::size_t m = n - b < kBlock ? n - b : kBlock;
    const double* vb = v + b;
    if constexpr (D != Decay::none) decay_block<D>(p, vb, m, decay, scratch);
    for (std::size_t i = 0; i < m; i += kWidth) store(sign + i, smooth_sign<kAtan>(load(vb + i) * inv_vt));
    for (std::size_t i = 0; i < m; i += kWidth) {
      const vec vi = load(vb + i);
      const vec s = load(sign + i);
      vec level = p.Fc;
      if constexpr (D != Decay::none) level = Isa::fma(p.dF, load(decay + i), p.Fc);
      store(F + b + i, with_zero(vi, Isa::fma(s, level, p.Fv * vi), zero));
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

void stribeck_sliding(const StribeckSide& law, AtZero zero, const double* v, double* F, std::size_t n) {
  with_decay(law.decay, [&]<Decay D>() { stribeck_loop<D>(Side(law), zero, v, F, n); });
}

void asymmetric_stribeck_sliding(const StribeckSide& pos, const StribeckSide& neg, AtZero zero, const double* v,
                                 double* F, std::size_t n) {
  // One decay pass on per-lane parameters, in a form both sides can take: a side without a dip
  // (none: Fs = Fc) takes any, and two different forms take power, which gives the scalar's
  // |x| and x^2 for delta = 1 and 2 up to rounding (within the power form's own error bound).
  const Decay shared = pos.decay == neg.decay || neg.decay == Decay::none ? pos.decay
                       : pos.decay == Decay::none                       ? neg.decay
                                                                        : Decay::power;
  with_decay(shared, [&]<Decay D>() { stribeck_loop<D>(Sides{Side(pos), Side(neg)}, zero, v, F, n); });
}

void smooth_sliding(const StribeckSide& level, double vt, bool atan_shape, AtZero zero, const double* v, double* F,
                    std::size_t n) {
  with_decay(level.decay, [&]<Decay D>() {
    if (atan_shape) {
      smooth_loop<D, true>(Side(level), vt, zero, v, F, n);
    } else {
      smooth_loop<D, false>(Side(level), vt, zero, v, F, n);
    }
  });
}

// The including file's table: `constinit const KernelSet <set>_kernels = kKernels;`.
constexpr KernelSet kKernels = {kWidth, &stribeck_sliding, &asymmetric_stribeck_sliding, &smooth_sliding};

}  // namespace
}  // namespace frictionlab::detail
