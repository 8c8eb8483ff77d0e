#include "frictionlab/identify/finite_result.hpp"

#include <cmath>
#include <utility>

#include "frictionlab/error.hpp"
#include "frictionlab/format.hpp"

namespace frictionlab {

std::string non_finite_figure(const Result& r) {
  if (!r.ok()) return "";
  auto bad = [](double x) { return !std::isfinite(x); };
  for (const Parameter& p : r.parameters) {
    if (bad(p.value)) return "parameter " + p.name + " = " + format_number(p.value);
    if (std::isinf(p.std)) return "std(" + p.name + ") = " + format_number(p.std);
  }
  if (r.fit.samples > 0) {
    if (bad(r.fit.rmse)) return "fit rmse = " + format_number(r.fit.rmse);
    if (bad(r.fit.relative_error_percent)) return "fit relative error = " + format_number(r.fit.relative_error_percent) + " %";
  }
  if (r.validation) {
    const ValidationFigures& v = *r.validation;
    if (v.samples > 0 && bad(v.rmse)) return "validation rmse = " + format_number(v.rmse);
    if (v.samples > 0 && v.signal_errors_percent.empty() && bad(v.relative_error_percent))
      return "validation relative error = " + format_number(v.relative_error_percent) + " %";
    for (const auto& [name, x] : v.signal_errors_percent)
      if (bad(x)) return "validation relative error of " + name + " = " + format_number(x) + " %";
  }
  if (std::isinf(r.diagnostics.condition_number)) return "condition number = " + format_number(r.diagnostics.condition_number);
  for (const auto& [name, x] : r.diagnostics.numbers)
    if (std::isinf(x)) return "diagnostics " + name + " = " + format_number(x);
  for (const auto& [group, items] : r.diagnostics.groups)
    for (const auto& [name, x] : items)
      if (std::isinf(x)) return "diagnostics " + group + "." + name + " = " + format_number(x);
  for (const auto& [list, rows] : r.diagnostics.lists)
    for (const auto& row : rows)
      for (const auto& [name, x] : row)
        if (std::isinf(x)) return "diagnostics " + list + "[]." + name + " = " + format_number(x);
  return "";
}

Result finite_or_error(Result r) {
  const std::string what = non_finite_figure(r);
  if (what.empty()) return r;
  r.status = ResultStatus::error;
  r.code = errc::output_not_finite;
  r.message = (r.data_file.empty() ? std::string() : r.data_file + ": ") + r.method + ": " + what +
              " is not a finite number (values or scales beyond what double precision holds); the data cannot "
              "give an answer";
  return r;
}

}  // namespace frictionlab
