#pragma once
// What a friction-law parameter measures, its unit on a linear or rotary axis, and the
// validation check that names the law, the parameter, its value and the rule it broke.

#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace frictionlab {

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
};

/// Unit string for a quantity on the given axis, e.g. unit(Quantity::viscous, Axis::rotary) = "N m s/rad".
std::string_view unit(Quantity q, Axis axis = Axis::linear);

/// Parses "linear" or "rotary"; throws std::invalid_argument naming the accepted values otherwise.
Axis parse_axis(std::string_view text);

namespace detail {
/// A number as every frictionlab message prints it: `digits` significant digits, no trailing
/// zeros (1e-05, not std::to_string's 0.000010). Default 10, enough to tell values apart.
inline std::string format_value(double value, int digits = 10) {
  std::ostringstream out;
  out.precision(digits);
  out << value;
  return out.str();
}

/// Throws std::invalid_argument("LAW: NAME = VALUE must be RULE") when `ok` is false.
inline void require(bool ok, std::string_view law, std::string_view name, double value, std::string_view rule) {
  if (ok) return;
  throw std::invalid_argument(std::string(law) + ": " + std::string(name) + " = " + format_value(value) + " must be " +
                              std::string(rule));
}
}  // namespace detail

}  // namespace frictionlab
