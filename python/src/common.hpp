#pragma once
// Shared helpers of the frictionlab Python extension: numpy conversions and the per-layer
// init functions (one .cpp per library layer: laws, io, identify, simulate, analysis).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "frictionlab/models/friction_law.hpp"

namespace frictionlab::python {

namespace py = pybind11;

/// A 1-D float64 copy of any array-like (list, numpy array of any numeric dtype).
/// \throws std::invalid_argument "NAME: expected a 1-D array of numbers, got ..." otherwise.
Eigen::VectorXd vector_arg(const py::handle& x, const std::string& name);

/// Same, as a std::vector (for the span-based analysis functions); None gives an empty vector.
std::vector<double> std_vector_arg(const py::handle& x, const std::string& name);

/// A new numpy array holding a copy of the values.
py::array_t<double> to_array(std::span<const double> values);
inline py::array_t<double> to_array(const Eigen::VectorXd& v) { return to_array(std::span<const double>(v.data(), static_cast<std::size_t>(v.size()))); }

/// A file path from a str or os.PathLike (pathlib.Path).
std::string path_arg(const py::handle& p);

/// A friction law from a FrictionLaw or its dict form {"law": name, param: value, ...}.
FrictionLaw law_arg(const py::handle& x);
/// The law in its dict form (the form law_arg accepts).
py::dict law_to_dict(const FrictionLaw& law);

void init_laws(py::module_& m);
void init_io(py::module_& m);
void init_identify(py::module_& m);
void init_simulate(py::module_& m);
void init_analysis(py::module_& m);
void init_validate(py::module_& m);

}  // namespace frictionlab::python
