// frictionlab export MODEL.json --c FILE.h [--compensation TYPE] [--float] [--prefix NAME]: the
// identified friction law (and a compensation) as one C99 header for a drive's firmware.
// frictionlab export MODEL.json --mjcf FILE.xml [--inertia M] [--armature A] [--timestep DT]
// [--json FILE]: the identified axis as a MuJoCo model, with the terms MuJoCo cannot express listed.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "io/atomic_write.hpp"
#include "frictionlab/error.hpp"
#include "frictionlab/export/c_export.hpp"
#include "frictionlab/export/mjcf_export.hpp"
#include "frictionlab/format.hpp"
#include "frictionlab/io/json_text.hpp"
#include "frictionlab/scenario/model_file.hpp"
#include "output.hpp"

namespace frictionlab::cli {
namespace {

struct ExportArgs {
  std::string model, output, mjcf, json, compensation, prefix = "friction";
  bool single = false, overwrite = false;
  std::optional<double> band, dead_band, gain, bandwidth, inertia, armature, timestep;
  CLI::Option* prefix_option = nullptr;
};

bool same_file(const std::string& a, const std::string& b) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(b, ec) && fs::equivalent(a, b, ec)) return true;  // links and other spellings
  return fs::weakly_canonical(a, ec) == fs::weakly_canonical(b, ec);
}

// A compensation flag given without its compensation is a mistake the user should hear about.
void flag_belongs(const std::optional<double>& flag, const char* name, const std::string& type, const char* owner) {
  if (flag && type != owner)
    throw std::invalid_argument(std::string(name) + " is a parameter of --compensation " + owner + (type.empty() ? "" : ", not of " + type) +
                                "; pass --compensation " + owner + " or drop " + name);
}

CompensationParams compensation(const ExportArgs& a, const ModelFile& m) {
  const std::string& type = a.compensation;
  flag_belongs(a.band, "--band", type, "feedforward");
  flag_belongs(a.dead_band, "--dead-band", type, "feedback");
  flag_belongs(a.gain, "--gain", type, "lugre-observer");
  flag_belongs(a.bandwidth, "--bandwidth", type, "disturbance-observer");
  flag_belongs(a.inertia, "--inertia", type, "disturbance-observer");
  if (type.empty()) return {};
  std::map<std::string, double> values;
  for (const auto& [name, flag] : {std::pair{"band", a.band}, {"dead_band", a.dead_band}, {"gain", a.gain},
                                   {"bandwidth", a.bandwidth}, {"inertia", a.inertia}})
    if (flag) values[name] = *flag;
  if (type == "disturbance-observer" && !a.inertia && !m.inertia)
    throw std::invalid_argument("--inertia: missing; --compensation disturbance-observer needs the nominal inertia "
                                "(kg or kg m^2): pass --inertia, or a MODEL.json with parameters.M (identify idim)");
  try {
    return make_compensation(type, values, m.inertia);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--compensation: ") + e.what());
  }
}

// The flags of one output refused with the other: "--float is an option of --c, not of --mjcf".
void only_with(bool given, const char* name, const char* owner, const char* other) {
  if (given)
    throw InputError(errc::option_conflict,
                     std::string(name) + " is an option of " + owner + ", not of " + other + "; drop " + name,
                     {.option = name});
}

double checked_flag(const std::optional<double>& flag, const char* name, bool ok, const std::string& rule) {
  if (!ok)
    throw InputError(errc::option_out_of_range, std::string(name) + " = " + format_number(*flag, 10) + " must be " + rule,
                     {.option = name, .value = format_number(*flag, 17)});
  return *flag;
}

nlohmann::ordered_json quantity(double value, const std::string& unit) {
  return {{"value", value}, {"unit", unit}};
}

int run_mjcf(const ExportArgs& a) {
  const char* c_flags[] = {"--compensation", "--float", "--prefix", "--band", "--dead-band", "--gain", "--bandwidth"};
  const bool c_given[] = {!a.compensation.empty(), a.single, a.prefix_option && a.prefix_option->count() > 0,
                          a.band.has_value(), a.dead_band.has_value(), a.gain.has_value(), a.bandwidth.has_value()};
  for (std::size_t i = 0; i < std::size(c_flags); ++i) only_with(c_given[i], c_flags[i], "--c", "--mjcf");
  for (const auto& [flag, path] : {std::pair{"--mjcf", a.mjcf}, {"--json", a.json}})
    if (path != "-" && !path.empty() && same_file(a.model, path))
      throw InputError(errc::output_is_input,
                       std::string(flag) + " " + path + " is the model file " + a.model +
                           "; an export never replaces its input: give it its own file",
                       {.file = path, .option = flag, .other_file = a.model, .other_option = "MODEL"});
  if (a.mjcf == "-" && a.json == "-")
    throw InputError(errc::output_duplicate, "--mjcf - and --json -: both on stdout; give one of them a file",
                     {.file = "-", .option = "--json", .other_file = "-", .other_option = "--mjcf"});
  check_run_files({{"MODEL", a.model, RunFile::Kind::file}},
                  {{"--mjcf", a.mjcf, RunFile::Kind::file}, {"--json", a.json, RunFile::Kind::file}}, a.overwrite);
  const ModelFile m = read_model_file(a.model);
  const std::optional<double> fc = mjcf_coulomb_level(m.law);
  if (!fc)
    throw InputError(errc::scenario_key_missing,
                     a.model + " has no Fc (law " + m.law.name() +
                         "): --mjcf needs a Coulomb level (Fc, or Fc_pos and Fc_neg) for MuJoCo's frictionloss",
                     {.file = a.model, .key = "Fc", .option = "--mjcf"});
  MjcfOptions o;
  o.axis = m.axis.value_or(Axis::linear);
  const std::string inertia_unit = o.axis == Axis::rotary ? "kg m^2" : "kg";
  if (a.inertia) {
    o.inertia = checked_flag(a.inertia, "--inertia", std::isfinite(*a.inertia) && *a.inertia > 0, "> 0 (" + inertia_unit + ")");
  } else if (m.inertia) {
    if (!(std::isfinite(*m.inertia) && *m.inertia > 0))
      throw InputError(errc::scenario_value,
                       a.model + ": parameters.M = " + format_number(*m.inertia, 10) + " must be > 0 (" + inertia_unit +
                           "); pass --inertia to give the axis' inertia",
                       {.file = a.model, .key = "parameters.M", .value = format_number(*m.inertia, 17)});
    o.inertia = *m.inertia;
  } else {
    throw InputError(errc::scenario_key_missing,
                     a.model + " has no parameters.M: --mjcf needs the axis' inertia (" + inertia_unit +
                         ") for the body; pass --inertia, or a MODEL.json of identify idim or decay",
                     {.file = a.model, .key = "parameters.M", .option = "--inertia"});
  }
  if (a.armature)
    o.armature = checked_flag(a.armature, "--armature", std::isfinite(*a.armature) && *a.armature >= 0 && *a.armature < o.inertia,
                              ">= 0 and < the inertia M = " + format_number(o.inertia, 10) + " (" + inertia_unit + ")");
  if (a.timestep)
    o.timestep = checked_flag(a.timestep, "--timestep", std::isfinite(*a.timestep) && *a.timestep > 0, "> 0 (s)");
  o.offset = m.offset.value_or(0.0);
  o.source = std::filesystem::path(a.model).filename().string();
  const MjcfModel x = mjcf_model(m.law, o);

  const bool rotary = o.axis == Axis::rotary;
  const std::string force_unit(unit(Quantity::force, o.axis)), viscous_unit(unit(Quantity::viscous, o.axis));
  std::string text = (a.mjcf == "-" ? std::string("MuJoCo model") : "wrote " + a.mjcf) + " (MJCF, " + x.joint_type +
                     " joint" + (m.axis ? "" : ", linear: the model names no axis") + "): frictionloss = Fc = " +
                     format_number(x.frictionloss, 10) + " " + force_unit + ", damping = " +
                     format_number(x.damping, 10) + " " + viscous_unit + ", " +
                     (rotary ? "inertia about the axis = " : "mass = ") + format_number(x.body_inertia, 10) + " " +
                     inertia_unit + ", armature = " + format_number(x.armature, 10) + " " + inertia_unit +
                     ", timestep = " + format_number(o.timestep, 10) + " s; actuator \"drive\" (ctrl in " + force_unit +
                     ")\n";
  if (x.left_out.empty()) {
    text += "left out: nothing (the law is Coulomb and viscous friction, which MuJoCo expresses)\n";
  } else {
    text += "left out (MuJoCo cannot express them; listed in the file's comment too):\n";
    const std::string lines = mjcf_left_out_text(x.left_out);
    for (std::size_t at = 0; at < lines.size();) {
      const std::size_t end = lines.find('\n', at);
      text += "  " + lines.substr(at, end - at) + "\n";
      at = end == std::string::npos ? lines.size() : end + 1;
    }
  }
  nlohmann::ordered_json left = nlohmann::ordered_json::array();
  for (const auto& l : x.left_out)
    left.push_back({{"name", l.name}, {"value", l.value}, {"unit", l.unit}, {"reason", l.reason}});
  const nlohmann::ordered_json j = {
      {"schema", 1},
      {"status", "ok"},
      {"message", ""},
      {"method", "export"},
      {"model_file", a.model},
      {"axis", rotary ? "rotary" : "linear"},
      {"mjcf",
       {{"file", a.mjcf},
        {"joint", x.joint_type},
        {"frictionloss", quantity(x.frictionloss, force_unit)},
        {"damping", quantity(x.damping, viscous_unit)},
        {rotary ? "body_inertia" : "body_mass", quantity(x.body_inertia, inertia_unit)},
        {"armature", quantity(x.armature, inertia_unit)},
        {"timestep", quantity(o.timestep, "s")},
        {"integrator", "Euler"}}},
      {"left_out", left}};

  if (a.mjcf == "-") std::cout << x.xml;
  else write_file_atomic(a.mjcf, x.xml, {a.overwrite});
  if (a.json == "-") std::cout << json_text(j) << "\n";
  else if (!a.json.empty()) write_file_atomic(a.json, json_text(j, 2) + "\n", {a.overwrite});
  (a.mjcf == "-" || a.json == "-" ? std::cerr : std::cout) << text;
  return 0;
}

}  // namespace

Handler register_export(CLI::App& app) {
  auto a = std::make_shared<ExportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "export",
      "Write the friction law of MODEL.json (and a compensation) as one C99 header for a drive's firmware (--c), "
      "or the identified axis as a MuJoCo model (--mjcf).");
  cmd->footer(
      "The header has static inline functions and static const parameters (SI units: N, m/s, N s/m, N/m; N m,\n"
      "rad/s, N m s/rad, N m/rad on a rotary axis; dt in s), no allocation, nothing beyond math.h:\n"
      "PREFIX_friction(v) for every law; PREFIX_friction_stuck(v, applied) for static laws;\n"
      "PREFIX_state, PREFIX_init(&s), PREFIX_update(&s, v, dt) for dynamic laws (stable for any dt);\n"
      "PREFIX_feedforward(vr), PREFIX_feedback(v), PREFIX_lugre_observer_update(&s, x, v, r, dt),\n"
      "PREFIX_disturbance_observer_update(&s, v, drive, dt) for the chosen compensation.\n"
      "Example: frictionlab export model.json --c friction.h --compensation feedforward --band 0.002\n"
      "\n"
      "--mjcf FILE.xml: a MuJoCo model (MJCF) of the axis: a slide joint (linear axis; N, m, kg) or a hinge\n"
      "(rotary axis of MODEL.json; N m, rad, kg m^2) with frictionloss = Fc, damping = Fv (LuGre: sigma2),\n"
      "the body's mass or inertia about the axis = M (parameters.M, or --inertia; required) minus --armature,\n"
      "and a motor \"drive\" whose ctrl is the force. What MuJoCo cannot express (Fs, vs, delta, presliding\n"
      "states, asymmetry, the offset) is listed in the file's comment, on stdout, and with --json in \"left_out\".\n"
      "MuJoCo's friction is a soft constraint: below Fc the joint creeps (docs/export.md has the measurement).\n"
      "Example: frictionlab export model.json --mjcf axis.xml --json axis.json\n");
  cmd->add_option("model", a->model, "MODEL.json of `frictionlab identify ... --json`, or a law file (.json, .yaml)")
      ->required();
  CLI::Option* c_option =
      output_option(cmd->add_option("--c", a->output, "write the C header to this file (- for stdout)"));
  CLI::Option* mjcf_option = output_option(
      cmd->add_option("--mjcf", a->mjcf, "write the axis as a MuJoCo model (MJCF XML) to this file (- for stdout)"));
  c_option->excludes(mjcf_option);
  mjcf_option->excludes(c_option);
  cmd->add_option("--compensation", a->compensation,
                  "also export a compensation: feedforward, feedback, lugre-observer (needs a lugre law), "
                  "disturbance-observer");
  cmd->add_flag("--float", a->single, "single precision (float) instead of double");
  a->prefix_option = cmd->add_option("--prefix", a->prefix, "prefix of every C name (a C identifier; default friction)");
  cmd->add_option("--band", a->band, "feedforward: half-width of the smoothing band around rest (m/s or rad/s; default 1e-3)");
  cmd->add_option("--dead-band", a->dead_band, "feedback: half-width of the dead band (m/s or rad/s; default 1e-3)");
  cmd->add_option("--gain", a->gain, "lugre-observer: observer gain k (1/s; default 0.01)");
  cmd->add_option("--bandwidth", a->bandwidth, "disturbance-observer: low-pass bandwidth (rad/s; default 100)");
  cmd->add_option("--inertia", a->inertia,
                  "disturbance-observer, and --mjcf: the axis' inertia (kg or kg m^2; default parameters.M of MODEL.json)");
  cmd->add_option("--armature", a->armature,
                  "--mjcf: the part of the inertia the joint carries as MuJoCo's armature, e.g. a rotor's "
                  "(kg or kg m^2, >= 0 and < M; default 0)");
  cmd->add_option("--timestep", a->timestep, "--mjcf: MuJoCo's time step (s; default 0.002, MuJoCo's own)");
  CLI::Option* json = output_option(
      cmd->add_option("--json", a->json, "--mjcf: write what was mapped and left out as JSON to FILE, or '-' for stdout"));
  cmd->add_flag("--overwrite", a->overwrite, "replace an existing output file");
  register_json_output(cmd, json, [] { return std::string("export"); });
  return [a]() -> int {
    if (a->output.empty() && a->mjcf.empty())
      throw InputError(errc::option_invalid, "--c FILE.h or --mjcf FILE.xml: missing; give the output to write",
                       {.option = "--c"});
    if (!a->mjcf.empty()) return run_mjcf(*a);
    only_with(a->armature.has_value(), "--armature", "--mjcf", "--c");
    only_with(a->timestep.has_value(), "--timestep", "--mjcf", "--c");
    only_with(!a->json.empty(), "--json", "--mjcf", "--c");
    if (a->output != "-" && same_file(a->model, a->output))
      throw InputError(errc::output_is_input,
                       "--c " + a->output + " is the model file " + a->model +
                           "; the header never replaces its input: give it its own file",
                       {.file = a->output, .option = "--c", .other_file = a->model, .other_option = "MODEL"});
    check_run_files({{"MODEL", a->model, RunFile::Kind::file}}, {{"--c", a->output, RunFile::Kind::file}}, a->overwrite);
    const ModelFile m = read_model_file(a->model);
    CExportOptions o;
    o.prefix = a->prefix;
    o.single_precision = a->single;
    o.compensation = compensation(*a, m);
    o.source = std::filesystem::path(a->model).filename().string();
    std::string text;
    try {
      text = c_header(m.law, o);
    } catch (const std::invalid_argument& e) {
      // The compensation's own refusals are named as its; a constant out of the header type's
      // range (--float, export:) may come from the law as well.
      const std::string what = e.what();
      const bool prefix = what.rfind("prefix", 0) == 0;
      const bool constant = what.rfind("--float", 0) == 0 || what.rfind("export:", 0) == 0;
      // The code and fields stay (output.not_finite for a constant beyond the type's range).
      throw InputError(error_code(e), prefix ? "--" + what : a->model + (constant ? ": " : ": --compensation ") + what,
                       error_fields(e));
    }
    if (a->output == "-") {
      std::cout << text;
    } else {
      AtomicWriteOptions w;
      w.overwrite = a->overwrite;
      write_file_atomic(a->output, text, w);
      std::cerr << "wrote " << a->output << " (" << m.law.name()
                << (a->compensation.empty() ? "" : " with " + a->compensation) << ", "
                << (a->single ? "float" : "double") << ")\n";
    }
    // The identified offset is a constant force of the rig (gravity on an inclined axis, a
    // cable, a current sensor's bias), not friction: the header's friction and its compensation
    // leave it out. Said, not dropped in silence.
    if (m.offset && *m.offset != 0.0)
      std::cerr << "not in the header: parameters.offset = " << format_number(*m.offset, 6) << " "
                << unit(Quantity::force, m.axis.value_or(Axis::linear))
                << " (a constant force of the rig, not friction: a friction compensation leaves it out; add it "
                   "to the drive's command yourself if it is a bias to cancel)\n";
    return 0;
  };
}

}  // namespace frictionlab::cli
