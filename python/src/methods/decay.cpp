// frictionlab.identify_decay: friction from a free decay's energy lost per half cycle. Binds
// DecayOptions and _identify_decay (the keyword API is python/frictionlab/identify.py).
#include "frictionlab/identify/decay.hpp"

#include "../cancellable.hpp"
#include "method.hpp"

namespace frictionlab::python {
namespace {

void bind(py::module_& m) {
  auto decay_opts = py::class_<DecayOptions>(m, "DecayOptions", "Options of identify_decay.");
  decay_opts.def(py::init<>())
      .def_readwrite("stiffness", &DecayOptions::stiffness, "Restoring stiffness, N/m or N m/rad (pendulum: m g l); NaN: use natural_frequency.")
      .def_readwrite("inertia", &DecayOptions::inertia, "Inertia, kg or kg m^2 (with natural_frequency).")
      .def_readwrite("natural_frequency", &DecayOptions::natural_frequency, "sqrt(k/M), rad/s.")
      .def_readwrite("pendulum", &DecayOptions::pendulum, "Restoring force k sin(x) instead of k x.")
      .def_readwrite("stop_threshold", &DecayOptions::stop_threshold, "|v| below which the motion stopped (NaN: 1e-6 max |v|).");
  m.def("_make_decay_options", &make_decay_options, py::arg("values"),
        "DecayOptions from the values of the method's option table (_option_values).");
  axis_property(decay_opts);

  m.def("_identify_decay", [](py::object time, py::object position, const DecayOptions& o) {
    const DecayData d{vector_arg(time, "identify_decay", "time"), vector_arg(position, "identify_decay", "position")};
    same_length("identify_decay", {{"time", d.time.size()}, {"position", d.position.size()}});
    return finite_answer(run_cancellable([&] { return identify_decay(d, o); }));
  });
}

}  // namespace

PyMethod decay_binding() { return {"identify_decay", bind, {}}; }

}  // namespace frictionlab::python
