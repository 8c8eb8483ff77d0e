#pragma once
// Shared helpers of the frictionlab Python extension: numpy conversions and the per-layer
// init functions (one .cpp per library layer: laws, io, identify, simulate, analysis; the
// identification Result is result.hpp, each method is methods/NAME.cpp).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <initializer_list>
#include <map>
#include <span>
#include <stdexcept>
#include <utility>
#include <string>
#include <vector>

#include "frictionlab/models/friction_law.hpp"

namespace frictionlab::python {

namespace py = pybind11;

/// An argument of the wrong type (None, a str, an object or complex array): raised in Python as
/// frictionlab._core.ArgumentTypeError, a subclass of both TypeError and ValueError (callers
/// written for either catch it).
struct argument_type_error : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// What an array argument may be (check_array).
struct ArraySpec {
  std::size_t min_size = 2;  ///< fewest samples; 0 accepts an empty array
  bool optional = false;     ///< None gives an empty array instead of an error
  bool any_shape = false;    ///< any number of dimensions (element-wise functions); else 1-D only
  bool finite = true;        ///< NaN and inf refused
};

/// The one check of an array argument of a public function (every binding calls it): accepts a
/// numpy array of integer or float dtype, or a list/tuple of numbers, of any memory layout
/// (non-contiguous and other dtypes are copied to contiguous float64). Messages name the function
/// and the argument: "identify_sweep: argument velocity is empty; expected at least 2 samples".
/// \throws argument_type_error for None (unless spec.optional), a value that is not an array of
///         numbers ("FUNCTION: argument NAME: expected a 1-D array of numbers, got str"), a bool,
///         complex, object, string or datetime dtype; std::invalid_argument for a 0-d or 2-D
///         array (unless spec.any_shape), fewer than spec.min_size samples, a NaN or inf (with its
///         index; unless !spec.finite).
py::array_t<double, py::array::c_style> check_array(const py::handle& x, const std::string& function,
                                                     const std::string& name, const ArraySpec& spec = {});

/// check_array as an Eigen vector (1-D).
Eigen::VectorXd vector_arg(const py::handle& x, const std::string& function, const std::string& name,
                           const ArraySpec& spec = {});

/// check_array as a std::vector (1-D; for the span-based analysis functions).
std::vector<double> std_vector_arg(const py::handle& x, const std::string& function, const std::string& name,
                                   const ArraySpec& spec = {});

/// Refuses arrays of unequal lengths, naming them: "FUNCTION: arguments time (100 samples) and
/// force (99 samples) differ in length; expected equal lengths". Empty (absent optional) arrays
/// are skipped. \throws std::invalid_argument.
struct NamedLength {
  const char* name;
  std::size_t size;
  template <class Int>
  NamedLength(const char* n, Int s) : name(n), size(static_cast<std::size_t>(s)) {}
};
void same_length(const std::string& function, std::initializer_list<NamedLength> arrays);

/// A finite number argument (a Python int or float, a numpy scalar). \throws argument_type_error
/// for None or a non-number, std::invalid_argument for NaN or inf, naming the argument.
double number_arg(const py::handle& x, const std::string& function, const std::string& name);

/// A compensation given as a type name or a dict {"type": TYPE, parameter: value, ...}
/// (control/compensation_spec.hpp): its type and parameters. `function` and `name` name the
/// argument in messages. \throws argument_type_error for anything else or a type that is not a
/// string, std::invalid_argument for a dict without 'type' or a parameter that is not a finite number.
std::pair<std::string, std::map<std::string, double>> compensation_arg(const py::handle& c, const std::string& function,
                                                                       const std::string& name);

/// A new numpy array holding a copy of the values.
py::array_t<double> to_array(std::span<const double> values);
inline py::array_t<double> to_array(const Eigen::VectorXd& v) { return to_array(std::span<const double>(v.data(), static_cast<std::size_t>(v.size()))); }

/// A file path from a str or os.PathLike (pathlib.Path). \throws argument_type_error naming the
/// function and argument for anything else (None, a number, an array).
std::string path_arg(const py::handle& p, const std::string& function = "", const std::string& name = "path");

/// A friction law from a FrictionLaw or its dict form {"law": name, param: value, ...}.
FrictionLaw law_arg(const py::handle& x);
/// The law in its dict form (the form law_arg accepts).
py::dict law_to_dict(const FrictionLaw& law);

void init_laws(py::module_& m);
void init_io(py::module_& m);
void init_result(py::module_& m);  // result.hpp: the Result classes, before any method
void init_identify(py::module_& m);
void init_simulate(py::module_& m);
void init_analysis(py::module_& m);

}  // namespace frictionlab::python
