// Identification: the Result type (parameters with std and units, fit figures, validation,
// diagnostics) and every method (idim, breakaway, sweep, decay, static law fit). Options are
// plain classes with the C++ fields; the keyword API is frictionlab/identify.py.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <tuple>

#include "common.hpp"
#include "frictionlab/format.hpp"
#include "frictionlab/identify/breakaway.hpp"
#include "frictionlab/identify/decay.hpp"
#include "frictionlab/identify/idim.hpp"
#include "frictionlab/identify/result.hpp"
#include "frictionlab/identify/static_fit.hpp"
#include "frictionlab/identify/sweep.hpp"
#include "frictionlab/io/atomic_write.hpp"

namespace frictionlab::python {

namespace {

std::string axis_name(Axis a) { return a == Axis::rotary ? "rotary" : "linear"; }

std::string static_model_name(StaticFitModel m) {
  switch (m) {
    case StaticFitModel::coulomb_viscous: return "coulomb-viscous";
    case StaticFitModel::coulomb_viscous_asymmetric: return "coulomb-viscous-asymmetric";
    case StaticFitModel::stribeck: return "stribeck";
    case StaticFitModel::stribeck_asymmetric: return "stribeck-asymmetric";
  }
  return "?";
}

std::string num(double x, int precision = 6) { return format_number(x, precision); }

// The one conversion of parameters to a Python dict: name -> get(parameter), in their order.
template <class Get>
py::dict by_name(const std::vector<Parameter>& ps, Get get) {
  py::dict d;
  for (const auto& p : ps) d[py::str(p.name)] = get(p);
  return d;
}

// A static fit's parameters with the units of `axis` (the fit itself knows quantities only).
std::vector<Parameter> with_units(const std::vector<Parameter>& ps, Axis axis) {
  std::vector<Parameter> out;
  for (const auto& p : ps) out.push_back(p.with_unit(axis));
  return out;
}

// The aligned parameter table of a result (name, value, +- std, unit), one line each.
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
  s << "  fit: relative error " << num(r.fit.relative_error_percent, 4) << " %, rmse " << num(r.fit.rmse, 4) << ", "
    << r.fit.samples << " samples\n";
  if (r.validation)
    s << "  validation " << r.validation->file << ": relative error " << num(r.validation->relative_error_percent, 4)
      << " %, rmse " << num(r.validation->rmse, 4) << "\n";
  if (std::isfinite(r.diagnostics.condition_number))
    s << "  condition number " << num(r.diagnostics.condition_number, 4) << "\n";
  for (const auto& w : r.diagnostics.warnings) s << "  warning: " << w << "\n";
  return s.str();
}

py::object json_loads(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

IdimData idim_data(const char* function, const py::object& time, const py::object& force, const py::object& position,
                   const py::object& velocity, const std::string& file, const std::string& sha256) {
  IdimData d;
  d.time = vector_arg(time, function, "time");
  d.force = vector_arg(force, function, "force");
  ArraySpec optional;
  optional.optional = true;
  d.position = vector_arg(position, function, "position", optional);
  d.velocity = vector_arg(velocity, function, "velocity", optional);
  same_length(function, {{"time", d.time.size()}, {"force", d.force.size()}, {"position", d.position.size()},
                         {"velocity", d.velocity.size()}});
  d.file = file;
  d.sha256 = sha256;
  return d;
}

// time, force and velocity of the breakaway and sweep methods, checked, of equal lengths.
std::tuple<Eigen::VectorXd, Eigen::VectorXd, Eigen::VectorXd> three_arrays(const char* function, const py::object& time,
                                                                          const py::object& force,
                                                                          const py::object& velocity) {
  Eigen::VectorXd t = vector_arg(time, function, "time"), f = vector_arg(force, function, "force"),
                  v = vector_arg(velocity, function, "velocity");
  same_length(function, {{"time", t.size()}, {"force", f.size()}, {"velocity", v.size()}});
  return {std::move(t), std::move(f), std::move(v)};
}

template <class Options>
void axis_property(py::class_<Options>& c) {
  c.def_property("axis", [](const Options& o) { return axis_name(o.axis); },
                 [](Options& o, const std::string& a) { o.axis = parse_axis(a); },
                 "'linear' (N, N s/m, kg, m/s) or 'rotary' (N m, N m s/rad, kg m^2, rad/s): the units reported.");
}

}  // namespace

void init_identify(py::module_& m) {
  // ---- the result -------------------------------------------------------------------------
  py::class_<Parameter>(m, "Parameter", "One identified parameter: value and standard deviation in `unit` (SI).")
      .def_readonly("name", &Parameter::name, "Parameter name, e.g. 'M', 'Fc', 'Fv_pos'.")
      .def_readonly("value", &Parameter::value, "Estimate, SI unit `unit`.")
      .def_readonly("std", &Parameter::std, "Standard deviation, same unit (NaN when unknown).")
      .def_readonly("unit", &Parameter::unit, "Unit, e.g. 'N', 'N s/m', 'kg', 'N m', 'N m s/rad', 'kg m^2'.")
      .def("__iter__", [](const Parameter& p) { return py::iter(py::make_tuple(p.value, p.std, p.unit)); })
      .def("__repr__", [](const Parameter& p) {
        return "Parameter(" + p.name + " = " + num(p.value) + " \u00b1 " + num(p.std, 3) + " " + p.unit + ")";
      });

  py::class_<FitFigures>(m, "FitFigures", "How well the model reproduces the identification data.")
      .def_readonly("relative_error_percent", &FitFigures::relative_error_percent, "100 ||y - y_hat|| / ||y||, percent.")
      .def_readonly("rmse", &FitFigures::rmse, "sqrt(mean((y - y_hat)^2)), unit of y (N or N m for force).")
      .def_readonly("samples", &FitFigures::samples, "Samples (or points) in the fit.")
      .def("__repr__", [](const FitFigures& f) {
        return "FitFigures(relative_error_percent=" + num(f.relative_error_percent) + ", rmse=" + num(f.rmse) +
               ", samples=" + std::to_string(f.samples) + ")";
      });

  py::class_<ValidationFigures>(m, "ValidationFigures", "Fit figures of an identified model on a second data set.")
      .def_readonly("file", &ValidationFigures::file, "The second data set's file name.")
      .def_readonly("sha256", &ValidationFigures::sha256, "Its SHA-256.")
      .def_readonly("relative_error_percent", &ValidationFigures::relative_error_percent, "100 ||y - y_hat|| / ||y||, percent.")
      .def_readonly("rmse", &ValidationFigures::rmse, "Root mean square error, unit of y (N or N m).")
      .def_readonly("samples", &ValidationFigures::samples, "Samples compared.")
      .def_readonly("signal_errors_percent", &ValidationFigures::signal_errors_percent,
                    "validate(): relative error (percent) of each signal: position, velocity, acceleration, force.")
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
      .def("__repr__", [](const Diagnostics& d) {
        return "Diagnostics(condition_number=" + num(d.condition_number) + ", warnings=" + std::to_string(d.warnings.size()) +
               ", numbers=" + py::cast<std::string>(py::repr(py::cast(d.numbers))) + ")";
      });

  py::class_<Result>(m, "Result", py::dynamic_attr(), R"doc(
Outcome of an identification method: parameters (value, std, unit; SI), fit figures, optional
validation on a second data set, diagnostics, and a status with a message. `result['Fc']` is a
value; `result.parameters['Fc']` a Parameter; `to_json()` is the MODEL.json of the command line.
A status of 'error' (data that cannot give an answer) is not an exception: check `result.ok`.)doc")
      .def_property_readonly("status", [](const Result& r) { return r.ok() ? "ok" : "error"; }, "'ok' or 'error'.")
      .def_property_readonly("ok", &Result::ok, "True when status is 'ok'.")
      .def_readonly("message", &Result::message, "Why status is 'error' (names file, parameter, expectation); '' when ok.")
      .def_readonly("method", &Result::method, "'idim', 'breakaway', 'sweep', 'decay'.")
      .def_readonly("model", &Result::model, "Model name, e.g. 'coulomb-viscous'.")
      .def_readonly("data_file", &Result::data_file, "Identification data file ('' for arrays).")
      .def_readonly("data_sha256", &Result::data_sha256, "Its SHA-256 ('' for arrays).")
      .def_property_readonly("parameters", [](const Result& r) { return by_name(r.parameters, [](const Parameter& p) { return p; }); },
                             "Parameters by name (in the method's order): Parameter(name, value, std, unit).")
      .def_property_readonly("values", [](const Result& r) { return by_name(r.parameters, [](const Parameter& p) { return p.value; }); },
                             "Parameter values by name (SI units).")
      .def_property_readonly("std", [](const Result& r) { return by_name(r.parameters, [](const Parameter& p) { return p.std; }); },
                             "Standard deviations by name (SI units).")
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

  // ---- options ----------------------------------------------------------------------------
  auto idim_opts = py::class_<IdimOptions>(m, "IdimOptions", "Options of identify_idim; defaults are the EMPS recipe.");
  idim_opts.def(py::init<>())
      .def_readwrite("terms", &IdimOptions::terms, "Regressor terms in column order: inertia, viscous, coulomb, offset, asymmetric, "
                                                   "viscous_pos, coulomb_pos, viscous_neg, coulomb_neg, stribeck.")
      .def_readwrite("cutoff_hz", &IdimOptions::cutoff_hz, "Position low-pass cut-off, Hz (100).")
      .def_readwrite("filter_order", &IdimOptions::filter_order, "Butterworth order (4).")
      .def_readwrite("padlen", &IdimOptions::padlen, "Odd padding of the zero-phase filter, samples (12).")
      .def_readwrite("input_delay", &IdimOptions::input_delay, "Samples the applied force lags the recorded input (0; EMPS: 1).")
      .def_readwrite("skip", &IdimOptions::skip, "Samples dropped at the start (49).")
      .def_readwrite("skip_end", &IdimOptions::skip_end, "Samples dropped at the end (0).")
      .def_readwrite("decimation", &IdimOptions::decimation, "Decimation factor (10; 1 = none).")
      .def_readwrite("auto_cutoff", &IdimOptions::auto_cutoff,
                     "Take cutoff_hz from the sample rate fs: min(100 Hz, fs/10) (False).")
      .def_readwrite("auto_decimation", &IdimOptions::auto_decimation,
                     "Take decimation from fs: floor(fs/100 Hz), 1 to 10 (False).")
      .def_readwrite("auto_skip", &IdimOptions::auto_skip,
                     "Take skip from fs: five periods of the cut-off less one sample (False).")
      .def_readwrite("stribeck_vs", &IdimOptions::stribeck_vs, "Stribeck velocity of the stribeck term, m/s or rad/s (0.01).")
      .def_readwrite("search_stribeck_vs", &IdimOptions::search_stribeck_vs, "Search the Stribeck velocity (False).")
      .def_readwrite("stribeck_delta", &IdimOptions::stribeck_delta, "Stribeck exponent (2).")
      .def_readwrite("min_velocity", &IdimOptions::min_velocity, "No excitation at or below this max |qd|, m/s or rad/s (0).")
      .def_readwrite("max_condition", &IdimOptions::max_condition, "Largest condition number accepted (1e8).");
  axis_property(idim_opts);
  m.def(
      "idim_rate_defaults",
      [](double sample_rate_hz) {
        const IdimRateDefaults d = idim_rate_defaults(sample_rate_hz);
        py::dict out;
        out["cutoff_hz"] = d.cutoff_hz;
        out["decimation"] = d.decimation;
        out["skip"] = d.skip;
        return out;
      },
      py::arg("sample_rate_hz"),
      "The idim cut-off (Hz), decimation and skip (samples) chosen from the sample rate fs (Hz): "
      "min(100 Hz, fs/10), clamp(floor(fs/100 Hz), 1, 10), round(5 fs/cutoff) - 1; exactly the EMPS "
      "recipe (100 Hz, 10, 49) at 1 kHz. Raises ValueError when fs is not a positive finite number.");

  auto brk_opts = py::class_<BreakawayOptions>(m, "BreakawayOptions", "Options of identify_breakaway.");
  brk_opts.def(py::init<>())
      .def_readwrite("inertia", &BreakawayOptions::inertia, "Inertia held fixed, kg m^2 or kg (NaN: estimated as M).")
      .def_readwrite("velocity_threshold", &BreakawayOptions::velocity_threshold, "|v| above which the axis moves, rad/s or m/s (NaN: 1 % of max |v|).")
      .def_readwrite("edge_samples", &BreakawayOptions::edge_samples, "Samples skipped at each end of a sliding interval (2).");
  axis_property(brk_opts);

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

  auto sweep_opts = py::class_<SweepOptions>(m, "SweepOptions", "Options of identify_sweep.");
  sweep_opts.def(py::init<>())
      .def_readwrite("fit", &SweepOptions::fit, "StaticFitOptions: the law fitted to the points.")
      .def_readwrite("velocity_tolerance", &SweepOptions::velocity_tolerance, "Absolute steady band, m/s or rad/s (0).")
      .def_readwrite("relative_tolerance", &SweepOptions::relative_tolerance, "Relative steady band (0.01).")
      .def_readwrite("min_duration", &SweepOptions::min_duration, "Shortest steady segment, s (0.5).")
      .def_readwrite("settle_fraction", &SweepOptions::settle_fraction, "Fraction dropped at each segment's start (0.2).")
      .def_readwrite("min_speed", &SweepOptions::min_speed, "Slower segments are standstill, m/s or rad/s (-1: 1e-6 max |v|).")
      .def_readwrite("noise_band", &SweepOptions::noise_band, "Steady band half-width in smoothed-noise std (5).")
      .def_readwrite("smoothing_fraction", &SweepOptions::smoothing_fraction,
                     "Moving-average window as a fraction of min_duration (0.1).")
      .def_readwrite("reference", &SweepOptions::reference,
                     "Commanded velocity (length N) to find the steady segments on; empty: the measured velocity.")
      .def_readwrite("min_segments", &SweepOptions::min_segments, "Fewer segments is an error (-1: parameters + 1).")
      .def_property("windows", [](const SweepOptions& o) {
        py::list l;
        for (const auto& w : o.windows) l.append(py::make_tuple(w.t_begin, w.t_end));
        return l;
      }, [](SweepOptions& o, const std::vector<std::pair<double, double>>& w) {
        o.windows.clear();
        for (const auto& [a, b] : w) o.windows.push_back({a, b});
      }, "Steady windows [(t_begin, t_end), ...] in s instead of detection ([]: detect).");
  axis_property(sweep_opts);

  auto decay_opts = py::class_<DecayOptions>(m, "DecayOptions", "Options of identify_decay.");
  decay_opts.def(py::init<>())
      .def_readwrite("stiffness", &DecayOptions::stiffness, "Restoring stiffness, N/m or N m/rad (pendulum: m g l); NaN: use natural_frequency.")
      .def_readwrite("inertia", &DecayOptions::inertia, "Inertia, kg or kg m^2 (with natural_frequency).")
      .def_readwrite("natural_frequency", &DecayOptions::natural_frequency, "sqrt(k/M), rad/s.")
      .def_readwrite("pendulum", &DecayOptions::pendulum, "Restoring force k sin(x) instead of k x.")
      .def_readwrite("stop_threshold", &DecayOptions::stop_threshold, "|v| below which the motion stopped (NaN: 1e-6 max |v|).");
  axis_property(decay_opts);

  // ---- methods ----------------------------------------------------------------------------
  m.def("_identify_idim", [](py::object time, py::object force, py::object position, py::object velocity,
                             const IdimOptions& o, const std::string& file, const std::string& sha256) {
    const IdimData d = idim_data("identify_idim", time, force, position, velocity, file, sha256);
    py::gil_scoped_release release;
    return identify_idim(d, o);
  });
  m.def("_cross_test", [](const Result& r, py::object time, py::object force, py::object position, py::object velocity,
                          const IdimOptions& o, const std::string& file, const std::string& sha256) {
    const IdimData d = idim_data("cross_test", time, force, position, velocity, file, sha256);
    py::gil_scoped_release release;
    return cross_test(r, d, o);
  });
  m.def("_idim_regression", [](py::object time, py::object force, py::object position, py::object velocity,
                               const IdimOptions& o) {
    const IdimRegression reg = idim_regression(idim_data("idim_regression", time, force, position, velocity, "", ""), o);
    py::dict d;
    d["X"] = reg.X;
    d["y"] = reg.y;
    py::list names;
    for (const auto& t : reg.terms) names.append(t.parameter);
    d["parameters"] = names;
    d["dt"] = reg.dt;
    d["max_speed"] = reg.max_speed;
    return d;
  });
  m.def("_identify_breakaway", [](py::object time, py::object force, py::object velocity, const BreakawayOptions& o) {
    const auto [t, f, v] = three_arrays("identify_breakaway", time, force, velocity);
    const BreakawayData d{t, f, v};
    py::gil_scoped_release release;
    return identify_breakaway(d, o);
  });
  m.def("_identify_sweep", [](py::object time, py::object force, py::object velocity, const SweepOptions& o) {
    const auto [t, f, v] = three_arrays("identify_sweep", time, force, velocity);
    const SweepData d{t, f, v};
    py::gil_scoped_release release;
    return identify_sweep(d, o);
  });
  m.def("_sweep_points", [](py::object time, py::object force, py::object velocity, const SweepOptions& o) {
    const auto [tt, ff, vv] = three_arrays("sweep_points", time, force, velocity);
    const SweepData d{tt, ff, vv};
    const std::vector<SweepPoint> pts = sweep_points(d, o);
    std::vector<double> v, vs, f, fs, tb, te, n;
    for (const auto& p : pts) {
      v.push_back(p.velocity), vs.push_back(p.velocity_std), f.push_back(p.force), fs.push_back(p.force_std);
      tb.push_back(p.t_begin), te.push_back(p.t_end), n.push_back(static_cast<double>(p.samples));
    }
    py::dict out;
    out["velocity"] = to_array(v);
    out["velocity_std"] = to_array(vs);
    out["force"] = to_array(f);
    out["force_std"] = to_array(fs);
    out["t_begin"] = to_array(tb);
    out["t_end"] = to_array(te);
    out["samples"] = to_array(n);
    return out;
  });
  m.def("_identify_decay", [](py::object time, py::object position, const DecayOptions& o) {
    const DecayData d{vector_arg(time, "identify_decay", "time"), vector_arg(position, "identify_decay", "position")};
    same_length("identify_decay", {{"time", d.time.size()}, {"position", d.position.size()}});
    py::gil_scoped_release release;
    return identify_decay(d, o);
  });

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
    py::gil_scoped_release release;
    return fit_static_law(v, f, o);
  });
}

}  // namespace frictionlab::python
