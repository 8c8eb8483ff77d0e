// Closed-loop (or open-loop) validation of an identified model: frictionlab.validate.
#include <pybind11/stl.h>

#include "common.hpp"
#include "frictionlab/identify/lugre.hpp"
#include "frictionlab/identify/validate.hpp"
#include "frictionlab/io/load.hpp"
#include "frictionlab/io/scenario.hpp"

namespace frictionlab::python {

void init_validate(py::module_& m) {
  m.def(
      "_validate",
      [](const Result& identified, const py::handle& data_arg, const py::handle& scenario_arg, const py::handle& time,
         const py::handle& position, const py::handle& force) {
        const std::string data_path = path_arg(data_arg, "validate", "data"),
                          scenario_path = path_arg(scenario_arg, "validate", "scenario");
        ValidationData v;
        v.time = vector_arg(time, "validate", "time");
        v.position = vector_arg(position, "validate", "position");
        v.force = vector_arg(force, "validate", "force");
        same_length("validate", {{"time", v.time.size()}, {"position", v.position.size()}, {"force", v.force.size()}});
        IdentifiedModel model = model_from_result(identified);
        auto data = std::make_shared<const Dataset>(load_dataset(data_path));
        ScenarioOptions so;
        so.data = data;
        so.law = model.law;
        so.axis = model.axis;
        const Scenario scenario = load_scenario(scenario_path, so);
        v.file = data->file;
        v.sha256 = data->sha256;
        Result r = validate_model(model, scenario, v, {});
        r.data_file = identified.data_file;
        r.data_sha256 = identified.data_sha256;
        return r;
      },
      py::arg("identified"), py::arg("data_path"), py::arg("scenario_path"), py::arg("time"), py::arg("position"),
      py::arg("force"));

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

}  // namespace frictionlab::python
