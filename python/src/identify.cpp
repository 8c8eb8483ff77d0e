// Identification: the static law fit (fit_static_law, StaticFitOptions, StaticFit), every
// registered method (methods/methods.cpp) and frictionlab.methods()'s table. The Result classes
// are result.cpp; the keyword API is python/frictionlab/identify.py.
#include "cancellable.hpp"
#include "frictionlab/identify/method.hpp"
#include "frictionlab/identify/option_applies.hpp"
#include "frictionlab/identify/static_fit.hpp"
#include "methods/method.hpp"
#include "result.hpp"

namespace frictionlab::python {

namespace {

std::string static_model_name(StaticFitModel m) {
  switch (m) {
    case StaticFitModel::coulomb_viscous: return "coulomb-viscous";
    case StaticFitModel::coulomb_viscous_asymmetric: return "coulomb-viscous-asymmetric";
    case StaticFitModel::stribeck: return "stribeck";
    case StaticFitModel::stribeck_asymmetric: return "stribeck-asymmetric";
  }
  return "?";
}

}  // namespace

void init_identify(py::module_& m) {
  py::class_<StaticFitOptions>(m, "StaticFitOptions", "Options of fit_static_law (and of the sweep's fit).")
      .def(py::init<>())
      .def_property("model", [](const StaticFitOptions& o) { return static_model_name(o.model); },
                    [](StaticFitOptions& o, const std::string& s) { o.model = parse_static_fit_model(s); },
                    "'coulomb-viscous', 'coulomb-viscous-asymmetric', 'stribeck' (default), 'stribeck-asymmetric'.")
      .def_readwrite("fixed_delta", &StaticFitOptions::fixed_delta, "Stribeck exponent held at this value; <= 0: fitted (0).")
      .def_readwrite("delta_min", &StaticFitOptions::delta_min, "Lower bound of a fitted exponent (0.5).")
      .def_readwrite("delta_max", &StaticFitOptions::delta_max, "Upper bound of a fitted exponent (5).")
      .def_readwrite("max_iterations", &StaticFitOptions::max_iterations, "Solver iterations (200).")
      .def_readwrite("num_threads", &StaticFitOptions::num_threads, "Threads for residual evaluation (2).");

  py::class_<StaticFit>(m, "StaticFit", "A static law fitted to friction-velocity points.")
      .def_readonly("law", &StaticFit::law, "The fitted FrictionLaw.")
      .def_readonly("relative_error_percent", &StaticFit::relative_error_percent, "100 ||F - F_hat|| / ||F||, percent.")
      .def_readonly("rmse", &StaticFit::rmse, "Root mean square residual, N or N m.")
      .def_readonly("samples", &StaticFit::samples, "Points fitted.")
      .def_readonly("iterations", &StaticFit::iterations, "Solver iterations.")
      .def_readonly("converged", &StaticFit::converged, "True when the solver converged.")
      .def_readonly("warnings", &StaticFit::warnings, "Human-readable warnings.")
      .def("parameters", [](const StaticFit& f, const std::string& axis) {
        // The flag stays out, as before: the fit's parameters are shown as a result's would be.
        std::vector<Parameter> ps = with_units(f.parameters, parse_axis(axis));
        for (auto& p : ps) p.flag.clear();
        return by_name(ps, [](const Parameter& p) { return p; });
      }, py::arg("axis") = "linear", "Fitted parameters by name: Parameter(name, value, std, unit) with units of the axis.")
      .def_property_readonly("values", [](const StaticFit& f) { return by_name(f.parameters, [](const Parameter& p) { return p.value; }); },
                             "Fitted values by name (SI).")
      .def_property_readonly("std", [](const StaticFit& f) { return by_name(f.parameters, [](const Parameter& p) { return p.std; }); },
                             "Standard deviations by name (SI).")
      .def("__getitem__", [](const StaticFit& f, const std::string& name) {
        for (const auto& p : f.parameters)
          if (p.name == name) return p.value;
        throw py::key_error(name);
      })
      .def("__repr__", [](const StaticFit& f) {
        const std::vector<Parameter> ps = with_units(f.parameters, Axis::linear);
        std::string s = "<frictionlab.StaticFit law='" + f.law.name() + "' converged=" + (f.converged ? "True" : "False") + ">\n" +
                        parameter_table(ps) + "  relative error " + num(f.relative_error_percent, 4) + " %, rmse " +
                        num(f.rmse, 4) + ", " + std::to_string(f.samples) + " points\n";
        for (const auto& w : f.warnings) s += "  warning: " + w + "\n";
        return s;
      });
  m.def("_fit_static_law", [](py::object velocity, py::object force, const StaticFitOptions& o) {
    // Unequal lengths: the library's own message ("friction fit: velocity has ... points").
    const Eigen::VectorXd v = vector_arg(velocity, "fit_static_law", "velocity"), f = vector_arg(force, "fit_static_law", "force");
    return run_cancellable([&] { return fit_static_law(v, f, o); });
  });

  // ---- the registered methods -------------------------------------------------------------
  bind_option_tables(m);
  for (const PyMethod& method : py_methods()) method.bind(m);
  m.def("_methods", [] {
    py::list out;
    for (const MethodInfo& info : identification_methods()) {
      py::dict d;
      d["name"] = info.name;
      d["summary"] = info.summary;
      d["fit_signal"] = info.fit_signal;
      py::dict units;
      if (info.fit_quantity)
        for (Axis a : {Axis::linear, Axis::rotary}) units[py::str(axis_name(a))] = std::string(unit(*info.fit_quantity, a));
      d["fit_units"] = units;
      py::object function = py::none();
      for (const PyMethod& method : py_methods())
        if (method.name == info.name) function = py::str(method.function);
      d["function"] = function;
      py::list options;  // the option table: what makes the keywords, their checks and docs
      for (const OptionSpec& o : info.options) {
        py::dict od;
        od["name"] = o.name;
        od["keyword"] = o.keyword();
        od["type"] = to_string(o.type);
        od["unit"] = o.unit_text();
        od["default"] = o.default_value ? py::object(py::str(option_text(*o.default_value))) : py::object(py::none());
        od["help"] = o.help;
        od["expected"] = o.expected();
        od["required"] = o.required;
        od["deprecated"] = o.deprecated_keywords;
        // When it applies, from the table's conditions: the words the CLI's --help prints, with
        // keywords for flags ("applies with iv=True"); "" when always.
        od["applies"] = applies_text(o, info.options, AppliesStyle::python);
        options.append(od);
      }
      d["options"] = options;
      out.append(d);
    }
    return out;
  }, "The library's identification methods (identify/method.hpp) in its order, one dict each: name, summary, "
     "fit_signal (words; '' when none), fit_units ({'linear': unit, 'rotary': unit} of the fit's rmse; {} when "
     "none) and function (the frictionlab function binding it, or None when no Python binding is registered).");
}

}  // namespace frictionlab::python
