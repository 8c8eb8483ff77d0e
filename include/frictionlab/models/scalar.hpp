#pragma once
// Scalar helpers shared by every friction law. They accept double and ceres::Jet alike,
// so one formula serves simulation (double) and fitting (automatic differentiation).

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The plain value of a scalar: the value itself for arithmetic types, the real part of a Jet.
template <class T>
double value_of(const T& x) {
  if constexpr (std::is_arithmetic_v<T>) {
    return static_cast<double>(x);
  } else {
    return x.a;
  }
}

/// sign(x) in {-1, 0, +1}; the derivative is zero everywhere (a constant of the right type).
template <class T>
T sgn(const T& x) {
  if (x > T(0)) return T(1);
  if (x < T(0)) return T(-1);
  return T(0);
}

/// |x / scale|^exponent without the singular derivative of pow at 0 (returns exactly 0 there).
template <class T, class S, class E>
T abs_pow_ratio(const T& x, const S& scale, const E& exponent) {
  using std::abs;
  using std::pow;
  if (value_of(x) == 0.0) return T(0);
  return pow(abs(x / scale), exponent);
}

/// The Stribeck decay exp(-|v / vs|^delta), in [0, 1]. Fast paths: delta = 2 (the usual shape)
/// squares instead of calling pow when the exponent is a plain number; far past the Stribeck
/// velocity (|v/vs|^delta > 40, decay < 4.3e-18, below the rounding of Fc + (Fs - Fc) decay for
/// any Fc > 1e-2 (Fs - Fc)) it returns 0 without calling exp, which is slow on its way to
/// underflow.
inline constexpr double kNegligibleDecayExponent = 40.0;

template <class T, class S, class E>
T stribeck_decay(const T& v, const S& vs, const E& delta) {
  using std::exp;
  if constexpr (std::is_arithmetic_v<E>) {
    if (delta == 2.0) {
      const T x = v / vs;
      const double xx = value_of(x) * value_of(x);
      if constexpr (std::is_same_v<T, double>) {  // no branch on xx (see below)
        const double e = std::exp(-std::min(xx, kNegligibleDecayExponent));
        return xx > kNegligibleDecayExponent ? 0.0 : e;
      } else {
        return xx > kNegligibleDecayExponent ? T(0) : exp(-x * x);
      }
    }
  }
  if constexpr (std::is_same_v<T, double> && std::is_arithmetic_v<S> && std::is_arithmetic_v<E>) {
    // |x|^delta as exp(delta log|x|): log and exp together cost half of pow, for a relative
    // error of about |delta log|x|| ulps in the exponent (well below the data's resolution).
    // exp is always called (on a clamped argument) and the cut-off selected afterwards: a branch
    // on u is taken at random as v moves through the dip, and each miss costs more than exp.
    const double x = std::abs(v / vs);
    if (x == 0.0) return 1.0;
    const double u = delta == 1.0 ? x : std::exp(delta * std::log(x));
    const double e = std::exp(-std::min(u, kNegligibleDecayExponent));
    return u > kNegligibleDecayExponent ? 0.0 : e;
  } else {
    const T u = abs_pow_ratio(v, vs, delta);
    return value_of(u) > kNegligibleDecayExponent ? T(0) : exp(-u);
  }
}

}  // namespace frictionlab
