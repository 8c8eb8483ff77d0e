#pragma once
// One identification method of the Python module, declared in one file under python/src/methods/:
// what binds its options class and its `_core` entry points, and the public function of the
// frictionlab package that wraps them with keywords (python/frictionlab/identify.py,
// validate.py). The library's side of a method (name, summary, fitted signal) is
// frictionlab/identify/method.hpp; the command line's is app/methods/. Adding a method:
// python/src/methods/NAME.cpp defining NAME_binding(), and one line in methods.cpp.
#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include "../result.hpp"

namespace frictionlab::python {

struct PyMethod {
  std::string name;      ///< the library's method name (identification_methods()): "idim", ...
  std::string function;  ///< the frictionlab function a user calls: "identify_idim", "validate"
  /// Binds the method's options class and its `_core._identify_NAME` (or `_NAME`) functions;
  /// called once when the module loads, after the Result classes.
  std::function<void(py::module_& m)> bind;
};

PyMethod idim_binding();
PyMethod breakaway_binding();
PyMethod sweep_binding();
PyMethod decay_binding();
PyMethod lugre_binding();
PyMethod validate_binding();

/// Every method's binding, in the library's order.
const std::vector<PyMethod>& py_methods();

/// time (s), force (N or N m) and velocity (m/s or rad/s) of a method on records of one drive
/// (breakaway, sweep), checked by vector_arg and of equal lengths (same_length).
/// \throws argument_type_error, std::invalid_argument naming `function` and the argument.
std::tuple<Eigen::VectorXd, Eigen::VectorXd, Eigen::VectorXd> time_force_velocity(const char* function,
                                                                                 const py::object& time,
                                                                                 const py::object& force,
                                                                                 const py::object& velocity);

}  // namespace frictionlab::python
