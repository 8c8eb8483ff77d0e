// frictionlab export MODEL.json --c FILE.h [--compensation TYPE] [--float] [--prefix NAME]: the
// identified friction law (and a compensation) as one C99 header for a drive's firmware.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

#include "commands.hpp"
#include "io/atomic_write.hpp"
#include "frictionlab/export/c_export.hpp"
#include "frictionlab/scenario/model_file.hpp"
#include "output.hpp"

namespace frictionlab::cli {
namespace {

struct ExportArgs {
  std::string model, output, compensation, prefix = "friction";
  bool single = false, overwrite = false;
  std::optional<double> band, dead_band, gain, bandwidth, inertia;
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

}  // namespace

Handler register_export(CLI::App& app) {
  auto a = std::make_shared<ExportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "export", "Write the friction law of MODEL.json (and a compensation) as one C99 header for a drive's firmware.");
  cmd->footer(
      "The header has static inline functions and static const parameters (SI units: N, m/s, N s/m, N/m; N m,\n"
      "rad/s, N m s/rad, N m/rad on a rotary axis; dt in s), no allocation, nothing beyond math.h:\n"
      "PREFIX_friction(v) for every law; PREFIX_friction_stuck(v, applied) for static laws;\n"
      "PREFIX_state, PREFIX_init(&s), PREFIX_update(&s, v, dt) for dynamic laws (stable for any dt);\n"
      "PREFIX_feedforward(vr), PREFIX_feedback(v), PREFIX_lugre_observer_update(&s, x, v, r, dt),\n"
      "PREFIX_disturbance_observer_update(&s, v, drive, dt) for the chosen compensation.\n"
      "Example: frictionlab export model.json --c friction.h --compensation feedforward --band 0.002\n");
  cmd->add_option("model", a->model, "MODEL.json of `frictionlab identify ... --json`, or a law file (.json, .yaml)")
      ->required();
  cmd->add_option("--c", a->output, "write the C header to this file (- for stdout)")->required();
  cmd->add_option("--compensation", a->compensation,
                  "also export a compensation: feedforward, feedback, lugre-observer (needs a lugre law), "
                  "disturbance-observer");
  cmd->add_flag("--float", a->single, "single precision (float) instead of double");
  cmd->add_option("--prefix", a->prefix, "prefix of every C name (a C identifier; default friction)");
  cmd->add_option("--band", a->band, "feedforward: half-width of the smoothing band around rest (m/s or rad/s; default 1e-3)");
  cmd->add_option("--dead-band", a->dead_band, "feedback: half-width of the dead band (m/s or rad/s; default 1e-3)");
  cmd->add_option("--gain", a->gain, "lugre-observer: observer gain k (1/s; default 0.01)");
  cmd->add_option("--bandwidth", a->bandwidth, "disturbance-observer: low-pass bandwidth (rad/s; default 100)");
  cmd->add_option("--inertia", a->inertia,
                  "disturbance-observer: nominal inertia (kg or kg m^2; default parameters.M of MODEL.json)");
  cmd->add_flag("--overwrite", a->overwrite, "replace an existing header file");
  return [a]() -> int {
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
      const std::string what = e.what();
      const bool prefix = what.rfind("prefix", 0) == 0;
      throw std::invalid_argument(prefix ? "--" + what : a->model + ": --compensation " + what);
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
    return 0;
  };
}

}  // namespace frictionlab::cli
