// Code for the drive: frictionlab.export_c, the C99 header of export/c_export.hpp; and
// frictionlab.export_mjcf, the MuJoCo model of export/mjcf_export.hpp.
#include <pybind11/stl.h>

#include <filesystem>
#include <optional>

#include "cancellable.hpp"
#include "common.hpp"
#include "frictionlab/error.hpp"
#include "frictionlab/identify/validate.hpp"
#include "io/atomic_write.hpp"
#include "frictionlab/export/c_export.hpp"
#include "frictionlab/export/mjcf_export.hpp"
#include "frictionlab/models/parameter.hpp"
#include "frictionlab/scenario/model_file.hpp"

namespace frictionlab::python {
namespace {

// The law and, where known, the identified inertia M (the disturbance observer's default and the
// MuJoCo body's), the axis and the offset. `function` names the caller in messages.
ModelFile model_arg(const py::handle& model, const std::string& function = "export_c") {
  if (py::isinstance<Result>(model)) {
    const Result& r = py::cast<const Result&>(model);
    const IdentifiedModel m = model_from_result(r);
    ModelFile f{m.law, m.axis.M > 0 ? std::optional<double>(m.axis.M) : std::nullopt};
    f.axis = r.axis;
    f.offset = -m.axis.offset;  // the plant's offset is the negative of the identified one
    return f;
  }
  if (py::isinstance<FrictionLaw>(model) || py::isinstance<py::dict>(model)) return {law_arg(model), std::nullopt};
  if (py::isinstance<py::str>(model) || py::hasattr(model, "__fspath__"))
  {
    const std::string path = path_arg(model, function, "model");
    return run_cancellable([&] { return read_model_file(path); });  // a file read: without the GIL, Ctrl-C stops it
  }
  throw argument_type_error(
      function + ": argument model: expected a FrictionLaw, a law dict, an identification Result or the path of a "
      "MODEL.json, got " + py::cast<std::string>(py::str(py::type::of(model).attr("__name__"))));
}

// The path argument checked before any work, in Python's words (overwrite=True, not --overwrite).
void check_path(const std::string& p, bool overwrite, const std::string& function) {
  try {
    check_output_path(p, overwrite);
  } catch (const std::invalid_argument& e) {
    std::string message = e.what();
    if (const auto at = message.find("--overwrite"); at != std::string::npos) message.replace(at, 11, "overwrite=True");
    throw std::invalid_argument(function + ": argument path: " + message);
  }
}

py::dict export_mjcf(const py::handle& model, const py::handle& path, std::optional<double> inertia, double armature,
                     double timestep, const std::optional<std::string>& axis, bool overwrite) {
  const ModelFile em = model_arg(model, "export_mjcf");
  std::string p;
  if (!path.is_none()) {
    p = path_arg(path, "export_mjcf", "path");
    check_path(p, overwrite, "export_mjcf");
  }
  const std::optional<double> fc = mjcf_coulomb_level(em.law);
  if (!fc)
    throw InputError(errc::scenario_key_missing,
                     "export_mjcf: argument model: law " + em.law.name() +
                         " has no Fc: MuJoCo's frictionloss needs a Coulomb level (Fc, or Fc_pos and Fc_neg)",
                     {.key = "Fc", .option = "model"});
  MjcfOptions o;
  if (axis) {
    Axis given{};
    try {
      given = parse_axis(*axis);
    } catch (const std::invalid_argument& e) {
      throw InputError(errc::option_invalid, std::string("export_mjcf: argument axis: ") + e.what(), {.option = "axis"});
    }
    if (em.axis && *em.axis != given)
      throw InputError(errc::option_conflict, "export_mjcf: argument axis: '" + *axis +
                                                  "' differs from the model's axis '" +
                                                  (*em.axis == Axis::rotary ? "rotary" : "linear") + "'; drop axis",
                       {.option = "axis"});
    o.axis = given;
  } else {
    o.axis = em.axis.value_or(Axis::linear);
  }
  if (inertia) {
    o.inertia = *inertia;
  } else if (em.inertia) {
    o.inertia = *em.inertia;
  } else {
    throw InputError(errc::scenario_key_missing,
                     "export_mjcf: argument inertia: missing; the model has no M and MuJoCo's body needs the axis' "
                     "inertia (kg or kg m^2): pass inertia=, or an identification Result or MODEL.json with M",
                     {.option = "inertia"});
  }
  o.armature = armature;
  o.timestep = timestep;
  o.offset = em.offset.value_or(0.0);
  if (py::isinstance<py::str>(model) || py::hasattr(model, "__fspath__"))
    o.source = std::filesystem::path(path_arg(model, "export_mjcf", "model")).filename().string();
  MjcfModel x;
  try {
    x = mjcf_model(em.law, o);
  } catch (const std::invalid_argument& e) {
    std::string message = e.what();  // "mjcf: inertia = ..." -> the keyword
    if (message.rfind("mjcf: ", 0) == 0) message = message.substr(6);
    throw std::invalid_argument("export_mjcf: argument " + message);
  }
  if (!p.empty()) write_file_atomic(p, x.xml, {overwrite});
  py::list left;
  for (const auto& l : x.left_out) {
    py::dict d;
    d["name"] = l.name;
    d["value"] = l.value;
    d["unit"] = l.unit;
    d["reason"] = l.reason;
    left.append(d);
  }
  py::dict out;
  out["xml"] = x.xml;
  out["joint"] = x.joint_type;
  out["frictionloss"] = x.frictionloss;
  out["damping"] = x.damping;
  out["body_inertia"] = x.body_inertia;
  out["armature"] = x.armature;
  out["timestep"] = o.timestep;
  out["left_out"] = left;
  return out;
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
          check_path(p, overwrite, "export_c");  // before any work, as the command line does
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
or PREFIX_disturbance_observer_update(&s, v, drive, dt). A law with load, temperature or ripple terms adds
PREFIX_friction_at(v[, q][, load][, T]) and PREFIX_feedforward_at(vr[, q][, load][, T]) /
PREFIX_feedback_at(v[, q][, load][, T]), whose ripple r(q) is taken at the reference (feedforward) or
measured (feedback) position q.
Raises ValueError naming the argument for a compensation that does not fit the law, a bad parameter or prefix.)doc");

  m.def("export_mjcf", &export_mjcf, py::arg("model"), py::arg("path") = py::none(), py::arg("inertia") = py::none(),
        py::arg("armature") = 0.0, py::arg("timestep") = 0.002, py::arg("axis") = py::none(),
        py::arg("overwrite") = false,
        R"doc(The identified axis as a MuJoCo model (MJCF XML), as `frictionlab export MODEL.json --mjcf FILE.xml`
writes it: a slide joint (linear axis; N, m, kg) or a hinge (rotary; N m, rad, kg m^2) with
frictionloss = Fc, damping = Fv (LuGre: sigma2), the body's mass or inertia about the axis = inertia - armature,
and a motor "drive" whose ctrl is the force. Writes it to `path` when given (atomically; an existing file
only with overwrite=True). Returns a dict: xml (the text), joint ("slide" or "hinge"), frictionloss (N or N m),
damping (N s/m or N m s/rad), body_inertia (kg or kg m^2), armature (kg or kg m^2), timestep (s), and
left_out: what MuJoCo cannot express (Fs, vs, delta, presliding states, asymmetry, the offset), each
{"name", "value", "unit", "reason"}, also listed in the file's comment.

model: a FrictionLaw, a law dict, an identification Result, or the path of a MODEL.json / law file.
inertia: the axis' inertia M (kg or kg m^2, > 0); default the model's M (required when it has none).
armature: the part of M the joint carries as MuJoCo's armature (kg or kg m^2, 0 <= armature < M).
timestep: MuJoCo's time step (s, > 0; MuJoCo's default 0.002).
axis: "linear" or "rotary" for a model that names none (a law); default the model's, else linear.
Raises ValueError naming the argument: a law without a Coulomb level, a missing or bad inertia,
armature or timestep, an existing path without overwrite=True.)doc");
}

}  // namespace frictionlab::python
