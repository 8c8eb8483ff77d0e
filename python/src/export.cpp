// Code for the drive: frictionlab.export_c, the C99 header of export/c_export.hpp.
#include <pybind11/stl.h>

#include <optional>

#include "common.hpp"
#include "frictionlab/identify/validate.hpp"
#include "io/atomic_write.hpp"
#include "frictionlab/export/c_export.hpp"
#include "frictionlab/scenario/model_file.hpp"

namespace frictionlab::python {
namespace {

// The law and, where known, the identified inertia M (the disturbance observer's default).
ModelFile model_arg(const py::handle& model) {
  if (py::isinstance<Result>(model)) {
    const IdentifiedModel m = model_from_result(py::cast<const Result&>(model));
    return {m.law, m.axis.M > 0 ? std::optional<double>(m.axis.M) : std::nullopt};
  }
  if (py::isinstance<FrictionLaw>(model) || py::isinstance<py::dict>(model)) return {law_arg(model), std::nullopt};
  if (py::isinstance<py::str>(model) || py::hasattr(model, "__fspath__"))
    return read_model_file(path_arg(model, "export_c", "model"));
  throw argument_type_error(
      "export_c: argument model: expected a FrictionLaw, a law dict, an identification Result or the path of a "
      "MODEL.json, got " + py::cast<std::string>(py::str(py::type::of(model).attr("__name__"))));
}

// None, a type name, or {"type": TYPE, parameter: value, ...}, on the model's inertia.
CompensationParams compensation_params(const py::handle& c, const ModelFile& model) {
  if (c.is_none()) return {};
  const auto [type, values] = compensation_arg(c, "export_c", "compensation");
  try {
    return make_compensation(type, values, model.inertia);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("export_c: argument compensation: ") + e.what());
  }
}

}  // namespace

void init_export(py::module_& m) {
  m.def(
      "export_c",
      [](const py::handle& model, const py::handle& compensation, bool single, const std::string& prefix,
         const py::handle& path, bool overwrite) {
        const ModelFile em = model_arg(model);
        CExportOptions o;
        o.compensation = compensation_params(compensation, em);
        o.single_precision = single;
        o.prefix = prefix;
        if (!path.is_none()) {
          const std::string p = path_arg(path, "export_c", "path");
          try {
            check_output_path(p, overwrite);  // before any work, as the command line does
          } catch (const std::invalid_argument& e) {
            std::string message = e.what();  // in Python's words: the keyword, not the CLI flag
            if (const auto at = message.find("--overwrite"); at != std::string::npos)
              message.replace(at, 11, "overwrite=True");
            throw std::invalid_argument("export_c: argument path: " + message);
          }
          const std::string text = c_header(em.law, o);
          write_file_atomic(p, text, {overwrite});
          return text;
        }
        return c_header(em.law, o);
      },
      py::arg("model"), py::arg("compensation") = py::none(), py::arg("float") = false, py::arg("prefix") = "friction",
      py::arg("path") = py::none(), py::arg("overwrite") = false,
      R"doc(The friction law (and a compensation) as one dependency-free C99 header for a drive's firmware;
returns the header's text, and writes it to `path` when given (atomically; an existing file only with
overwrite=True). The same header as `frictionlab export MODEL.json --c FILE.h`.

model: a FrictionLaw, a law dict, an identification Result, or the path of a MODEL.json / law file.
compensation: None, "feedforward", "feedback", "lugre-observer" (needs a lugre law),
  "disturbance-observer", or a dict {"type": NAME, ...parameters}: band (feedforward, m/s or rad/s),
  dead_band (feedback, m/s or rad/s), gain (lugre-observer, 1/s), bandwidth (rad/s) and inertia
  (kg or kg m^2; default the model's M) for disturbance-observer.
float: single precision (float constants, states and math) instead of double.
prefix: prefix of every C name (a C identifier).
Functions in the header (SI units; N m, rad/s on a rotary axis): PREFIX_friction(v); static laws
PREFIX_friction_stuck(v, applied); dynamic laws PREFIX_state, PREFIX_init(&s), PREFIX_update(&s, v, dt);
and the compensation's PREFIX_feedforward(vr), PREFIX_feedback(v), PREFIX_lugre_observer_update(&s, x, v, r, dt)
or PREFIX_disturbance_observer_update(&s, v, drive, dt).
Raises ValueError naming the argument for a compensation that does not fit the law, a bad parameter or prefix.)doc");
}

}  // namespace frictionlab::python
