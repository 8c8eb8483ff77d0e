// frictionlab validate MODEL.json DATA --scenario SCENARIO.yaml: simulate an identified model in
// the scenario's plant and controller and compare it with a measured run. On a two-axis plant
// (xy-table), MODEL is x=MODEL_X.json[,y=MODEL_Y.json] and the circular test of measured and
// simulated is compared too (analysis/contour_validation.hpp).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "commands.hpp"
#include "frictionlab/error.hpp"
#include "frictionlab/format.hpp"
#include "data_options.hpp"
#include "contour_figure.hpp"
#include "figure_kit.hpp"
#include "frictionlab/analysis/contour_validation.hpp"
#include "frictionlab/identify/validate.hpp"
#include "io/atomic_write.hpp"
#include "frictionlab/io/column_expression.hpp"
#include "frictionlab/io/columns.hpp"
#include "frictionlab/scenario/law_file.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/simulate/environment.hpp"
#include "frictionlab/simulate/scenario.hpp"
#include "methods/method.hpp"
#include "output.hpp"

namespace frictionlab::cli {
namespace {

struct ValidateArgs {
  std::string model, data, scenario;
  DataOptions columns;
  // A two-axis plant (xy-table): the measured positions and, optionally, drive forces per axis.
  std::string x, y, x_force, y_force;
  bool x_force_given = false, y_force_given = false;
  OutputOptions output;
  GivenOptions given;  // --scenario and the two-axis columns, from validate's option table
};

// The model a `frictionlab identify ... --json` run wrote: its "law", parameters M and offset.
struct ModelFile {
  IdentifiedModel model;
  std::string data_file, data_sha256;
  std::optional<Axis> axis;  // the axis it was identified on, when the file says
};

// The one model reader (scenario/law_file.hpp: whole file, status ok) and the plant values, each
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
  if (j.contains("axis")) m.axis = parse_axis(j["axis"].get<std::string>());  // linear or rotary: read_model_json checked it
  if (j.contains("data") && j["data"].is_object()) {
    const auto& d = j["data"];
    if (d.contains("file") && d["file"].is_string()) m.data_file = d["file"].get<std::string>();
    if (d.contains("sha256") && d["sha256"].is_string()) m.data_sha256 = d["sha256"].get<std::string>();
  }
  return m;
}

// A law whose levels move with the load or the temperature is validated at the conditions the
// measured run worked at, which the scenario's environment block gives (the log's load as a data
// input); without them the simulation would run at zero load or at T_ref and blame the law for
// the difference. Throws naming MODEL, the effect and what to add.
void check_conditions(const FrictionLaw& law, const Scenario& sc, const std::string& model, const std::string& scenario) {
  const LawEffects& e = law.effects();
  const ContactEnvironment none;
  const ContactEnvironment& env = sc.options.environments.empty() ? none : sc.options.environments.front();
  if (e.load && !env.load.given())
    throw std::invalid_argument(model + ": the law's load effect (mu_load) needs the load the measured run worked at; "
                                "scenario " + scenario + " gives none: add 'environment: {load: {type: data, column: "
                                "LOAD}}' naming the log's load column (N or N m)");
  if (e.temperature && !env.temperature && !env.temperature_log && !env.thermal)
    throw std::invalid_argument(model + ": the law's temperature effect (T_ref, Fv_per_K) needs the temperature the "
                                "measured run worked at; scenario " + scenario + " gives none: add 'environment: "
                                "{temperature: {type: data, column: TEMPERATURE}}' naming the log's temperature column, "
                                "'{temperature: T}' (degC or K, the log's mean) or a thermal model");
}

// MODEL as "AXIS=FILE[,AXIS=FILE]" (a model per axis of a two-axis plant): the pairs, in order;
// empty for a plain file name (one model, a one-axis plant). A name that is an existing file
// is a file, whatever it contains.
std::vector<std::pair<std::string, std::string>> axis_models(const std::string& arg) {
  std::vector<std::pair<std::string, std::string>> out;
  std::error_code ec;
  if (arg.find('=') == std::string::npos || std::filesystem::exists(arg, ec)) return out;
  std::size_t start = 0;
  while (start <= arg.size()) {
    const std::size_t end = std::min(arg.find(',', start), arg.size());
    const std::string piece = arg.substr(start, end - start);
    const std::size_t eq = piece.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == piece.size())
      throw std::invalid_argument("MODEL '" + arg + "': '" + piece + "' is not AXIS=FILE; expected a MODEL.json, or one "
                                  "per axis of a two-axis plant as x=MODEL_X.json,y=MODEL_Y.json");
    const std::string name = piece.substr(0, eq);
    for (const auto& [seen, file] : out)
      if (seen == name) throw std::invalid_argument("MODEL '" + arg + "': axis '" + name + "' is given twice");
    out.emplace_back(name, piece.substr(eq + 1));
    start = end + 1;
  }
  return out;
}

// A drive-force column of a two-axis record: the option's column when given (it must exist),
// else the default name when the file has it, else none (forces are then not compared).
Eigen::VectorXd optional_force(const Dataset& d, const std::string& name, bool given, const std::string& option) {
  if (!given && !d.has_column(name)) return {};
  return finite_signal(d, name, option);
}

// "12.3 um" (3 significant digits: a circular test holds no more).
std::string um(double m) { return format_number(m * 1e6, 3) + " um"; }

std::string contour_text(const ContourValidation& cv) {
  std::ostringstream s;
  const ContourResult &m = *cv.measured, &sim = *cv.simulated;
  s << "contour: circle R " << format_number(m.radius * 1e3, 4) << " mm, " << format_number(m.turns, 3)
    << " turns (radial error r - R about the reference's centre)\n"
    << "  " << std::left << std::setw(26) << "" << std::right << std::setw(12) << "measured" << std::setw(12) << "simulated\n";
  auto row = [&](const std::string& name, double a, double b) {
    s << "  " << std::left << std::setw(26) << name << std::right << std::setw(12) << um(a) << std::setw(12) << um(b) << "\n";
  };
  row("largest quadrant glitch", max_quadrant_glitch(m), max_quadrant_glitch(sim));
  for (std::size_t i = 0; i < 4; ++i)
    row("  glitch at " + format_number(m.glitches[i].reversal_deg) + " deg", m.glitches[i].peak_m, sim.glitches[i].peak_m);
  row("roundness (max - min)", m.roundness_m, sim.roundness_m);
  row("largest |r - R|", m.max_radial_error_m, sim.max_radial_error_m);
  s << "  radial error trace: relative error "
    << format_number(cv.result.diagnostics.numbers.at("radial_error_relative_error_percent"), 4) << " %\n";
  return s.str();
}

std::string text_of(const Result& r, const std::string& scenario) {
  std::ostringstream s;
  s << "frictionlab validate: " << r.model << " model in " << scenario << "\n";
  if (!r.ok()) {
    s << "error: " << r.message << "\n";
    return s.str();
  }
  // The names' column as wide as the longest ("x.offset" on a two-axis table), so the '=' align.
  std::size_t w = 7;
  for (const auto& p : r.parameters) w = std::max(w, p.name.size());
  for (const auto& p : r.parameters)
    s << "  " << std::left << std::setw(static_cast<int>(w)) << p.name << " = " << std::right << std::setw(12)
      << format_number(p.value) << (p.unit.empty() ? "" : " " + p.unit) << "\n";
  const auto& v = *r.validation;
  const auto& full = r.diagnostics.groups.at("relative_error_percent_full_rate");
  s << "data " << v.file << ": relative error % (IDIM grid, " << v.samples << " samples; every sample)\n";
  // One axis: position, velocity, acceleration, force; several: AXIS.SIGNAL, axis by axis.
  const bool one_axis = v.signal_errors_percent.count("position") > 0;
  std::vector<std::string> names;
  if (one_axis) names = {"position", "velocity", "acceleration", "force"};
  if (!one_axis)
    for (const std::string axis : {"x", "y"})
      for (const char* sig : {"position", "velocity", "acceleration", "force"})
        if (v.signal_errors_percent.count(axis + "." + sig)) names.push_back(axis + "." + sig);
  for (const std::string& name : names)
    s << "  " << std::left << std::setw(15) << name << std::right << std::setw(10)
      << format_number(v.signal_errors_percent.at(name), 4) << std::setw(10) << format_number(full.at(name), 4) << "\n";
  for (const auto& w : r.diagnostics.warnings) s << "warning: " << w << "\n";
  return s.str();
}

// A two-axis plant (xy-table): the models by axis, the x and y records, and the circular test's
// figures (the measured and simulated contour, the polar error plots, the axes' signals).
int run_two_axis(const ValidateArgs& a, const OptionValues& options, const std::map<std::string, IdentifiedModel>& models, const Scenario& sc,
                 const std::shared_ptr<const Dataset>& data, const std::string& data_file, const std::string& data_sha256) {
  MultiAxisValidationData v;
  v.time = time_column(*data, a.columns);
  // The report lists the columns taken by default.
  a.columns.columns_read["--x"] = a.x;
  a.columns.columns_read["--y"] = a.y;
  if (a.x_force_given || data->has_column(a.x_force)) a.columns.columns_read["--x-force"] = a.x_force;
  if (a.y_force_given || data->has_column(a.y_force)) a.columns.columns_read["--y-force"] = a.y_force;
  v.axes.push_back({"x", finite_signal(*data, a.x, "--x"), optional_force(*data, a.x_force, a.x_force_given, "--x-force")});
  v.axes.push_back({"y", finite_signal(*data, a.y, "--y"), optional_force(*data, a.y_force, a.y_force_given, "--y-force")});
  v.file = data->file;
  v.sha256 = data->sha256;
  ValidateOptions vo;
  vo.processing.axis = a.columns.parsed_axis();
  ContourValidation cv = validate_contour(sc, v, models, vo);
  Result& r = cv.result;
  record_options(r, options);
  r.data_file = data_file;
  r.data_sha256 = data_sha256;
  note_data(r, *data);
  std::string text = text_of(r, a.scenario);
  if (cv.measured) text += contour_text(cv);
  std::vector<ReportFigure> figures;
  if (!a.output.plot.empty() || !a.output.report.empty()) figures = xy_validation_figures(r, cv.measured, cv.simulated, file_name(v.file));
  return emit(r, a.output, text, &figures);
}

int run(ValidateArgs& a) {
  const OptionValues options = a.given();
  a.output.values = &options;  // the report lists the options that applied, with units
  a.output.data = &a.columns;  // and the columns the run took by default
  a.scenario = options.text("scenario");
  a.x = options.text("x");
  a.y = options.text("y");
  a.x_force = options.text("x-force");
  a.y_force = options.text("y-force");
  a.x_force_given = options.given("x-force");
  a.y_force_given = options.given("y-force");
  const auto named = axis_models(a.model);
  std::vector<RunFile> inputs = command_inputs(a.output.command);
  for (const auto& [axis, file] : named) inputs.push_back({"MODEL " + axis, file, RunFile::Kind::file});
  try {
    check_outputs(a.output, inputs);
  } catch (const std::invalid_argument&) {
    // An output at a file the scenario names is said to be that, whatever else is wrong with it
    // (a --plot at the scenario's data file): the same check with those files throws it first.
    std::vector<RunFile> all = inputs;
    for (auto& f : scenario_inputs(a.scenario)) all.push_back(std::move(f));
    check_outputs(a.output, all);
    throw;
  }
  ScenarioOptions so;
  std::map<std::string, IdentifiedModel> models;
  ModelFile mf;
  if (named.empty()) {
    mf = read_model(a.model);
    so.law = mf.model.law;
    so.axis = mf.model.axis;
  } else {
    for (const auto& [axis, file] : named) {
      ModelFile m = read_model(file);
      so.axis_models[axis] = AxisModel{m.model.law, m.model.axis};
      models.emplace(axis, m.model);
      if (mf.data_file.empty()) mf = m;  // the first model's identification data, for the result
    }
  }
  auto data = std::make_shared<const Dataset>(load_data(a.data, a.columns));
  so.data = data;
  so.model_source = named.size() == 1 ? named.front().second : a.model;
  std::vector<std::string> scenario_files;
  so.files_read = &scenario_files;
  const Scenario sc = load_scenario(a.scenario, so);
  for (const auto& f : scenario_files) inputs.push_back({"named by the scenario", f, RunFile::Kind::file});
  // A model of the other kind of axis has its numbers in other units (N m, not N): refused naming both.
  const Axis plant_axis = sc.plant->motion_axis();
  const auto axis_name = [](Axis x) { return std::string(x == Axis::rotary ? "rotary" : "linear"); };
  const auto check_axis = [&](const std::string& file, const std::optional<Axis>& axis) {
    if (axis && *axis != plant_axis)
      throw InputError(errc::scenario_value,
                       file + ": axis: a " + axis_name(*axis) + " model on the " + axis_name(plant_axis) + " plant of " +
                           a.scenario + "; expected a model identified on a " + axis_name(plant_axis) + " axis",
                       {.file = file, .key = "axis", .value = axis_name(*axis)});
  };
  if (named.empty()) check_axis(a.model, mf.axis);
  for (const auto& [axis, file] : named) check_axis(file, read_model(file).axis);
  check_run_files(inputs, {{"--json", a.output.json}, {"--plot", a.output.plot, RunFile::Kind::figure},
                           {"--report", a.output.report, RunFile::Kind::report}},
                  a.output.overwrite);
  if (sc.plant->num_contacts() > 1) return run_two_axis(a, options, models, sc, data, mf.data_file, mf.data_sha256);
  check_conditions(mf.model.law, sc, a.model, a.scenario);
  ValidationData v;
  v.time = time_column(*data, a.columns);
  v.position = position_column(*data, a.columns);
  v.force = force_column(*data, a.columns);
  v.file = data->file;
  v.sha256 = data->sha256;
  ValidateOptions vo;
  vo.processing.axis = a.columns.parsed_axis();
  Result r = validate_model(mf.model, sc, v, vo);
  record_options(r, options);
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
                                 "velocity, acceleration and force; on a two-axis plant (xy-table) per axis, with the circular "
                                 "test's quadrant glitches and roundness of the measured and the simulated path");
  cmd->add_option("MODEL", a->model,
                  "MODEL.json written by frictionlab identify ... --json; on a two-axis plant (xy-table) a model "
                  "per axis it replaces, AXIS=FILE separated by commas (x=model_x.json,y=model_y.json; an axis not "
                  "named keeps the scenario's law and mass)")
      ->required();
  cmd->add_option("DATA", a->data, "Measured run: a CSV file (with a header row, or without one: see --names), or a MATLAB .mat file")->required();
  add_data_options(cmd, a->columns, "linear");
  a->given = add_table_options(cmd, method_info(MethodId::validate));
  add_output_options(cmd, a->output);
  return [a]() -> int { return run(*a); };
}

}  // namespace frictionlab::cli
