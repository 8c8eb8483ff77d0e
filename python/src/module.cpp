// The frictionlab Python extension `_core`: friction laws, data files, identification,
// simulation and analysis, numpy in and out. C++ std::invalid_argument and std::logic_error
// become ValueError with the same message; std::runtime_error becomes RuntimeError.
// The bindings live in one file per library layer (laws.cpp, io.cpp, identify.cpp,
// simulate.cpp, analysis.cpp), the identification Result in result.cpp, and each identification
// method in its own file (methods/NAME.cpp, registered in methods/methods.cpp); the friendly
// keyword API and the plots are pure Python (python/frictionlab/*.py).
#include <cmath>
#include <stdexcept>

#include "cancellable.hpp"
#include "common.hpp"
#include "frictionlab/budget.hpp"
#include "frictionlab/cancellation.hpp"
#include "frictionlab/error.hpp"
#include "frictionlab/version.hpp"

namespace frictionlab::python {

namespace {

unsigned long python_main_thread = 0;  // threading.main_thread().ident, set at import

std::string type_name(const py::handle& x) { return py::cast<std::string>(py::str(py::type::of(x).attr("__name__"))); }

std::string prefix(const std::string& function) { return function.empty() ? std::string() : function + ": "; }

std::string shape_text(const py::array& a) {
  if (a.ndim() == 0) return "a number (0-d)";
  std::string s = "a " + std::to_string(a.ndim()) + "-D array of shape (";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + ")";
}

}  // namespace

void remember_python_main_thread() {
  python_main_thread = py::module_::import("threading").attr("main_thread")().attr("ident").cast<unsigned long>();
}

bool on_python_main_thread() { return python_main_thread != 0 && PyThread_get_thread_ident() == python_main_thread; }

py::array_t<double, py::array::c_style> check_array(const py::handle& x, const std::string& function,
                                                     const std::string& name, const ArraySpec& spec) {
  const std::string arg = prefix(function) + "argument " + name;
  const std::string expected = spec.any_shape ? "a number or an array of numbers" : "a 1-D array of numbers";
  if (x.is_none()) {
    if (spec.optional) return py::array_t<double, py::array::c_style>(0);
    throw argument_type_error(arg + ": expected " + expected + ", got None");
  }
  // Strings, bytes, dicts, sets, bools: numpy would make a 0-d or object array of them.
  if (py::isinstance<py::str>(x) || py::isinstance<py::bytes>(x) || py::isinstance<py::dict>(x) ||
      py::isinstance<py::set>(x) || py::isinstance<py::bool_>(x))
    throw argument_type_error(arg + ": expected " + expected + ", got " + type_name(x));
  py::array a;
  try {
    a = py::module_::import("numpy").attr("asarray")(x);
  } catch (const py::error_already_set&) {  // a ragged list, an object numpy cannot read
    throw argument_type_error(arg + ": expected " + expected + ", got a " + type_name(x) + " that is not an array of numbers");
  }
  const char kind = py::cast<std::string>(a.dtype().attr("kind"))[0];
  if (kind != 'i' && kind != 'u' && kind != 'f') {
    const std::string what = kind == 'b'                  ? "bool"
                             : kind == 'c'                ? "complex"
                             : kind == 'O'                ? "object"
                             : (kind == 'U' || kind == 'S') ? "string"
                             : (kind == 'M' || kind == 'm') ? "datetime"
                                                          : "not numbers";
    throw argument_type_error(arg + ": expected " + expected + ", got " +
                              (a.ndim() == 0 ? type_name(x)
                                             : "an array of dtype " + py::cast<std::string>(py::str(a.dtype())) + " (" + what + ")"));
  }
  if (!spec.any_shape && a.ndim() != 1) throw std::invalid_argument(arg + ": expected " + expected + ", got " + shape_text(a));
  // A contiguous float64 copy when the layout or dtype differ (strided slices, int arrays).
  auto out = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  if (!out) {
    PyErr_Clear();
    throw argument_type_error(arg + ": expected " + expected + ", got " + type_name(x));
  }
  const auto n = static_cast<std::size_t>(out.size());
  if (n < spec.min_size) {
    if (n == 0) throw std::invalid_argument(arg + " is empty; expected at least " + std::to_string(spec.min_size) + " samples");
    throw std::invalid_argument(arg + " has " + std::to_string(n) + " sample" + (n == 1 ? "" : "s") + "; expected at least " +
                                std::to_string(spec.min_size));
  }
  if (spec.finite) {
    const double* d = out.data();
    for (std::size_t i = 0; i < n; ++i)
      if (!std::isfinite(d[i]))
        throw std::invalid_argument(arg + " has " + (std::isnan(d[i]) ? "NaN" : d[i] > 0 ? "inf" : "-inf") + " at index " +
                                    std::to_string(i) + "; expected finite numbers");
  }
  return out;
}

Eigen::VectorXd vector_arg(const py::handle& x, const std::string& function, const std::string& name, const ArraySpec& spec) {
  const auto a = check_array(x, function, name, spec);
  return Eigen::Map<const Eigen::VectorXd>(a.data(), static_cast<Eigen::Index>(a.size()));
}

std::vector<double> std_vector_arg(const py::handle& x, const std::string& function, const std::string& name,
                                   const ArraySpec& spec) {
  const auto a = check_array(x, function, name, spec);
  return std::vector<double>(a.data(), a.data() + a.size());
}

void same_length(const std::string& function, std::initializer_list<NamedLength> arrays) {
  const NamedLength* first = nullptr;
  for (const auto& a : arrays) {
    if (a.size == 0) continue;
    if (!first) {
      first = &a;
    } else if (a.size != first->size) {
      throw std::invalid_argument(prefix(function) + "arguments " + first->name + " (" + std::to_string(first->size) +
                                  " samples) and " + a.name + " (" + std::to_string(a.size) +
                                  " samples) differ in length; expected equal lengths");
    }
  }
}

std::pair<std::string, std::map<std::string, double>> compensation_arg(const py::handle& c, const std::string& function,
                                                                       const std::string& name) {
  const std::string where = function + ": argument " + name;
  std::string type;
  std::map<std::string, double> values;
  if (py::isinstance<py::str>(c)) {
    type = py::cast<std::string>(c);
  } else if (py::isinstance<py::dict>(c)) {
    for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(c)) {
      const std::string k = py::cast<std::string>(py::str(key));
      if (k == "type") {
        if (!py::isinstance<py::str>(value)) throw argument_type_error(where + "['type']: expected a compensation name");
        type = py::cast<std::string>(value);
      } else {
        values[k] = number_arg(value, function, name + "['" + k + "']");
      }
    }
    if (type.empty())
      throw std::invalid_argument(where + ": missing 'type' (feedforward, feedback, lugre-observer or disturbance-observer)");
  } else {
    throw argument_type_error(where + ": expected None, a compensation name or a dict {'type': NAME, parameter: value}");
  }
  return {type, values};
}

double number_arg(const py::handle& x, const std::string& function, const std::string& name) {
  const std::string arg = prefix(function) + "argument " + name;
  if (x.is_none() || py::isinstance<py::bool_>(x) || py::isinstance<py::str>(x))
    throw argument_type_error(arg + ": expected a number, got " + (x.is_none() ? std::string("None") : type_name(x)));
  double v;
  try {
    v = py::cast<double>(py::float_(py::reinterpret_borrow<py::object>(x)));
  } catch (const py::error_already_set&) {
    throw argument_type_error(arg + ": expected a number, got " + type_name(x));
  }
  if (!std::isfinite(v)) throw std::invalid_argument(arg + " is " + (std::isnan(v) ? "NaN" : "infinite") + "; expected a finite number");
  return v;
}

std::string path_arg(const py::handle& p, const std::string& function, const std::string& name) {
  if (!py::isinstance<py::str>(p) && !py::hasattr(p, "__fspath__"))
    throw argument_type_error(prefix(function) + "argument " + name + ": expected a file path (str or os.PathLike), got " +
                              (p.is_none() ? std::string("None") : type_name(p)));
  return py::cast<std::string>(py::module_::import("os").attr("fspath")(p));
}

py::array_t<double> to_array(std::span<const double> values) {
  py::array_t<double> out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

void init_export(py::module_& m);  // export.cpp: export_c (the C header of export/c_export.hpp)
void init_contour(py::module_& m);  // contour.cpp: analyze_contour (analysis/contour.hpp)
void init_plan(py::module_& m);  // plan.cpp: _plan, the core of frictionlab.plan (analysis/plan/plan.hpp)

}  // namespace frictionlab::python

PYBIND11_MODULE(_core, m) {
  namespace fp = frictionlab::python;
  m.doc() = "frictionlab: friction models, simulation and identification (SI units throughout).";
  m.attr("__version__") = frictionlab::kVersion;
  fp::remember_python_main_thread();

  // Wrong-type arguments: a TypeError that is also a ValueError (code catching either works).
  static pybind11::handle argument_type_error_class;
  {
    pybind11::tuple bases = pybind11::make_tuple(pybind11::handle(PyExc_TypeError), pybind11::handle(PyExc_ValueError));
    argument_type_error_class = PyErr_NewExceptionWithDoc(
        "frictionlab._core.ArgumentTypeError",
        "An argument of the wrong type (None, a string, an object or complex array); a TypeError and a ValueError.",
        bases.ptr(), nullptr);
    m.attr("ArgumentTypeError") = pybind11::handle(argument_type_error_class);
  }
  // Bad input with a code (frictionlab/error.hpp): frictionlab.Error, a ValueError with .code
  // and the fields that apply as attributes (file, row, column, key, option, value, other_file,
  // other_option; None when they do not apply).
  static pybind11::handle error_class;
  {
    error_class = PyErr_NewExceptionWithDoc(
        "frictionlab._core.Error",
        "Bad input (a data file, a scenario, an option): a ValueError with a stable .code (e.g. "
        "'data.column_missing', 'scenario.key_unknown', 'output.exists'; the table is in frictionlab/error.hpp) "
        "and the fields that locate the fault: .file, .row, .column, .key, .option, .value, .other_file, "
        ".other_option (None when they do not apply).",
        PyExc_ValueError, nullptr);
    m.attr("Error") = pybind11::handle(error_class);
  }
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const frictionlab::Cancelled&) {  // work whose token was cancelled (cancellable.hpp)
      PyErr_SetNone(PyExc_KeyboardInterrupt);
    } catch (const fp::argument_type_error& e) {
      PyErr_SetString(argument_type_error_class.ptr(), e.what());
    } catch (const frictionlab::InputError& e) {
      // Build the instance (args = (message,)) and set its attributes; a failure here falls back
      // to a plain ValueError with the message.
      const std::string what = e.what();
      PyObject* message = PyUnicode_DecodeUTF8(what.data(), static_cast<Py_ssize_t>(what.size()), "backslashreplace");
      PyObject* instance = message ? PyObject_CallFunctionObjArgs(error_class.ptr(), message, nullptr) : nullptr;
      Py_XDECREF(message);
      if (!instance) {
        PyErr_Clear();
        PyErr_SetString(PyExc_ValueError, e.what());
        return;
      }
      pybind11::object obj = pybind11::reinterpret_steal<pybind11::object>(instance);
      try {
        const frictionlab::ErrorFields& f = e.fields();
        const auto text = [](const std::string& v) -> pybind11::object {
          if (v.empty()) return pybind11::none();
          return pybind11::reinterpret_steal<pybind11::object>(
              PyUnicode_DecodeUTF8(v.data(), static_cast<Py_ssize_t>(v.size()), "surrogateescape"));
        };
        obj.attr("code") = pybind11::str(e.code());
        obj.attr("file") = text(f.file);
        obj.attr("row") = f.row ? pybind11::object(pybind11::int_(*f.row)) : pybind11::none();
        obj.attr("column") = text(f.column);
        obj.attr("key") = text(f.key);
        obj.attr("option") = text(f.option);
        obj.attr("value") = text(f.value);
        obj.attr("other_file") = text(f.other_file);
        obj.attr("other_option") = text(f.other_option);
      } catch (const pybind11::error_already_set&) {
        PyErr_Clear();
      }
      PyErr_SetObject(error_class.ptr(), obj.ptr());
    } catch (const std::logic_error& e) {
      // invalid_argument derives from logic_error: both are the caller's mistake.
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  // The work and memory budget's factor (frictionlab/budget.hpp): the command line's --budget.
  m.def("set_budget_factor", &frictionlab::set_budget_factor, pybind11::arg("factor"),
        "Raises (or lowers) the work and memory budget that every call checks before its work: the work "
        "budget times `factor`, the memory budget too but never beyond what the process may use; the "
        "command line's --budget FACTOR. Process-wide. factor: finite, >= 1e-6 (default 1); raises "
        "frictionlab.Error (option.out_of_range) otherwise.");
  m.def("budget_factor", &frictionlab::budget_factor, "The budget factor in effect (default 1).");
  fp::init_laws(m);
  fp::init_io(m);
  fp::init_result(m);
  fp::init_identify(m);
  fp::init_simulate(m);
  fp::init_analysis(m);
  fp::init_export(m);
  fp::init_contour(m);
  fp::init_plan(m);
}
