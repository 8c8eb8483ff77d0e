#pragma once
// Coulomb plus viscous friction, F = Fc sign(v) + Fv v: the model of inverse-dynamics identification.

#include <string_view>

#include "frictionlab/models/parameter.hpp"
#include "frictionlab/models/scalar.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// F = Fc sign(v) + Fv v. A stuck contact holds up to Fc.
template <class S = double>
struct CoulombViscousT {
  S Fc{1.0};  ///< Coulomb level (N or N m), >= 0. Default 1.
  S Fv{0.1};  ///< viscous coefficient (N s/m or N m s/rad), >= 0. Default 0.1.

  static constexpr std::string_view kName = "coulomb-viscous";

  template <class Self, class Visit>
  static void visit(Self& self, Visit&& visit) {
    visit("Fc", Quantity::force, self.Fc);
    visit("Fv", Quantity::viscous, self.Fv);
  }

  /// Throws std::invalid_argument naming the first parameter that is negative or not finite.
  void validate() const {
    detail::require(std::isfinite(Fc) && Fc >= 0, kName, "Fc", Fc, ">= 0 (N or N m)");
    detail::require(std::isfinite(Fv) && Fv >= 0, kName, "Fv", Fv, ">= 0 (N s/m or N m s/rad)");
  }

  template <class T>
  T sliding(const T& v) const {
    return T(Fc) * sgn(v) + T(Fv) * v;
  }
  S breakaway_positive() const { return Fc; }
  S breakaway_negative() const { return Fc; }
};
using CoulombViscous = CoulombViscousT<double>;

}  // namespace frictionlab
