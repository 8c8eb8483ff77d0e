// frictionlab.identify_lugre: LuGre parameters by output error on the position. Binds
// _identify_lugre (the keyword API is python/frictionlab/validate.py).
#include "frictionlab/identify/lugre.hpp"

#include "../cancellable.hpp"
#include "method.hpp"

namespace frictionlab::python {
namespace {

void bind(py::module_& m) {
  m.def(
      "_identify_lugre",
      [](const py::handle& time, const py::handle& force, const py::handle& position, const OptionValues& values,
         const py::handle& static_law, const std::string& axis) {
        const char* fn = "identify_lugre";
        LugreData d{vector_arg(time, fn, "time"), vector_arg(force, fn, "force"), vector_arg(position, fn, "position")};
        same_length(fn, {{"time", d.time.size()}, {"force", d.force.size()}, {"position", d.position.size()}});
        LugreOptions o = make_lugre_options(values);
        if (!static_law.is_none()) o.static_law = law_arg(static_law);
        o.axis = parse_axis(axis);
        return finite_answer(run_cancellable([&] { return identify_lugre(d, o); }));  // the fit takes a while
      },
      py::arg("time"), py::arg("force"), py::arg("position"), py::arg("values"), py::arg("static_law"), py::arg("axis"));
}

}  // namespace

PyMethod lugre_binding() { return {"identify_lugre", bind, {}}; }

}  // namespace frictionlab::python
