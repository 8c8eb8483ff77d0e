#pragma once
// Load, temperature and position effects composed with any velocity law of this folder: a
// decorator that moves the law's own levels (Coulomb Fc, static Fs, viscous Fv or sigma2) to the
// conditions the contact works at, and adds the position ripple. The law keeps its shape (the
// Stribeck curve, the bristles of LuGre): only its coefficients move.
//
//   Fc' = Fc + mu_coulomb |F_load| + Fc_per_K (T - T_ref)
//   Fs' = Fs + mu_static  |F_load| + Fc_per_K (T - T_ref)     (laws with a static level)
//   Fv' = Fv + Fv_per_K (T - T_ref)                            (Fv, or sigma2 of the bristle laws)
//   friction = law'(v) + r(q)                                   (r: PositionRipple)

#include <limits>
#include <optional>
#include <string>

#include "frictionlab/models/load_dependence.hpp"
#include "frictionlab/models/position_ripple.hpp"
#include "frictionlab/models/temperature_dependence.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The conditions a contact works at, besides its velocity.
struct Conditions {
  double load = 0.0;                 ///< transmitted or normal load F_load (N or N m); its magnitude counts
  std::optional<double> temperature; ///< degC or K; none = the law's T_ref (no shift)
  double position = 0.0;             ///< the contact's position q (m or rad), for the ripple
};

/// The effects a law carries besides its velocity dependence; each absent one does nothing.
struct LawEffects {
  std::optional<LoadDependence> load;
  std::optional<TemperatureDependence> temperature;
  std::optional<PositionRipple> ripple;

  bool empty() const { return !load && !temperature && !ripple; }
  /// True when the levels depend on the conditions (load or temperature), not only the ripple.
  bool moves_levels() const { return load.has_value() || temperature.has_value(); }
  /// Ripple force r(q) (N or N m); 0 without a ripple.
  double ripple_force(double q) const { return ripple ? ripple->force(q) : 0.0; }
  /// \throws InputError (law.parameter) from the effects' own checks.
  void validate() const {
    if (load) load->validate();
    if (temperature) temperature->validate();
    if (ripple) ripple->validate();
  }
};

/// What a law offers the effects: a Coulomb level, a separate static level, a viscous coefficient.
template <class Law>
constexpr bool kHasCoulombLevel = requires(Law l) { l.Fc; } || requires(Law l) { l.pos.Fc; };
template <class Law>
constexpr bool kHasStaticLevel = requires(Law l) { l.Fs; } || requires(Law l) { l.pos.Fs; };
template <class Law>
constexpr bool kHasViscous = requires(Law l) { l.Fv; } || requires(Law l) { l.sigma2; } || requires(Law l) { l.pos.Fv; };

namespace detail FRICTIONLAB_NO_EXPORT {
template <class Law>
void shift_levels(Law& law, double dFc, double dFs, double dFv) {
  if constexpr (requires { law.pos; law.neg; }) {  // Asymmetric<...>: both sides move alike
    shift_levels(law.pos, dFc, dFs, dFv);
    shift_levels(law.neg, dFc, dFs, dFv);
  } else {
    if constexpr (requires { law.Fc; }) law.Fc += dFc;
    if constexpr (requires { law.Fs; }) law.Fs += dFs;
    if constexpr (requires { law.Fv; }) law.Fv += dFv;
    else if constexpr (requires { law.sigma2; }) law.sigma2 += dFv;
  }
}
template <class Law>
double first_coulomb(const Law& law) {
  if constexpr (requires { law.pos; }) return std::min(first_coulomb(law.pos), first_coulomb(law.neg));
  else if constexpr (requires { law.Fc; }) return law.Fc;
  else return std::numeric_limits<double>::quiet_NaN();
}
template <class Law>
double first_viscous(const Law& law) {
  if constexpr (requires { law.pos; }) return std::min(first_viscous(law.pos), first_viscous(law.neg));
  else if constexpr (requires { law.Fv; }) return law.Fv;
  else if constexpr (requires { law.sigma2; }) return law.sigma2;
  else return std::numeric_limits<double>::quiet_NaN();
}
}  // namespace detail

/// Checks that `law` (of type Law, named `name`) has what `effects` move, and that a temperature
/// range keeps its coefficients >= 0 at both ends (they are linear in T, so both ends suffice).
/// \throws InputError (law.parameter) naming the effect's parameter: mu_load on a law without a
///         Coulomb level (viscous, table), two different load coefficients on a law with one level,
///         Fc_per_K without a Coulomb level, Fv_per_K without a viscous coefficient, a T_min or
///         T_max at which a coefficient would be negative (message names the temperature).
template <class Law>
void check_effects(const Law& law, const LawEffects& effects, const std::string& name) {
  effects.validate();
  auto refuse = [&](const char* key, const std::string& why) {
    throw InputError(errc::law_parameter, std::string(key) + ": " + why, {.key = key});
  };
  if (effects.load) {
    if (!kHasCoulombLevel<Law>)
      refuse("mu_load", "law '" + name + "' has no Coulomb level Fc for the load to raise (load dependence needs a law with Fc)");
    if (!kHasStaticLevel<Law> && effects.load->mu_static != effects.load->mu_coulomb)
      refuse("mu_load_static", "law '" + name + "' has one level (its static level is Fc): give one coefficient, mu_load");
  }
  if (const auto& t = effects.temperature) {
    if (t->Fc_per_K != 0 && !kHasCoulombLevel<Law>) refuse("Fc_per_K", "law '" + name + "' has no Coulomb level Fc");
    if (t->Fv_per_K != 0 && !kHasViscous<Law>) refuse("Fv_per_K", "law '" + name + "' has no viscous coefficient (Fv or sigma2)");
    const double Fc = detail::first_coulomb(law), Fv = detail::first_viscous(law);
    for (const auto& end : {t->T_min, t->T_max})
      if (end) {
        t->check_at(*end, Fc, Fv);
        Law moved = law;
        detail::shift_levels(moved, t->coulomb_shift(*end), t->coulomb_shift(*end), t->viscous_shift(*end));
        try {
          moved.validate();
        } catch (const std::invalid_argument& e) {
          throw InputError(errc::law_parameter,
                           std::string(t->Fc_per_K != 0 ? "Fc_per_K" : "Fv_per_K") + ": at T = " + detail::format_value(*end) +
                               " the law breaks its rule: " + e.what(),
                           {.key = t->Fc_per_K != 0 ? "Fc_per_K" : "Fv_per_K", .value = detail::format_value(*end)});
        }
      }
  }
}

/// `law` with its levels moved to `c` (load and temperature; the ripple is not part of it).
/// \throws InputError (law.parameter) when the temperature makes a coefficient negative or lies
///         outside [T_min, T_max] (see TemperatureDependence::check_at).
template <class Law>
Law at_conditions(const Law& law, const LawEffects& effects, const Conditions& c) {
  if (!effects.moves_levels()) return law;
  double dFc = 0, dFs = 0, dFv = 0;
  if (effects.load) {
    dFc += effects.load->coulomb_rise(c.load);
    dFs += effects.load->static_rise(c.load);
  }
  if (effects.temperature && c.temperature) {
    const TemperatureDependence& t = *effects.temperature;
    const double T = *c.temperature;
    t.check_at(T, detail::first_coulomb(law), detail::first_viscous(law));
    dFc += t.coulomb_shift(T);
    dFs += t.coulomb_shift(T);
    dFv += t.viscous_shift(T);
  }
  Law moved = law;
  detail::shift_levels(moved, dFc, dFs, dFv);
  return moved;
}

}  // namespace frictionlab
