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
      [](const Result& identified, const std::string& data_path, const std::string& scenario_path, const py::handle& time,
         const py::handle& position, const py::handle& force) {
        IdentifiedModel model = model_from_result(identified);
        auto data = std::make_shared<const Dataset>(load_dataset(data_path));
        ScenarioOptions so;
        so.data = data;
        so.law = model.law;
        so.axis = model.axis;
        const Scenario scenario = load_scenario(scenario_path, so);
        ValidationData v;
        v.time = vector_arg(time, "time");
        v.position = vector_arg(position, "position");
        v.force = vector_arg(force, "force");
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
      [](const py::handle& time, const py::handle& force, const py::handle& position, double inertia,
         const py::handle& static_law, double delta, double stribeck_velocity, int substeps, int max_iterations,
         const std::string& axis, double vd) {
        LugreData d{vector_arg(time, "time"), vector_arg(force, "force"), vector_arg(position, "position")};
        LugreOptions o;
        o.inertia = inertia;
        if (!static_law.is_none()) o.static_law = law_arg(static_law);
        o.delta = delta;
        o.stribeck_velocity = stribeck_velocity;
        o.substeps = substeps;
        o.max_iterations = max_iterations;
        o.axis = parse_axis(axis);
        o.vd = vd;
        py::gil_scoped_release release;  // the fit takes a while; let other Python threads run
        return identify_lugre(d, o);
      },
      py::arg("time"), py::arg("force"), py::arg("position"), py::arg("inertia"), py::arg("static_law"),
      py::arg("delta"), py::arg("stribeck_velocity"), py::arg("substeps"), py::arg("max_iterations"), py::arg("axis"), py::arg("vd") = 0.0);
}

}  // namespace frictionlab::python
