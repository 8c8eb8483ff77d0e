// frictionlab.identify_lugre: LuGre parameters by output error on the position. Binds
// _identify_lugre (the keyword API is python/frictionlab/validate.py).
#include "frictionlab/identify/lugre.hpp"

#include <algorithm>

#include "../cancellable.hpp"
#include "method.hpp"

namespace frictionlab::python {
namespace {

// len() of an array argument without converting it; 0 when it has none (None, a number, an
// object len() refuses): vector_arg names what is wrong with it.
double length_of(const py::handle& x) {
  if (x.is_none() || py::isinstance<py::str>(x) || py::isinstance<py::bytes>(x) || !py::hasattr(x, "__len__")) return 0;
  const Py_ssize_t n = PyObject_Length(x.ptr());
  if (n < 0) {
    PyErr_Clear();
    return 0;
  }
  return static_cast<double>(n);
}

void bind(py::module_& m) {
  m.def(
      "_identify_lugre",
      [](const py::handle& time, const py::handle& force, const py::handle& position, const OptionValues& values,
         const py::handle& static_law, const std::string& axis) {
        const char* fn = "identify_lugre";
        LugreOptions o = make_lugre_options(values);
        // The work budget before the arrays are converted and checked (copies of 10^7 samples
        // take seconds): from their lengths alone.
        check_lugre_work(std::max({length_of(time), length_of(force), length_of(position)}), o);
        LugreData d{vector_arg(time, fn, "time"), vector_arg(force, fn, "force"), vector_arg(position, fn, "position")};
        same_length(fn, {{"time", d.time.size()}, {"force", d.force.size()}, {"position", d.position.size()}});
        if (!static_law.is_none()) o.static_law = law_arg(static_law);
        o.axis = parse_axis(axis);
        return finite_answer(run_cancellable([&] { return identify_lugre(d, o); }));  // the fit takes a while
      },
      py::arg("time"), py::arg("force"), py::arg("position"), py::arg("values"), py::arg("static_law"), py::arg("axis"));
}

}  // namespace

PyMethod lugre_binding() { return {"identify_lugre", bind, {}}; }

}  // namespace frictionlab::python
