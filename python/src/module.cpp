// The frictionlab Python extension `_core`: friction laws, data files, identification,
// simulation and analysis, numpy in and out. C++ std::invalid_argument and std::logic_error
// become ValueError with the same message; std::runtime_error becomes RuntimeError.
// The bindings live in one file per library layer (laws.cpp, io.cpp, identify.cpp,
// simulate.cpp, analysis.cpp); the friendly keyword API and the plots are pure Python
// (python/frictionlab/*.py).
#include <stdexcept>

#include "common.hpp"
#include "frictionlab/version.hpp"

namespace frictionlab::python {

Eigen::VectorXd vector_arg(const py::handle& x, const std::string& name) {
  const std::vector<double> v = std_vector_arg(x, name);
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

std::vector<double> std_vector_arg(const py::handle& x, const std::string& name) {
  if (x.is_none()) return {};
  py::array_t<double, py::array::c_style | py::array::forcecast> a;
  try {
    a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(x);
  } catch (const py::error_already_set&) {
  }
  if (!a) {
    PyErr_Clear();
    throw std::invalid_argument(name + ": expected a 1-D array of numbers, got " +
                                py::cast<std::string>(py::str(py::type::of(x).attr("__name__"))));
  }
  if (a.ndim() != 1) {
    throw std::invalid_argument(name + ": expected a 1-D array of numbers, got an array with " +
                                std::to_string(a.ndim()) + " dimensions");
  }
  return std::vector<double>(a.data(), a.data() + a.shape(0));
}

std::string path_arg(const py::handle& p) {
  return py::cast<std::string>(py::module_::import("os").attr("fspath")(p));
}

py::array_t<double> to_array(std::span<const double> values) {
  py::array_t<double> out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

}  // namespace frictionlab::python

PYBIND11_MODULE(_core, m) {
  namespace fp = frictionlab::python;
  m.doc() = "frictionlab: friction models, simulation and identification (SI units throughout).";
  m.attr("__version__") = frictionlab::kVersion;

  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const std::logic_error& e) {
      // invalid_argument derives from logic_error: both are the caller's mistake.
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  fp::init_laws(m);
  fp::init_io(m);
  fp::init_identify(m);
  fp::init_simulate(m);
  fp::init_analysis(m);
  fp::init_validate(m);
}
