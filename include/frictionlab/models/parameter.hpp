#pragma once
// What a friction-law parameter measures, its unit on a linear or rotary axis, and the
// validation check that names the law, the parameter, its value and the rule it broke.

#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "frictionlab/format.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The kind of axis decides the units printed: N, N s/m, kg, m/s or N m, N m s/rad, kg m^2, rad/s.
enum class Axis { linear, rotary };

/// Physical quantity of a parameter or signal; units follow from it and the axis.
enum class Quantity {
  force,          ///< N or N m (Fc, Fs, offset, levels)
  viscous,        ///< N s/m or N m s/rad (Fv, sigma1, sigma2)
  velocity,       ///< m/s or rad/s (vs, vd, Karnopp band)
  displacement,   ///< m or rad (breakaway displacement)
  stiffness,      ///< N/m or N m/rad (sigma0, GMS element stiffness)
  inertia,        ///< kg or kg m^2
  acceleration,   ///< m/s^2 or rad/s^2
  time,           ///< s
  rate,           ///< 1/s
  force_rate,     ///< N/s or N m/s (force ramps, GMS attraction constant)
  dimensionless,  ///< exponents, fractions
  energy,         ///< J on either axis (energy lost per half cycle of a free decay)
  viscous_per_kelvin,  ///< N s/m/K or N m s/rad/K (how a viscous coefficient changes with temperature)
};

/// Unit string for a quantity on the given axis, e.g. unit(Quantity::viscous, Axis::rotary) = "N m s/rad".
std::string_view unit(Quantity q, Axis axis = Axis::linear);

/// Parses "linear" or "rotary"; throws std::invalid_argument naming the accepted values otherwise.
Axis parse_axis(std::string_view text);

/// One named value of frictionlab: a law's parameter, an identified estimate, a fitted
/// parameter. `value` and `std` are in SI units of `quantity` on the axis the result is on;
/// `unit` is that unit's text where the axis is known (identification results), empty for a
/// law's own parameters (their unit follows from `quantity` and the axis they are used on).
struct Parameter {
  std::string name;  ///< the shared name (docs/contract.md): "M", "Fv", "Fc", "offset", "Fc_pos", "sigma0", ...
  double value = 0;
  /// Standard deviation, same unit: 0 for a held or exact value, NaN when the data cannot
  /// determine it (see `flag`).
  double std = 0;
  Quantity quantity = Quantity::dimensionless;  ///< what it measures, hence its unit
  std::string unit;                             ///< e.g. "N", "N s/m", "kg m^2"
  /// Why `std` is NaN, for text output and reports: "" (determined), "undetermined" (the data
  /// cannot determine it) or "at bound" (the fit ended at a bound). See identify/uncertainty.hpp.
  std::string flag;
  /// The ordinary least-squares std s sqrt(diag((X'X)^-1)), same unit, when a method reports a
  /// std that accounts for correlated residuals instead (idim: identify/covariance.hpp); a lower
  /// bound when the residuals are coloured. Empty when the method has no such figure; NaN
  /// exactly where `std` is NaN.
  std::optional<double> std_ols;

  Parameter() = default;
  /// A law's parameter: no std, no axis yet.
  Parameter(std::string name_, double value_, Quantity q) : name(std::move(name_)), value(value_), quantity(q) {}
  /// An estimate whose unit follows from its quantity once an axis is chosen (with_unit).
  Parameter(std::string name_, double value_, double std_, Quantity q, std::string flag_ = {})
      : name(std::move(name_)), value(value_), std(std_), quantity(q), flag(std::move(flag_)) {}
  /// An estimate with its quantity and the unit text on `axis`.
  Parameter(std::string name_, double value_, double std_, Quantity q, Axis axis, std::string flag_ = {})
      : name(std::move(name_)), value(value_), std(std_), quantity(q), unit(unit_text(q, axis)),
        flag(std::move(flag_)) {}
  /// An estimate with its unit text only (quantity left dimensionless: unknown).
  Parameter(std::string name_, double value_, double std_, std::string unit_, std::string flag_ = {})
      : name(std::move(name_)), value(value_), std(std_), unit(std::move(unit_)), flag(std::move(flag_)) {}

  /// This parameter with `unit` set from its quantity on `axis`.
  Parameter with_unit(Axis axis) const {
    Parameter p = *this;
    p.unit = unit_text(quantity, axis);
    return p;
  }

 private:
  static std::string unit_text(Quantity q, Axis axis) { return std::string(::frictionlab::unit(q, axis)); }
};

namespace detail FRICTIONLAB_NO_EXPORT {
/// The name the laws' checks use for format_number (format.hpp) with 10 significant digits,
/// enough to tell values apart.
inline std::string format_value(double value, int digits = 10) { return format_number(value, digits); }

/// Throws std::invalid_argument("LAW: NAME = VALUE must be RULE") when `ok` is false.
inline void require(bool ok, std::string_view law, std::string_view name, double value, std::string_view rule) {
  if (ok) return;
  throw std::invalid_argument(std::string(law) + ": " + std::string(name) + " = " + format_value(value) + " must be " +
                              std::string(rule));
}
}  // namespace detail

}  // namespace frictionlab
