#pragma once
// Temperature-dependent friction coefficients, linear in T - T_ref: grease thins as it warms, so
// the viscous coefficient falls (Fv_per_K < 0); the Coulomb level may move too.
//   Fv(T) = Fv + Fv_per_K (T - T_ref),   Fc(T) = Fc + Fc_per_K (T - T_ref)
// The static level moves with the Coulomb level (Fs(T) = Fs + Fc_per_K (T - T_ref): the Stribeck
// rise Fs - Fc is kept).

#include <cmath>
#include <optional>
#include <string>

#include "frictionlab/error.hpp"
#include "frictionlab/models/parameter.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Temperatures are in degrees Celsius or kelvin (one scale throughout a run: only differences
/// T - T_ref enter); the slopes are per kelvin.
struct TemperatureDependence {
  double T_ref = 20.0;     ///< temperature at which the law's own Fc and Fv hold (degC or K)
  double Fc_per_K = 0.0;   ///< slope of the Coulomb (and static) level (N/K or N m/K)
  double Fv_per_K = 0.0;   ///< slope of the viscous coefficient (N s/(m K) or N m s/(rad K))
  /// The range of temperatures the law is to serve (degC or K); when given, the law refuses a
  /// range over which a coefficient would turn negative, and a run that leaves it.
  std::optional<double> T_min, T_max;

  /// Checks the parameters themselves (finite, T_min <= T_ref <= T_max when given).
  /// \throws InputError (code law.parameter, key = the parameter's name).
  void validate() const {
    auto refuse = [](const char* key, double v, const std::string& rule) {
      throw InputError(errc::law_parameter, std::string(key) + " = " + detail::format_value(v) + " must be " + rule,
                       {.key = key, .value = detail::format_value(v)});
    };
    if (!std::isfinite(T_ref)) refuse("T_ref", T_ref, "finite (degC or K)");
    if (!std::isfinite(Fc_per_K)) refuse("Fc_per_K", Fc_per_K, "finite (N/K or N m/K)");
    if (!std::isfinite(Fv_per_K)) refuse("Fv_per_K", Fv_per_K, "finite (N s/(m K) or N m s/(rad K))");
    if (T_min && !(std::isfinite(*T_min) && *T_min <= T_ref)) refuse("T_min", *T_min, "<= T_ref = " + detail::format_value(T_ref) + " (degC or K)");
    if (T_max && !(std::isfinite(*T_max) && *T_max >= T_ref)) refuse("T_max", *T_max, ">= T_ref = " + detail::format_value(T_ref) + " (degC or K)");
  }

  /// Shift of the Coulomb and static levels at temperature T (N or N m).
  double coulomb_shift(double T) const { return Fc_per_K * (T - T_ref); }
  /// Shift of the viscous coefficient at temperature T (N s/m or N m s/rad).
  double viscous_shift(double T) const { return Fv_per_K * (T - T_ref); }

  /// Refuses coefficients Fc(T) and Fv(T) that a temperature T makes negative, and a temperature
  /// outside [T_min, T_max] when the range is given. `Fc` and `Fv` are the law's own values at
  /// T_ref (pass NaN for a coefficient the law does not have).
  /// \throws InputError (code law.parameter) naming the parameter (Fc_per_K, Fv_per_K, T_min or
  ///         T_max) and the temperature.
  void check_at(double T, double Fc, double Fv) const {
    const std::string at = "at T = " + detail::format_value(T);
    if (T_min && T < *T_min)
      throw InputError(errc::law_parameter, "temperature T = " + detail::format_value(T) + " is below T_min = " + detail::format_value(*T_min),
                       {.key = "T_min", .value = detail::format_value(T)});
    if (T_max && T > *T_max)
      throw InputError(errc::law_parameter, "temperature T = " + detail::format_value(T) + " is above T_max = " + detail::format_value(*T_max),
                       {.key = "T_max", .value = detail::format_value(T)});
    if (!std::isnan(Fc) && Fc + coulomb_shift(T) < 0)
      throw InputError(errc::law_parameter,
                       "Fc_per_K = " + detail::format_value(Fc_per_K) + " makes the Coulomb level Fc(T) = " + detail::format_value(Fc) +
                           " + Fc_per_K (T - T_ref) negative " + at + " (T_ref = " + detail::format_value(T_ref) + ")",
                       {.key = "Fc_per_K", .value = detail::format_value(T)});
    if (!std::isnan(Fv) && Fv + viscous_shift(T) < 0)
      throw InputError(errc::law_parameter,
                       "Fv_per_K = " + detail::format_value(Fv_per_K) + " makes the viscous coefficient Fv(T) = " + detail::format_value(Fv) +
                           " + Fv_per_K (T - T_ref) negative " + at + " (T_ref = " + detail::format_value(T_ref) + ")",
                       {.key = "Fv_per_K", .value = detail::format_value(T)});
  }
};

}  // namespace frictionlab
