#pragma once
// Smooth approximation of Stribeck friction: sign(v) is replaced by tanh(v/vt) or (2/pi) atan(v/vt).
// This is an approximation, offered for users who need a continuous law (gradient-based
// controllers, solvers without events). Trade-off of vt: a large vt lets a body creep under any
// force below Fs (no true stiction); a small vt makes the ODE stiff near v = 0. The exact
// hybrid simulation of the discontinuous laws has neither problem.

#include <cmath>
#include <numbers>
#include <string_view>

#include "frictionlab/models/parameter.hpp"
#include "frictionlab/models/scalar.hpp"
#include "frictionlab/models/stribeck.hpp"

namespace frictionlab {

/// The smooth function used in place of sign(v).
enum class SmoothShape { tanh, atan };

/// F(v) = s(v/vt) (Fc + (Fs - Fc) exp(-|v/vs|^delta)) + Fv v, with s = tanh or (2/pi) atan.
/// With Fs = Fc (the default) it is a smoothed Coulomb + viscous law. No stiction (breakaway 0).
template <class S = double>
struct SmoothT {
  S Fc{1.0};     ///< Coulomb level (N or N m), >= 0. Default 1.
  S Fs{1.0};     ///< static level (N or N m), >= Fc. Default 1 (= Fc: no Stribeck dip).
  S vs{0.001};   ///< Stribeck velocity (m/s or rad/s), > 0. Default 0.001.
  S delta{2.0};  ///< Stribeck exponent, > 0. Default 2.
  S Fv{0.0};     ///< viscous coefficient (N s/m or N m s/rad), >= 0. Default 0.
  S vt{1e-3};    ///< smoothing velocity (m/s or rad/s), > 0: the slope at 0 is about Fc/vt. Default 1e-3.
  SmoothShape shape{SmoothShape::tanh};

  static constexpr std::string_view kName = "smooth";

  template <class Self, class Visit>
  static void visit(Self& self, Visit&& visit) {
    visit("Fc", Quantity::force, self.Fc);
    visit("Fs", Quantity::force, self.Fs);
    visit("vs", Quantity::velocity, self.vs);
    visit("delta", Quantity::dimensionless, self.delta);
    visit("Fv", Quantity::viscous, self.Fv);
    visit("vt", Quantity::velocity, self.vt);
  }

  /// Throws std::invalid_argument naming the first parameter that breaks its rule.
  void validate() const {
    detail::validate_stribeck_level(kName, Fc, Fs, vs, delta);
    detail::require(std::isfinite(Fv) && Fv >= 0, kName, "Fv", Fv, ">= 0 (N s/m or N m s/rad)");
    detail::require(std::isfinite(vt) && vt > 0, kName, "vt", vt, "> 0 (m/s or rad/s)");
  }

  template <class T>
  T sliding(const T& v) const {
    using std::atan;
    using std::expm1;
    const T x = v / T(vt);
    T s;
    if (shape == SmoothShape::atan) {
      s = T(2.0 / std::numbers::pi) * atan(x);
    } else if (value_of(x) > 20.0 || value_of(x) < -20.0) {
      s = T(value_of(x) > 0 ? 1.0 : -1.0);  // tanh(20) = 1 - 8e-18: one to rounding
    } else {
      // tanh|x| = expm1(2|x|) / (expm1(2|x|) + 2): one exp, accurate near 0; the sign is
      // applied last so the law stays exactly odd.
      using std::abs;
      const T e = expm1(T(2) * abs(x));
      s = sgn(x) * e / (e + T(2));
    }
    const T level = value_of(Fs) == value_of(Fc) ? T(Fc) : T(Fc) + (T(Fs) - T(Fc)) * stribeck_decay(v, vs, delta);
    return s * level + T(Fv) * v;
  }
  S breakaway_positive() const { return S(0); }
  S breakaway_negative() const { return S(0); }
};
using Smooth = SmoothT<double>;

}  // namespace frictionlab
