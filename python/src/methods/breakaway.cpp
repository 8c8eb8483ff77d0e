// frictionlab.identify_breakaway: the torque-mode trapezoid experiment. Binds BreakawayOptions
// and _identify_breakaway (the keyword API is python/frictionlab/identify.py).
#include "frictionlab/identify/breakaway.hpp"

#include "../cancellable.hpp"
#include "method.hpp"

namespace frictionlab::python {
namespace {

void bind(py::module_& m) {
  auto brk_opts = py::class_<BreakawayOptions>(m, "BreakawayOptions", "Options of identify_breakaway.");
  brk_opts.def(py::init<>())
      .def_readwrite("inertia", &BreakawayOptions::inertia, "Inertia held fixed, kg m^2 or kg (NaN: estimated as M).")
      .def_readwrite("velocity_threshold", &BreakawayOptions::velocity_threshold, "|v| above which the axis moves, rad/s or m/s (NaN: 1 % of max |v|).")
      .def_readwrite("edge_samples", &BreakawayOptions::edge_samples, "Samples skipped at each end of a sliding interval (2).");
  m.def("_make_breakaway_options", &make_breakaway_options, py::arg("values"),
        "BreakawayOptions from the values of the method's option table (_option_values).");
  axis_property(brk_opts);

  m.def("_identify_breakaway", [](py::object time, py::object force, py::object velocity, const BreakawayOptions& o,
                                  py::object load) {
    const auto [t, f, v] = time_force_velocity("identify_breakaway", time, force, velocity);
    BreakawayData d{t, f, v, {}};
    d.load = vector_arg(load, "identify_breakaway", "load", ArraySpec{.optional = true});
    return finite_answer(run_cancellable([&] { return identify_breakaway(d, o); }));
  });
}

}  // namespace

PyMethod breakaway_binding() { return {"identify_breakaway", bind, {}}; }

}  // namespace frictionlab::python
