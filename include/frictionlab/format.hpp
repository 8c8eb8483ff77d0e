#pragma once
// How frictionlab writes a number as text, everywhere (messages, tables, reports, figure data,
// Python reprs): one header. JSON numbers are nlohmann_json's (shortest round-trip text).

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// A number for people: `digits` significant digits (1 to 17), no trailing zeros, exponent form
/// for large and small magnitudes (printf's %g: 1e-05, 95.1, 1.234e+05). NaN prints "nan", the
/// infinities "inf" and "-inf". Messages use 6 digits; model validation 10, enough to tell
/// values apart.
inline std::string format_number(double value, int digits = 6) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits < 1 ? 1 : (digits > 17 ? 17 : digits), value);
  return buf;
}

/// A number exactly: the shortest text that reads back to the same double (std::to_chars: 0.1,
/// 95.1089, 1e-05, -inf, nan). For text that must round-trip: tables, part files, grid values.
inline std::string format_exact(double value) {
  char buf[32];  // the longest shortest form of a double has 24 characters
  const auto r = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, r.ptr);
}

/// A value to the precision its standard deviation supports (never more digits than the data
/// hold): the std to two significant digits and the value to the same decimal place
/// ({"95.10", "0.11"}); scientific notation for very large or small magnitudes ({"1.234e+05",
/// "2.1e+03"}). The value with format_number and the std as "0" (held) or "n/a" (unknown) when
/// the std is zero or not finite; "nan" / "n/a" for a value that is not finite.
inline std::pair<std::string, std::string> format_with_std(double value, double sd) {
  const auto text = [](double x, int digits) { return std::isnan(x) ? std::string("n/a") : format_number(x, digits); };
  if (!std::isfinite(value)) return {text(value, 6), text(sd, 2)};
  if (!std::isfinite(sd) || sd <= 0) return {format_number(value, 6), sd == 0 ? "0" : "n/a"};
  const int decimals = 1 - static_cast<int>(std::floor(std::log10(sd)));
  const double mag = std::max(std::abs(value), sd);
  char v[48], s[48];
  if (decimals >= 0 && decimals <= 8 && mag < 1e7) {
    std::snprintf(v, sizeof v, "%.*f", decimals, value);
    std::snprintf(s, sizeof s, "%.*f", decimals, sd);
  } else {
    const int exponent = static_cast<int>(std::floor(std::log10(mag)));
    const int sig = std::clamp(exponent + decimals, 1, 15);  // digits after the point in d.ddd e+XX
    std::snprintf(v, sizeof v, "%.*e", sig, value);
    std::snprintf(s, sizeof s, "%.1e", sd);
  }
  return {v, s};
}

}  // namespace frictionlab
