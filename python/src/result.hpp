#pragma once
// The one conversion of identification results to Python, shared by every method's binding
// (methods/NAME.cpp): the Result, Parameter, FitFigures, ValidationFigures and Diagnostics
// classes, parameter dicts by name, the aligned parameter table of a repr, and the `axis`
// property of an options class. Includes the stl and Eigen casters so that every file binding
// a method converts the same C++ types the same way.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "common.hpp"
#include "frictionlab/identify/result.hpp"

namespace frictionlab::python {

/// `r` as it is, unless the library refused it because a figure is not a finite number (status
/// error, code output.not_finite: finite_or_error of identify/finite_result.hpp): Python raises
/// frictionlab.Error for that instead of returning a result (docs/python.md). Data that gives no
/// answer (no motion, too few segments) stays a result of status 'error'.
/// \throws InputError (output.not_finite, file the data file) with the result's message.
Result finite_answer(Result r);

/// "linear" or "rotary".
std::string axis_name(Axis a);

/// A number as the repr shows it (format_number, `precision` significant digits).
std::string num(double x, int precision = 6);

/// Parameters as a Python dict, name -> get(parameter), in their order.
template <class Get>
py::dict by_name(const std::vector<Parameter>& ps, Get get) {
  py::dict d;
  for (const auto& p : ps) d[py::str(p.name)] = get(p);
  return d;
}

/// Parameters with the units of `axis` (a static fit knows quantities only).
std::vector<Parameter> with_units(const std::vector<Parameter>& ps, Axis axis);

/// The aligned parameter table (name = value ± std unit), one indented line each.
std::string parameter_table(const std::vector<Parameter>& ps);

/// The `axis` property ('linear' or 'rotary', the units reported) of a method's options class
/// with an `Axis axis` field. Setting anything else raises ValueError naming the accepted values.
template <class Options>
void axis_property(py::class_<Options>& c) {
  c.def_property("axis", [](const Options& o) { return axis_name(o.axis); },
                 [](Options& o, const std::string& a) { o.axis = parse_axis(a); },
                 "'linear' (N, N s/m, kg, m/s) or 'rotary' (N m, N m s/rad, kg m^2, rad/s): the units reported.");
}

}  // namespace frictionlab::python
