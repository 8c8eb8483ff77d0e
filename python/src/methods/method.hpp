#pragma once
// One identification method of the Python module, declared in one file under python/src/methods/:
// what binds its options class and its `_core` entry points, and the public function of the
// frictionlab package that wraps them with keywords (python/frictionlab/identify.py,
// validate.py). The library's side of a method (name, summary, fitted signal) is
// frictionlab/identify/method.hpp (with its option table, which makes the keywords: see
// option_values); the command line's is app/methods/. Adding a method:
// python/src/methods/NAME.cpp defining NAME_binding(), and its line in FRICTIONLAB_METHODS.
#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include "../result.hpp"
#include "frictionlab/identify/idim.hpp"
#include "frictionlab/identify/method.hpp"

namespace frictionlab::python {

struct PyMethod {
  std::string function;  ///< the frictionlab function a user calls: "identify_idim", "validate"
  /// Binds the method's options class and its `_core._identify_NAME` (or `_NAME`) functions;
  /// called once when the module loads, after the Result classes.
  std::function<void(py::module_& m)> bind;
  std::string name;  ///< the library's method name, set by the registry (FRICTIONLAB_METHODS)
};

#define FRICTIONLAB_PY_METHOD_DECL(method) PyMethod method##_binding();
FRICTIONLAB_METHODS(FRICTIONLAB_PY_METHOD_DECL)
#undef FRICTIONLAB_PY_METHOD_DECL

/// The option values of `method` from Python keywords (a dict keyword -> value, the keyword as
/// the caller wrote it: the table's keyword or a deprecated one; None: not given), each checked
/// by the method's option table (check_option), named "METHOD: KEYWORD" in messages. Column and
/// file options are the wrapper's to pass (arrays, laws), not here.
/// \throws argument_type_error for a value of no option type (an object, a dict);
///         std::invalid_argument for a keyword the table lacks or a bad value.
OptionValues option_values(const MethodInfo& method, const py::dict& keywords);

/// Binds OptionValues, _option_values(method, dict), Result._record_options and the tables
/// (called once, after the Result classes).
void bind_option_tables(py::module_& m);

/// Every method's binding, in the library's order.
const std::vector<PyMethod>& py_methods();

/// A trajectory record (idim, auto) from arrays: time (s), force (N or N m), position (m or rad)
/// and velocity (m/s or rad/s), load (N or N m) and temperature (degC or K), each but time and
/// force optional (None), all of equal length; `file` and `sha256` name the source.
/// \throws argument_type_error, std::invalid_argument naming `function` and the argument.
IdimData trajectory_arrays(const char* function, const py::object& time, const py::object& force,
                           const py::object& position, const py::object& velocity, const py::object& load,
                           const py::object& temperature, const std::string& file, const std::string& sha256);

/// time (s), force (N or N m) and velocity (m/s or rad/s) of a method on records of one drive
/// (breakaway, sweep), checked by vector_arg and of equal lengths (same_length).
/// \throws argument_type_error, std::invalid_argument naming `function` and the argument.
std::tuple<Eigen::VectorXd, Eigen::VectorXd, Eigen::VectorXd> time_force_velocity(const char* function,
                                                                                 const py::object& time,
                                                                                 const py::object& force,
                                                                                 const py::object& velocity);

}  // namespace frictionlab::python
