#pragma once
// Karnopp friction: a zero-velocity band in which the contact counts as stuck. Made for
// fixed-step simulation, where velocity is never exactly zero: inside |v| < dv the friction
// balances the applied force up to Fs; outside it is Fc sign(v) + Fv v.

#include <string_view>

#include "frictionlab/models/parameter.hpp"
#include "frictionlab/models/scalar.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Karnopp model. Trade-off of `dv`: wider sticks more reliably at large steps, but lets a
/// body creep at speeds below dv; narrower needs smaller steps. The hybrid engine of
/// frictionlab treats it as exact stiction (dv only matters in fixed-step mode).
template <class S = double>
struct KarnoppT {
  S Fs{1.5};    ///< static (breakaway) level (N or N m), >= Fc. Default 1.5.
  S Fc{1.0};    ///< Coulomb level (N or N m), >= 0. Default 1.
  S Fv{0.1};    ///< viscous coefficient (N s/m or N m s/rad), >= 0. Default 0.1.
  S dv{1e-4};   ///< half-width of the zero-velocity band (m/s or rad/s), > 0. Default 1e-4.

  static constexpr std::string_view kName = "karnopp";

  template <class Self, class Visit>
  static void visit(Self& self, Visit&& visit) {
    visit("Fs", Quantity::force, self.Fs);
    visit("Fc", Quantity::force, self.Fc);
    visit("Fv", Quantity::viscous, self.Fv);
    visit("dv", Quantity::velocity, self.dv);
  }

  /// Throws std::invalid_argument naming the first parameter that breaks its rule.
  void validate() const {
    detail::require(std::isfinite(Fc) && Fc >= 0, kName, "Fc", Fc, ">= 0 (N or N m)");
    detail::require(std::isfinite(Fs) && Fs >= Fc, kName, "Fs", Fs, ">= Fc = " + detail::format_value(Fc) + " (N or N m)");
    detail::require(std::isfinite(Fv) && Fv >= 0, kName, "Fv", Fv, ">= 0 (N s/m or N m s/rad)");
    detail::require(std::isfinite(dv) && dv > 0, kName, "dv", dv, "> 0 (m/s or rad/s)");
  }

  template <class T>
  T sliding(const T& v) const {
    return T(Fc) * sgn(v) + T(Fv) * v;
  }
  S breakaway_positive() const { return Fs; }
  S breakaway_negative() const { return Fs; }

  /// The Karnopp force (N or N m): inside |v| < dv it balances `applied` up to Fs, outside it slides.
  template <class T>
  T force(const T& v, const T& applied) const {
    using std::abs;
    if (abs(v) < T(dv)) {
      if (applied > T(Fs)) return T(Fs);
      if (applied < -T(Fs)) return -T(Fs);
      return applied;
    }
    return sliding(v);
  }
};
using Karnopp = KarnoppT<double>;

}  // namespace frictionlab
