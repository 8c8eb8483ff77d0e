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

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// 2|x| beyond which tanh(x) rounds to +-1 in double precision (1 - tanh(20) = 8e-18).
inline constexpr double kTanhSaturation = 40.0;

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
    } else {
      // tanh|x| = -m / (2 + m) with m = expm1(-2|x|) in (-1, 0]: one call, accurate to a few ulps
      // near 0 and far from it, and no branch on |x| (a mispredicted one costs more than the
      // call). Past |x| = 20, m rounds to -1 and the result to 1: the clamp keeps expm1 off its
      // slow path towards underflow. The sign is applied last so the law stays exactly odd.
      using std::abs;
      const T a = T(2) * abs(x);
      const T m = expm1(value_of(a) < kTanhSaturation ? -a : T(-kTanhSaturation));
      s = sgn(x) * (-m / (T(2) + m));
    }
    const T level = value_of(Fs) == value_of(Fc) ? T(Fc) : T(Fc) + (T(Fs) - T(Fc)) * stribeck_decay(v, vs, delta);
    return s * level + T(Fv) * v;
  }
  S breakaway_positive() const { return S(0); }
  S breakaway_negative() const { return S(0); }
};
using Smooth = SmoothT<double>;

}  // namespace frictionlab
