// The Result of every identification method and its parts, as Python classes (result.hpp).
#include "result.hpp"

#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

#include "frictionlab/error.hpp"
#include "frictionlab/format.hpp"
#include "io/atomic_write.hpp"

namespace frictionlab::python {

Result finite_answer(Result r) {
  if (!r.ok() && r.code == errc::output_not_finite) throw InputError(r.code, r.message, {.file = r.data_file});
  return r;
}

std::string axis_name(Axis a) { return a == Axis::rotary ? "rotary" : "linear"; }

std::string num(double x, int precision) { return format_number(x, precision); }

std::vector<Parameter> with_units(const std::vector<Parameter>& ps, Axis axis) {
  std::vector<Parameter> out;
  for (const auto& p : ps) out.push_back(p.with_unit(axis));
  return out;
}

std::string parameter_table(const std::vector<Parameter>& ps) {
  std::size_t wn = 4, wv = 5, ws = 3;
  for (const auto& p : ps) {
    wn = std::max(wn, p.name.size());
    wv = std::max(wv, num(p.value).size());
    ws = std::max(ws, num(p.std, 3).size());
  }
  std::ostringstream s;
  for (const auto& p : ps) {
    s << "  " << std::left << std::setw(static_cast<int>(wn)) << p.name << " = " << std::right
      << std::setw(static_cast<int>(wv)) << num(p.value) << " \u00b1 " << std::left << std::setw(static_cast<int>(ws))
      << num(p.std, 3) << "  " << p.unit << "\n";
  }
  return s.str();
}

namespace {

std::string result_repr(const Result& r) {
  std::ostringstream s;
  s << "<frictionlab.Result method='" << r.method << "' model='" << r.model << "' status='"
    << (r.ok() ? "ok" : "error") << "'";
  if (!r.data_file.empty()) s << " data='" << r.data_file << "'";
  s << ">\n";
  if (!r.ok()) {
    s << "  error: " << r.message << "\n";
    return s.str();
  }
  s << parameter_table(r.parameters);
  // rmse in the fitted signal's unit on the result's axis (N, N m, J, m); none when it has none.
  const std::string unit = r.fit.unit.empty() ? std::string() : " " + r.fit.unit;
  s << "  fit: relative error " << num(r.fit.relative_error_percent, 4) << " %, rmse " << num(r.fit.rmse, 4) << unit
    << ", " << r.fit.samples << " samples\n";
  if (r.validation)
    s << "  validation " << r.validation->file << ": relative error " << num(r.validation->relative_error_percent, 4)
      << " %, rmse " << num(r.validation->rmse, 4) << unit << "\n";
  if (std::isfinite(r.diagnostics.condition_number))
    s << "  condition number " << num(r.diagnostics.condition_number, 4) << "\n";
  for (const auto& w : r.diagnostics.warnings) s << "  warning: " << w << "\n";
  return s.str();
}

py::object json_loads(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

}  // namespace

void init_result(py::module_& m) {
  py::class_<Parameter>(m, "Parameter", "One identified parameter: value and standard deviation in `unit` (SI).")
      .def_readonly("name", &Parameter::name, "Parameter name, e.g. 'M', 'Fc', 'Fv_pos'.")
      .def_readonly("value", &Parameter::value, "Estimate, SI unit `unit`.")
      .def_readonly("std", &Parameter::std, "Standard deviation, same unit (NaN when unknown).")
      .def_readonly("unit", &Parameter::unit, "Unit, e.g. 'N', 'N s/m', 'kg', 'N m', 'N m s/rad', 'kg m^2'.")
      .def_readonly("std_ols", &Parameter::std_ols,
                    "The ordinary least-squares std s sqrt(diag((X'X)^-1)), same unit, when `std` accounts for "
                    "correlated residuals instead (idim); None for methods without it, NaN where std is NaN.")
      .def("__iter__", [](const Parameter& p) { return py::iter(py::make_tuple(p.value, p.std, p.unit)); })
      .def("__repr__", [](const Parameter& p) {
        return "Parameter(" + p.name + " = " + num(p.value) + " \u00b1 " + num(p.std, 3) + " " + p.unit + ")";
      });

  py::class_<FitFigures>(m, "FitFigures", "How well the model reproduces the identification data.")
      .def_readonly("relative_error_percent", &FitFigures::relative_error_percent, "100 ||y - y_hat|| / ||y||, percent.")
      .def_readonly("rmse", &FitFigures::rmse, "sqrt(mean((y - y_hat)^2)), unit of y (N or N m for force).")
      .def_readonly("samples", &FitFigures::samples, "Samples (or points) in the fit.")
      .def_readonly("quantity", &FitFigures::quantity,
                    "The fitted signal in words ('drive force', 'position'; see frictionlab.methods()); '' when none.")
      .def_readonly("unit", &FitFigures::unit, "rmse's unit on the result's axis ('N', 'N m', 'J', 'm'); '' when none.")
      .def("__repr__", [](const FitFigures& f) {
        return "FitFigures(relative_error_percent=" + num(f.relative_error_percent) + ", rmse=" + num(f.rmse) +
               (f.unit.empty() ? std::string() : ", unit='" + f.unit + "'") + ", samples=" + std::to_string(f.samples) +
               ")";
      });

  py::class_<ValidationFigures>(m, "ValidationFigures", "Fit figures of an identified model on a second data set.")
      .def_readonly("file", &ValidationFigures::file, "The second data set's file name.")
      .def_readonly("sha256", &ValidationFigures::sha256, "Its SHA-256.")
      .def_readonly("relative_error_percent", &ValidationFigures::relative_error_percent, "100 ||y - y_hat|| / ||y||, percent.")
      .def_readonly("rmse", &ValidationFigures::rmse, "Root mean square error, unit of y (N or N m).")
      .def_readonly("samples", &ValidationFigures::samples, "Samples compared.")
      .def_readonly("signal_errors_percent", &ValidationFigures::signal_errors_percent,
                    "validate(): relative error (percent) of each signal: position, velocity, acceleration, force "
                    "(validate_xy: 'x.position', ..., 'y.force').")
      .def_property_readonly("sections", [](const ValidationFigures& f) {
        py::dict d;
        for (const auto& [key, text] : f.json_sections) d[py::str(key)] = json_loads(text);
        return d;
      }, "Further figures by name as in the JSON's validation block: validate_xy's 'contour' ({'measured': {...}, "
         "'simulated': {...}, 'difference': {...}, 'relative_error_percent': {...}}; m), when the reference is a circle.")
      .def("__repr__", [](const ValidationFigures& f) {
        return "ValidationFigures(file='" + f.file + "', relative_error_percent=" + num(f.relative_error_percent) +
               ", rmse=" + num(f.rmse) + ", samples=" + std::to_string(f.samples) + ")";
      });

  py::class_<Diagnostics>(m, "Diagnostics", "Numerical health of an identification.")
      .def_readonly("condition_number", &Diagnostics::condition_number, "Of the regressor matrix (NaN if none).")
      .def_readonly("warnings", &Diagnostics::warnings, "Human-readable warnings, one sentence each.")
      .def_readonly("numbers", &Diagnostics::numbers, "Free-form figures by name ('dt' in s, 'max_speed', ...).")
      .def_readonly("groups", &Diagnostics::groups, "Named groups of figures, e.g. groups['readoff'] = {'Fs': ..., 'Fc': ...}.")
      .def_readonly("lists", &Diagnostics::lists, "Named lists of records, e.g. lists['points'] (sweep): one dict per segment.")
      .def_readonly("texts", &Diagnostics::texts,
                    "Named words, e.g. texts['estimator'] = 'idim-iv', texts['iv_source_kp'] (where IDIM-IV's kp came "
                    "from).")
      .def("__repr__", [](const Diagnostics& d) {
        return "Diagnostics(condition_number=" + num(d.condition_number) + ", warnings=" + std::to_string(d.warnings.size()) +
               ", numbers=" + py::cast<std::string>(py::repr(py::cast(d.numbers))) + ")";
      });

  py::class_<Result>(m, "Result", py::dynamic_attr(), R"doc(
Outcome of an identification method: parameters (value, std, unit; SI), fit figures, optional
validation on a second data set, diagnostics, and a status with a message. `result['Fc']` is a
value; `result.parameters['Fc']` a Parameter; `to_json()` is the MODEL.json of the command line.
A status of 'error' (data that cannot give an answer) is not an exception: check `result.ok`.
Figures beyond double precision (a force offset of 1e167: std(M) = inf) are: the identify_*
functions and validate raise frictionlab.Error with code 'output.not_finite'.)doc")
      .def_property_readonly("status", [](const Result& r) { return r.ok() ? "ok" : "error"; }, "'ok' or 'error'.")
      .def_property_readonly("ok", &Result::ok, "True when status is 'ok'.")
      .def_readonly("message", &Result::message, "Why status is 'error' (names file, parameter, expectation); '' when ok.")
      .def_readonly("method", &Result::method, "The method's name in frictionlab.methods(): 'idim', 'breakaway', 'sweep', 'decay', 'lugre', 'validate'.")
      .def_readonly("model", &Result::model, "Model name, e.g. 'coulomb-viscous'.")
      .def_readonly("data_file", &Result::data_file, "Identification data file ('' for arrays).")
      .def_readonly("data_sha256", &Result::data_sha256, "Its SHA-256 ('' for arrays).")
      .def_property_readonly("parameters", [](const Result& r) { return by_name(r.parameters, [](const Parameter& p) { return p; }); },
                             "Parameters by name (in the method's order): Parameter(name, value, std, unit).")
      .def_property_readonly("values", [](const Result& r) { return by_name(r.parameters, [](const Parameter& p) { return p.value; }); },
                             "Parameter values by name (SI units).")
      .def_property_readonly("std", [](const Result& r) { return by_name(r.parameters, [](const Parameter& p) { return p.std; }); },
                             "Standard deviations by name (SI units).")
      .def_property_readonly("std_ols", [](const Result& r) {
        return by_name(r.parameters, [](const Parameter& p) { return p.std_ols; }); },
                             "Ordinary least-squares standard deviations by name (SI units; None for methods "
                             "without them): idim's std accounts for correlated residuals, std_ols does not.")
      .def_property_readonly("units", [](const Result& r) { return by_name(r.parameters, [](const Parameter& p) { return p.unit; }); },
                             "Units by name.")
      .def_property_readonly("axis", [](const Result& r) { return axis_name(r.axis); }, "'linear' or 'rotary': the axis the units are on.")
      .def_readonly("fit", &Result::fit, "FitFigures on the identification data.")
      .def_readonly("validation", &Result::validation, "ValidationFigures on a second data set, or None.")
      .def_readonly("diagnostics", &Result::diagnostics, "Diagnostics: condition_number, warnings, numbers, groups, lists.")
      .def_property_readonly("law", [](const Result& r) -> py::object {
        if (!r.law) return py::none();
        return py::cast(FrictionLaw::from_spec(*r.law));
      }, "The identified friction law (FrictionLaw, ready to simulate), or None when the estimates do not make one.")
      .def_property_readonly("series", [](const Result& r) {
        py::dict d;
        for (const auto& [k, v] : r.series) d[py::str(k)] = to_array(v);
        return d;
      }, "Signals behind the result's figures, by name, as numpy arrays in SI units (not in the JSON): idim 'time', "
         "'force', 'force_model'; sweep 'velocity', 'force', 'force_std'; decay 'time', 'position', 'peak_time', ...")
      .def("value", &Result::value, py::arg("name"), "Value of parameter `name`; ValueError listing the parameters otherwise.")
      .def("__getitem__", [](const Result& r, const std::string& name) {
        if (const auto* p = r.find(name)) return p->value;
        try {
          r.value(name);
        } catch (const std::invalid_argument& e) {
          throw py::key_error(e.what());
        }
        throw py::key_error(name);
      })
      .def("__contains__", [](const Result& r, const std::string& name) { return r.find(name) != nullptr; })
      .def("__len__", [](const Result& r) { return r.parameters.size(); })
      .def("__iter__", [](const Result& r) {
        py::list names;
        for (const auto& p : r.parameters) names.append(p.name);
        return py::iter(names);
      })
      .def("keys", [](const Result& r) {
        py::list names;
        for (const auto& p : r.parameters) names.append(p.name);
        return names;
      }, "Parameter names.")
      .def("to_json", [](const Result& r, std::optional<int> indent) { return to_json(r, indent.value_or(-1)); },
           py::arg("indent") = 2, "The MODEL.json text (schema 1); indent=None gives one line. NaN is written as null.")
      .def("to_dict", [](const Result& r) { return json_loads(to_json(r, -1)); }, "The MODEL.json content as a dict.")
      .def("save", [](const Result& r, const py::object& path, bool overwrite) {
        AtomicWriteOptions o;
        o.overwrite = overwrite;
        write_file_atomic(path_arg(path, "Result.save"), to_json(r) + "\n", o);
      }, py::arg("path"), py::arg("overwrite") = false,
         "Writes the MODEL.json atomically. ValueError when the file exists and overwrite is False.")
      .def("_stamp", [](Result& r, const std::string& file, const std::string& sha256) {
        r.data_file = file;
        r.data_sha256 = sha256;
      })
      .def("_set_validation", [](Result& r, const ValidationFigures& v) { r.validation = v; })
      .def("__repr__", &result_repr)
      .def("__str__", &result_repr);
}

}  // namespace frictionlab::python
