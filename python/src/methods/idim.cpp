// frictionlab.identify_idim: inverse dynamic model least squares on a trajectory. Binds
// IdimOptions, idim_rate_defaults, _identify_idim, _cross_test and _idim_regression (the keyword
// API is python/frictionlab/identify.py).
#include "frictionlab/identify/idim.hpp"
#include "frictionlab/scenario/scenario.hpp"

#include "../cancellable.hpp"
#include "method.hpp"

namespace frictionlab::python {
namespace {

void bind(py::module_& m) {
  auto idim_opts = py::class_<IdimOptions>(m, "IdimOptions", "Options of identify_idim; defaults are the EMPS recipe.");
  idim_opts.def(py::init<>())
      .def_readwrite("terms", &IdimOptions::terms, "Regressor terms in column order: inertia, viscous, coulomb, offset, asymmetric, "
                                                   "viscous_pos, coulomb_pos, viscous_neg, coulomb_neg, stribeck, "
                                                   "load, temperature, ripple.")
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
      .def_readwrite("ripple_period", &IdimOptions::ripple_period, "Period of the ripple term, m or rad (0: none).")
      .def_readwrite("ripple_harmonics", &IdimOptions::ripple_harmonics, "Harmonics of the ripple term (1).")
      .def_readwrite("temperature_ref", &IdimOptions::temperature_ref,
                     "Reference temperature of the temperature term, degC or K (NaN: the mean of the used samples).")
      .def_readwrite("min_velocity", &IdimOptions::min_velocity, "No excitation at or below this max |qd|, m/s or rad/s (0).")
      .def_readwrite("max_condition", &IdimOptions::max_condition, "Largest condition number accepted (1e8).");
  idim_opts.def_property(
      "iv_sources", [](const IdimOptions& o) { return o.iv.sources; },
      [](IdimOptions& o, const std::map<std::string, std::string>& s) { o.iv.sources = s; },
      "IDIM-IV: where each of the controller's values came from, by option name (reported as diagnostics "
      "iv_source_NAME).");
  py::class_<IdimIvScenario>(m, "_IdimIvScenario", "IDIM-IV's controller as a scenario gives it (idim_iv_scenario).")
      .def_readonly("file", &IdimIvScenario::file);
  m.def(
      "_idim_iv_scenario",
      [](const py::object& scenario, const std::string& axis) {
        if (py::isinstance<Scenario>(scenario)) return idim_iv_scenario(scenario.cast<const Scenario&>(), "Scenario", parse_axis(axis));
        const std::string path = path_arg(scenario, "identify_idim", "scenario");
        // Read with its own data file; friction and inertia are not used (IDIM-IV simulates its estimate).
        ScenarioOptions so;
        so.law = FrictionLaw();
        so.axis = AxisParams{};
        const Axis parsed = parse_axis(axis);
        return run_cancellable([&] { return idim_iv_scenario(load_scenario(path, so), path, parsed); });  // a file read
      },
      py::arg("scenario"), py::arg("axis"),
      "IDIM-IV's controller from a scenario file path or a Scenario, checked (idim_iv_scenario).");
  m.def("_make_idim_options",
        [](const OptionValues& v, const IdimIvScenario* scenario) { return make_idim_options(v, scenario); },
        py::arg("values"), py::arg("scenario") = nullptr,
        "IdimOptions from the values of the method's option table (_option_values), with IDIM-IV's controller "
        "from a scenario (_idim_iv_scenario) under them.");
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

  m.def("_identify_idim", [](py::object time, py::object force, py::object position, py::object velocity,
                             py::object load, py::object temperature, const IdimOptions& o, const std::string& file,
                             const std::string& sha256, py::object reference, py::object feedforward) {
    IdimData d = trajectory_arrays("identify_idim", time, force, position, velocity, load, temperature, file, sha256);
    // The closed loop's reference and feedforward (IDIM-IV), as long as time when given.
    ArraySpec optional;
    optional.optional = true;
    d.reference = vector_arg(reference, "identify_idim", "reference", optional);
    d.feedforward = vector_arg(feedforward, "identify_idim", "feedforward", optional);
    same_length("identify_idim", {{"time", d.time.size()}, {"reference", d.reference.size()},
                                  {"feedforward", d.feedforward.size()}});
    return finite_answer(run_cancellable([&] { return identify_idim(d, o); }));
  });
  m.def("_cross_test", [](const Result& r, py::object time, py::object force, py::object position, py::object velocity,
                          py::object load, py::object temperature, const IdimOptions& o, const std::string& file,
                          const std::string& sha256) {
    const IdimData d = trajectory_arrays("cross_test", time, force, position, velocity, load, temperature, file, sha256);
    return run_cancellable([&] { return cross_test(r, d, o); });
  });
  m.def("_idim_regression", [](py::object time, py::object force, py::object position, py::object velocity,
                               py::object load, py::object temperature, const IdimOptions& o) {
    const IdimRegression reg =
        idim_regression(trajectory_arrays("idim_regression", time, force, position, velocity, load, temperature, "", ""), o);
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
}

}  // namespace

IdimData trajectory_arrays(const char* function, const py::object& time, const py::object& force,
                           const py::object& position, const py::object& velocity, const py::object& load,
                           const py::object& temperature, const std::string& file, const std::string& sha256) {
  IdimData d;
  d.time = vector_arg(time, function, "time");
  d.force = vector_arg(force, function, "force");
  ArraySpec optional;
  optional.optional = true;
  d.position = vector_arg(position, function, "position", optional);
  d.velocity = vector_arg(velocity, function, "velocity", optional);
  d.load = vector_arg(load, function, "load", optional);
  d.temperature = vector_arg(temperature, function, "temperature", optional);
  same_length(function, {{"time", d.time.size()}, {"force", d.force.size()}, {"position", d.position.size()},
                         {"velocity", d.velocity.size()}, {"load", d.load.size()}, {"temperature", d.temperature.size()}});
  d.file = file;
  d.sha256 = sha256;
  return d;
}

PyMethod idim_binding() { return {"identify_idim", bind, {}}; }

}  // namespace frictionlab::python
