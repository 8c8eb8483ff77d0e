// frictionlab.identify_auto: model selection on held-out data (identify/auto.hpp). Binds
// _identify_auto (the keyword API is python/frictionlab/methods/auto.py): the options come as the
// values of the method's option table, the second record as arrays.
#include "frictionlab/identify/auto.hpp"

#include "../cancellable.hpp"
#include "method.hpp"

namespace frictionlab::python {
namespace {

void bind(py::module_& m) {
  m.def("_identify_auto", [](py::object time, py::object force, py::object position, py::object velocity,
                             const OptionValues& values, const std::string& axis, const std::string& file,
                             const std::string& sha256, py::object heldout) {
    const IdimData d = trajectory_arrays("identify_auto", time, force, position, velocity, py::none(), py::none(), file, sha256);
    AutoOptions o = make_auto_options(values);
    o.axis = parse_axis(axis);
    if (!heldout.is_none()) {
      const py::dict h = heldout.cast<py::dict>();
      const auto get = [&](const char* k) { return h.contains(k) ? py::object(h[k]) : py::object(py::none()); };
      o.heldout = trajectory_arrays("identify_auto: validate", get("time"), get("force"), get("position"), get("velocity"),
                                    py::none(), py::none(), h.contains("file") ? h["file"].cast<std::string>() : std::string(), "");
    }
    return finite_answer(run_cancellable([&] { return identify_auto(d, o); }));
  });
}

}  // namespace

PyMethod auto_binding() { return {"identify_auto", bind, {}}; }

}  // namespace frictionlab::python
