// frictionlab.validate: an identified model simulated in a scenario's plant and controller
// against a measured run. Binds _validate (the keyword API is python/frictionlab/validate.py).
#include "frictionlab/identify/lugre.hpp"
#include "frictionlab/identify/validate.hpp"
#include "frictionlab/io/load.hpp"
#include "frictionlab/io/scenario.hpp"

#include "method.hpp"

namespace frictionlab::python {
namespace {

void bind(py::module_& m) {
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
}

}  // namespace

PyMethod validate_binding() { return {"validate", "validate", bind}; }

}  // namespace frictionlab::python
