#pragma once
// LuGre friction (Canudas de Wit, Olsson, Astrom, Lischinsky 1995; Astrom & Canudas de Wit 2008):
//   dz/dt = v - sigma0 |v| z / g(v),   g(v) = Fc + (Fs - Fc) exp(-|v/vs|^delta)
//   F     = sigma0 z + sigma1(v) dz/dt + sigma2 v,   sigma1(v) = sigma1 exp(-(v/vd)^2) (vd > 0) or sigma1.

#include <cmath>
#include <span>
#include <string>
#include <string_view>

#include "frictionlab/models/parameter.hpp"
#include "frictionlab/models/relaxation.hpp"
#include "frictionlab/models/scalar.hpp"
#include "frictionlab/models/stribeck.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Outcome of a passivity check: a set that is not passive is still accepted (the 1995 paper's
/// Table I set is not), but energy may then grow locally in simulation.
struct Passivity {
  bool passive = true;
  std::string message;  ///< the rule, the values, and the verdict, in words
};

/// LuGre bristle model. Defaults are the Table I set of Canudas de Wit et al. 1995.
template <class S = double>
struct LuGreT {
  S sigma0{1e5};                    ///< bristle stiffness (N/m or N m/rad), > 0
  S sigma1{316.22776601683796};     ///< bristle damping (N s/m or N m s/rad), >= 0 (sqrt(1e5))
  S sigma2{0.4};                    ///< viscous coefficient (N s/m or N m s/rad), >= 0
  S Fc{1.0};                        ///< Coulomb level (N or N m), > 0
  S Fs{1.5};                        ///< static level (N or N m), >= Fc
  S vs{0.001};                      ///< Stribeck velocity (m/s or rad/s), > 0
  S delta{2.0};                     ///< Stribeck exponent, > 0
  S vd{0.0};                        ///< damping decay velocity (m/s or rad/s), >= 0; 0 = constant damping

  static constexpr std::string_view kName = "lugre";

  template <class Self, class Visit>
  static void visit(Self& self, Visit&& visit) {
    visit("sigma0", Quantity::stiffness, self.sigma0);
    visit("sigma1", Quantity::viscous, self.sigma1);
    visit("sigma2", Quantity::viscous, self.sigma2);
    visit("Fc", Quantity::force, self.Fc);
    visit("Fs", Quantity::force, self.Fs);
    visit("vs", Quantity::velocity, self.vs);
    visit("delta", Quantity::dimensionless, self.delta);
    visit("vd", Quantity::velocity, self.vd);
  }

  /// Throws std::invalid_argument naming the first parameter that breaks its rule.
  void validate() const {
    detail::require(std::isfinite(sigma0) && sigma0 > 0, kName, "sigma0", sigma0, "> 0 (N/m or N m/rad)");
    detail::require(std::isfinite(sigma1) && sigma1 >= 0, kName, "sigma1", sigma1, ">= 0 (N s/m or N m s/rad)");
    detail::require(std::isfinite(sigma2) && sigma2 >= 0, kName, "sigma2", sigma2, ">= 0 (N s/m or N m s/rad)");
    detail::validate_stribeck_level(kName, Fc, Fs, vs, delta, true);
    detail::require(std::isfinite(vd) && vd >= 0, kName, "vd", vd, ">= 0 (m/s or rad/s; 0 = constant damping)");
  }

  /// Passive (dissipative for every input) for constant damping when sigma2 > sigma1 (Fs - Fc) / Fc;
  /// with velocity-dependent damping (vd > 0) that condition is sufficient, not necessary.
  Passivity passivity() const {
    const double bound = value_of(sigma1) * (value_of(Fs) - value_of(Fc)) / value_of(Fc);
    Passivity p;
    p.passive = value_of(sigma2) > bound || value_of(Fs) == value_of(Fc);
    p.message = "lugre: sigma2 = " + std::to_string(value_of(sigma2)) + (p.passive ? " > " : " <= ") +
                "sigma1 (Fs - Fc) / Fc = " + std::to_string(bound) + (p.passive ? ": passive" : ": not passive");
    if (p.passive && value_of(vd) > 0) p.message += " (sufficient condition; damping decays with |v|)";
    return p;
  }

  int num_states() const { return 1; }

  /// Stribeck level g(v) (N or N m): the force the bristles carry when sliding steadily at v.
  template <class T>
  T level(const T& v) const {
    return StribeckT<S>{Fc, Fs, vs, delta, S(0)}.level(v);
  }

  /// Bristle damping at velocity v (N s/m or N m s/rad).
  template <class T>
  T damping(const T& v) const {
    using std::exp;
    if (value_of(vd) == 0.0) return T(sigma1);
    const T r = v / T(vd);
    return T(sigma1) * exp(-r * r);
  }

  /// dz/dt (m/s or rad/s) at state z (m or rad) and velocity v.
  template <class T>
  T state_derivative(const T& z, const T& v) const {
    using std::abs;
    return v - T(sigma0) * abs(v) * z / level(v);
  }

  /// Friction force (N or N m) at state z and velocity v.
  template <class T>
  T force(const T& z, const T& v) const {
    return T(sigma0) * z + damping(v) * state_derivative(z, v) + T(sigma2) * v;
  }

  // Span forms of the DynamicLaw interface (one state).
  template <class T>
  void derivative(std::span<const T> z, const T& v, std::span<T> dz) const {
    dz[0] = state_derivative(z[0], v);
  }
  template <class T>
  T force(std::span<const T> z, const T& v) const {
    return force(z[0], v);
  }

  /// Exact update over dt (s) at constant v: z relaxes to g(v) sign(v) / sigma0 with rate
  /// sigma0 |v| / g(v), so z never leaves |z| <= Fs / sigma0 and any dt is stable.
  /// Returns the force at the end of the step (N or N m).
  double step(std::span<double> z, double v, double dt) const {
    // g(v) and the damping are evaluated once: this runs in a control loop (target < 20 ns).
    const BristleRelaxation<double> r = bristle_relaxation(*this, v);
    if (v != 0.0) z[0] = relax(z[0], r.target, std::exp(-r.rate * dt));  // at rest z holds
    const double zdot = v - r.rate * z[0];
    return sigma0 * z[0] + damping(v) * zdot + sigma2 * v;
  }

  /// Steady state at constant v (m or rad): g(v) sign(v) / sigma0.
  void steady_state(double v, std::span<double> z) const { z[0] = sgn(v) * level(v) / sigma0; }
};
using LuGre = LuGreT<double>;

}  // namespace frictionlab
