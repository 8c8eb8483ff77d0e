// frictionlab.identify_sweep: constant-velocity tests to a friction-velocity map and a fitted
// law. Binds SweepOptions, _identify_sweep and _sweep_points (the keyword API is
// python/frictionlab/identify.py; StaticFitOptions, the fit's options, is identify.cpp's).
#include "frictionlab/identify/sweep.hpp"

#include "../cancellable.hpp"
#include "method.hpp"

namespace frictionlab::python {
namespace {

void bind(py::module_& m) {
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
  m.def("_make_sweep_options", &make_sweep_options, py::arg("values"),
        "SweepOptions from the values of the method's option table (_option_values).");
  axis_property(sweep_opts);

  m.def("_identify_sweep", [](py::object time, py::object force, py::object velocity, const SweepOptions& o,
                              py::object load) {
    const auto [t, f, v] = time_force_velocity("identify_sweep", time, force, velocity);
    SweepData d{t, f, v, {}};
    d.load = vector_arg(load, "identify_sweep", "load", ArraySpec{.optional = true});
    return finite_answer(run_cancellable([&] { return identify_sweep(d, o); }));
  });
  m.def("_sweep_points", [](py::object time, py::object force, py::object velocity, const SweepOptions& o,
                            py::object load) {
    const auto [tt, ff, vv] = time_force_velocity("sweep_points", time, force, velocity);
    SweepData d{tt, ff, vv, {}};
    d.load = vector_arg(load, "sweep_points", "load", ArraySpec{.optional = true});
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
    if (d.load.size() > 0) {
      std::vector<double> l;
      for (const auto& p : pts) l.push_back(p.load);
      out["load"] = to_array(l);
    }
    return out;
  });
}

}  // namespace

PyMethod sweep_binding() { return {"identify_sweep", bind, {}}; }

}  // namespace frictionlab::python
