// The registry of the Python module's identification methods: one line per method.
#include "method.hpp"

namespace frictionlab::python {

const std::vector<PyMethod>& py_methods() {
  static const std::vector<PyMethod> methods = {
      idim_binding(),
      breakaway_binding(),
      sweep_binding(),
      decay_binding(),
      lugre_binding(),
      validate_binding(),
  };
  return methods;
}

std::tuple<Eigen::VectorXd, Eigen::VectorXd, Eigen::VectorXd> time_force_velocity(const char* function,
                                                                                 const py::object& time,
                                                                                 const py::object& force,
                                                                                 const py::object& velocity) {
  Eigen::VectorXd t = vector_arg(time, function, "time"), f = vector_arg(force, function, "force"),
                  v = vector_arg(velocity, function, "velocity");
  same_length(function, {{"time", t.size()}, {"force", f.size()}, {"velocity", v.size()}});
  return {std::move(t), std::move(f), std::move(v)};
}

}  // namespace frictionlab::python
