#pragma once
// Load-dependent friction levels: the Coulomb and static levels grow with the load the contact
// transmits (a gearbox's mesh force, a bearing's normal load), Fc + mu_coulomb |F_load| and
// Fs + mu_static |F_load|.

#include <cmath>
#include <string>

#include "frictionlab/error.hpp"
#include "frictionlab/models/parameter.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// How a law's levels grow with the load |F_load| (N or N m, the same unit as the levels: the
/// coefficients are dimensionless). One coefficient (`mu_load` in a law file) raises both levels
/// together; two (`mu_load_static`, `mu_load_coulomb`) raise them apart. For a law with one level
/// (coulomb, coulomb-viscous, dahl) the static level is the Coulomb level, so the two must agree.
struct LoadDependence {
  double mu_static = 0.0;   ///< rise of the static (breakaway) level per unit load, >= mu_coulomb
  double mu_coulomb = 0.0;  ///< rise of the Coulomb level per unit load, >= 0

  /// \throws InputError (code law.parameter, key = the file's parameter name) when a coefficient is
  ///         negative or not finite, or when mu_static < mu_coulomb (the static level would fall
  ///         below the Coulomb level at a large load).
  void validate() const {
    auto refuse = [](const char* key, double v, const std::string& rule) {
      throw InputError(errc::law_parameter, std::string(key) + " = " + detail::format_value(v) + " must be " + rule,
                       {.key = key, .value = detail::format_value(v)});
    };
    if (!(std::isfinite(mu_coulomb) && mu_coulomb >= 0)) refuse("mu_load_coulomb", mu_coulomb, ">= 0 (dimensionless: N of friction per N of load)");
    if (!(std::isfinite(mu_static) && mu_static >= 0)) refuse("mu_load_static", mu_static, ">= 0 (dimensionless: N of friction per N of load)");
    if (mu_static < mu_coulomb)
      refuse("mu_load_static", mu_static,
             ">= mu_load_coulomb = " + detail::format_value(mu_coulomb) + " (the static level stays above the Coulomb level at any load)");
  }

  /// Rise of the static level at load F (N or N m): mu_static |F|.
  double static_rise(double load) const { return mu_static * std::abs(load); }
  /// Rise of the Coulomb level at load F (N or N m): mu_coulomb |F|.
  double coulomb_rise(double load) const { return mu_coulomb * std::abs(load); }
};

}  // namespace frictionlab
