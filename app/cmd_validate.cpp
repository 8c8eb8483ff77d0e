// frictionlab validate MODEL.json DATA --scenario SCENARIO.yaml: simulate an identified model in
// the scenario's plant and controller and compare it with a measured run.
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "commands.hpp"
#include "frictionlab/format.hpp"
#include "data_options.hpp"
#include "frictionlab/identify/validate.hpp"
#include "frictionlab/io/atomic_write.hpp"
#include "frictionlab/io/law_file.hpp"
#include "frictionlab/io/scenario.hpp"
#include "output.hpp"

namespace frictionlab::cli {
namespace {

struct ValidateArgs {
  std::string model, data, scenario;
  DataOptions columns;
  OutputOptions output;
};

// The model a `frictionlab identify ... --json` run wrote: its "law", parameters M and offset.
struct ModelFile {
  IdentifiedModel model;
  std::string data_file, data_sha256;
};

// The one model reader (io/law_file.hpp: whole file, status ok) and the plant values, each
// checked here so that a bad value is blamed on MODEL.json, not on the scenario.
ModelFile read_model(const std::string& path) {
  const nlohmann::json j = read_model_json(path);
  if (!j.contains("law") || !j["law"].is_object())
    throw std::invalid_argument(path + ": no 'law' object; expected the friction law of an identification "
                                "(frictionlab identify ... --json writes it when the estimates make a valid law)");
  ModelFile m;
  m.model.law = law_from_json(j["law"], path + ": law");
  const nlohmann::json none = nlohmann::json::object();
  const nlohmann::json& p = j.contains("parameters") ? j["parameters"] : none;
  if (!p.is_object()) throw std::invalid_argument(path + ": parameters: expected an object, got " + p.dump());
  auto param = [&](const char* name, bool required, double fallback, const char* what) {
    if (!p.contains(name)) {
      if (required) throw std::invalid_argument(path + ": parameters." + name + ": missing; expected " + what);
      return fallback;
    }
    const bool wrapped = p[name].is_object();
    const auto& v = wrapped ? p[name].value("value", nlohmann::json()) : p[name];
    const std::string key = path + ": parameters." + name + (wrapped ? ".value" : "");
    if (!v.is_number()) throw std::invalid_argument(key + ": expected " + what + ", got " + v.dump());
    const double x = v.get<double>();
    if (!std::isfinite(x)) throw std::invalid_argument(key + ": expected a finite number (" + what + ")");
    return x;
  };
  m.model.axis.M = param("M", true, 0.0, "the identified inertia, a number > 0 (kg or kg m^2)");
  if (!(m.model.axis.M > 0))
    throw std::invalid_argument(path + ": parameters.M: " + nlohmann::json(m.model.axis.M).dump() +
                                " must be > 0 (the identified inertia, kg or kg m^2)");
  // The plant adds its offset to the drive; the identification's offset is spent by it (u = M a + F +
  // offset): the negative (see model_from_result).
  m.model.axis.offset = -param("offset", false, 0.0, "a force offset in N or N m");
  if (j.contains("method") && j["method"].is_string()) m.model.method = j["method"].get<std::string>();
  m.model.source = path;
  if (j.contains("data") && j["data"].is_object()) {
    const auto& d = j["data"];
    if (d.contains("file") && d["file"].is_string()) m.data_file = d["file"].get<std::string>();
    if (d.contains("sha256") && d["sha256"].is_string()) m.data_sha256 = d["sha256"].get<std::string>();
  }
  return m;
}

std::string text_of(const Result& r, const std::string& scenario) {
  std::ostringstream s;
  s << "frictionlab validate: " << r.model << " model in " << scenario << "\n";
  if (!r.ok()) {
    s << "error: " << r.message << "\n";
    return s.str();
  }
  for (const auto& p : r.parameters)
    s << "  " << std::left << std::setw(7) << p.name << " = " << std::right << std::setw(12) << format_number(p.value)
      << " " << p.unit << "\n";
  const auto& v = *r.validation;
  const auto& full = r.diagnostics.groups.at("relative_error_percent_full_rate");
  s << "data " << v.file << ": relative error % (IDIM grid, " << v.samples << " samples; every sample)\n";
  for (const char* name : {"position", "velocity", "acceleration", "force"})
    s << "  " << std::left << std::setw(13) << name << std::right << std::setw(10)
      << format_number(v.signal_errors_percent.at(name), 4) << std::setw(10) << format_number(full.at(name), 4) << "\n";
  for (const auto& w : r.diagnostics.warnings) s << "warning: " << w << "\n";
  return s.str();
}

int run(const ValidateArgs& a) {
  check_outputs(a.output);
  const ModelFile mf = read_model(a.model);
  auto data = std::make_shared<const Dataset>(load_data(a.data, a.columns));
  ScenarioOptions so;
  so.data = data;
  so.law = mf.model.law;
  so.axis = mf.model.axis;
  so.model_source = a.model;
  const Scenario sc = load_scenario(a.scenario, so);
  ValidationData v;
  v.time = time_column(*data, a.columns);
  v.position = position_column(*data, a.columns);
  v.force = force_column(*data, a.columns);
  v.file = data->file;
  v.sha256 = data->sha256;
  ValidateOptions vo;
  vo.processing.axis = a.columns.parsed_axis();
  Result r = validate_model(mf.model, sc, v, vo);
  r.data_file = mf.data_file;
  r.data_sha256 = mf.data_sha256;
  note_data(r, *data);
  return emit(r, a.output, text_of(r, a.scenario));
}

}  // namespace

Handler register_validate(CLI::App& app) {
  auto a = std::make_shared<ValidateArgs>();
  auto* cmd = app.add_subcommand("validate",
                                 "Simulate an identified model (MODEL.json of identify --json) in a scenario's plant and "
                                 "controller, driven by a measured run, and report the relative errors of position, "
                                 "velocity, acceleration and force");
  cmd->add_option("MODEL", a->model, "MODEL.json written by frictionlab identify ... --json")->required();
  cmd->add_option("DATA", a->data, "Measured run: a CSV file (with a header row, or without one: see --names), or a MATLAB .mat file")->required();
  cmd->add_option("--scenario", a->scenario,
                  "Scenario YAML: plant (axis), controller and input (e.g. examples/emps_closed_loop.yaml); its data "
                  "inputs read DATA, its M, offset and friction come from MODEL")
      ->required();
  add_data_options(cmd, a->columns, "linear");
  add_output_options(cmd, a->output);
  return [a]() -> int { return run(*a); };
}

}  // namespace frictionlab::cli
