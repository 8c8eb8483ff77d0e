#pragma once
// The control-oriented model of the friction lecture in the seeds: stuck while |applied| <= Fs,
// then Fc sign(v) + Fv v while sliding (Fs >= Fc: static friction exceeds kinetic).

#include <string_view>

#include "frictionlab/models/parameter.hpp"
#include "frictionlab/models/scalar.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Static + Coulomb + viscous: stuck while |applied| <= Fs; sliding force Fc sign(v) + Fv v.
template <class S = double>
struct StaticCoulombViscousT {
  S Fs{1.5};  ///< static (breakaway) level (N or N m), >= Fc. Default 1.5.
  S Fc{1.0};  ///< Coulomb level while sliding (N or N m), >= 0. Default 1.
  S Fv{0.1};  ///< viscous coefficient (N s/m or N m s/rad), >= 0. Default 0.1.

  static constexpr std::string_view kName = "static-coulomb-viscous";

  template <class Self, class Visit>
  static void visit(Self& self, Visit&& visit) {
    visit("Fs", Quantity::force, self.Fs);
    visit("Fc", Quantity::force, self.Fc);
    visit("Fv", Quantity::viscous, self.Fv);
  }

  /// Throws std::invalid_argument naming the first parameter that breaks its rule (Fc >= 0, Fs >= Fc, Fv >= 0).
  void validate() const {
    detail::require(std::isfinite(Fc) && Fc >= 0, kName, "Fc", Fc, ">= 0 (N or N m)");
    detail::require(std::isfinite(Fs) && Fs >= Fc, kName, "Fs", Fs, ">= Fc = " + detail::format_value(Fc) + " (N or N m)");
    detail::require(std::isfinite(Fv) && Fv >= 0, kName, "Fv", Fv, ">= 0 (N s/m or N m s/rad)");
  }

  template <class T>
  T sliding(const T& v) const {
    return T(Fc) * sgn(v) + T(Fv) * v;
  }
  S breakaway_positive() const { return Fs; }
  S breakaway_negative() const { return Fs; }
};
using StaticCoulombViscous = StaticCoulombViscousT<double>;

}  // namespace frictionlab
