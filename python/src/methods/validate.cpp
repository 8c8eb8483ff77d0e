// frictionlab.validate: an identified model simulated in a scenario's plant and controller
// against a measured run. Binds _validate (the keyword API is python/frictionlab/validate.py).
#include "frictionlab/analysis/contour_validation.hpp"
#include "frictionlab/identify/finite_result.hpp"
#include "frictionlab/identify/lugre.hpp"
#include "frictionlab/identify/validate.hpp"
#include "frictionlab/io/load.hpp"
#include "frictionlab/scenario/scenario.hpp"

#include "../cancellable.hpp"
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
        // The files read without the GIL, stopped by Ctrl-C.
        auto data = run_cancellable([&] { return std::make_shared<const Dataset>(load_dataset(data_path)); });
        ScenarioOptions so;
        so.data = data;
        so.law = model.law;
        so.axis = model.axis;
        const Scenario scenario = run_cancellable([&] { return load_scenario(scenario_path, so); });
        v.file = data->file;
        v.sha256 = data->sha256;
        // Numbers or an error (identify/finite_result.hpp), as the command line's validate.
        Result r = finite_answer(finite_or_error(run_cancellable([&] { return validate_model(model, scenario, v, {}); })));
        r.data_file = identified.data_file;
        r.data_sha256 = identified.data_sha256;
        return r;
      },
      py::arg("identified"), py::arg("data_path"), py::arg("scenario_path"), py::arg("time"), py::arg("position"),
      py::arg("force"));

  // A two-axis plant: models by axis name ({"x": Result, ...}), the x and y records (forces
  // optional: None). Returns (Result, measured ContourResult or None, simulated or None).
  m.def(
      "_validate_xy",
      [](const py::dict& models_arg, const py::handle& data_arg, const py::handle& scenario_arg, const py::handle& time,
         const py::handle& x, const py::handle& y, const py::handle& x_force, const py::handle& y_force) {
        const char* fn = "validate_xy";
        const std::string scenario_path = path_arg(scenario_arg, fn, "scenario");
        MultiAxisValidationData v;
        v.time = vector_arg(time, fn, "time");
        v.axes.push_back({"x", vector_arg(x, fn, "x"), x_force.is_none() ? Eigen::VectorXd() : vector_arg(x_force, fn, "x_force")});
        v.axes.push_back({"y", vector_arg(y, fn, "y"), y_force.is_none() ? Eigen::VectorXd() : vector_arg(y_force, fn, "y_force")});
        same_length(fn, {{"time", v.time.size()}, {"x", v.axes[0].position.size()}, {"y", v.axes[1].position.size()}});
        if (!x_force.is_none()) same_length(fn, {{"time", v.time.size()}, {"x_force", v.axes[0].force.size()}});
        if (!y_force.is_none()) same_length(fn, {{"time", v.time.size()}, {"y_force", v.axes[1].force.size()}});
        ScenarioOptions so;
        std::map<std::string, IdentifiedModel> models;
        for (const auto& [key, value] : models_arg) {
          const std::string axis = py::str(key);
          if (!py::isinstance<Result>(value))
            throw argument_type_error(std::string(fn) + ": argument models['" + axis + "']: expected the Result of an identification, got " +
                                    std::string(py::str(value.get_type().attr("__name__"))));
          IdentifiedModel m = model_from_result(value.cast<const Result&>());
          so.axis_models[axis] = AxisModel{m.law, m.axis};
          models.emplace(axis, m);
        }
        std::shared_ptr<const Dataset> data;
        if (!data_arg.is_none()) {
          const std::string data_path = path_arg(data_arg, fn, "data");
          data = run_cancellable([&] { return std::make_shared<const Dataset>(load_dataset(data_path)); });
          so.data = data;
          v.file = data->file;
          v.sha256 = data->sha256;
        }
        const Scenario scenario = run_cancellable([&] { return load_scenario(scenario_path, so); });
        ContourValidation cv = run_cancellable([&] { return validate_contour(scenario, v, models, {}); });
        auto opt = [](const std::optional<ContourResult>& c) { return c ? py::cast(*c) : py::none(); };
        return py::make_tuple(cv.result, opt(cv.measured), opt(cv.simulated));
      },
      py::arg("models"), py::arg("data_path"), py::arg("scenario_path"), py::arg("time"), py::arg("x"), py::arg("y"),
      py::arg("x_force"), py::arg("y_force"));
}

}  // namespace

PyMethod validate_binding() { return {"validate", bind, {}}; }

}  // namespace frictionlab::python
