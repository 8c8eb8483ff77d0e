// frictionlab.identify_lugre: LuGre parameters by output error on the position. Binds
// _identify_lugre (the keyword API is python/frictionlab/validate.py).
#include "frictionlab/identify/lugre.hpp"

#include "method.hpp"

namespace frictionlab::python {
namespace {

void bind(py::module_& m) {
  m.def(
      "_identify_lugre",
      [](const py::handle& time, const py::handle& force, const py::handle& position, const py::handle& inertia,
         const py::handle& static_law, const py::handle& delta, const py::handle& stribeck_velocity, int substeps,
         int max_iterations, const std::string& axis, const py::handle& vd) {
        const char* fn = "identify_lugre";
        LugreData d{vector_arg(time, fn, "time"), vector_arg(force, fn, "force"), vector_arg(position, fn, "position")};
        same_length(fn, {{"time", d.time.size()}, {"force", d.force.size()}, {"position", d.position.size()}});
        LugreOptions o;
        o.inertia = number_arg(inertia, fn, "inertia");
        if (!static_law.is_none()) o.static_law = law_arg(static_law);
        o.delta = number_arg(delta, fn, "delta");
        o.stribeck_velocity = number_arg(stribeck_velocity, fn, "stribeck_velocity");
        o.substeps = substeps;
        o.max_iterations = max_iterations;
        o.axis = parse_axis(axis);
        o.vd = number_arg(vd, fn, "vd");
        py::gil_scoped_release release;  // the fit takes a while; let other Python threads run
        return identify_lugre(d, o);
      },
      py::arg("time"), py::arg("force"), py::arg("position"), py::arg("inertia"), py::arg("static_law"),
      py::arg("delta"), py::arg("stribeck_velocity"), py::arg("substeps"), py::arg("max_iterations"), py::arg("axis"), py::arg("vd") = 0.0);
}

}  // namespace

PyMethod lugre_binding() { return {"lugre", "identify_lugre", bind}; }

}  // namespace frictionlab::python
