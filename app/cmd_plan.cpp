// frictionlab plan METHOD --prior MODEL.json --scenario PLANT.yaml -o PROFILE.csv: design the
// excitation of an identification experiment and predict each parameter's std before it is run.
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.hpp"
#include "frictionlab/analysis/plan/plan.hpp"
#include "frictionlab/format.hpp"
#include "finite_output.hpp"
#include "io/atomic_write.hpp"
#include "frictionlab/scenario/plan_files.hpp"
#include "output.hpp"

namespace frictionlab::cli {
namespace {

struct PlanArgs {
  std::string method, prior, scenario, profile, json;
  std::vector<std::string> noise, limits;
  int runs = 0;
  std::uint64_t seed = 1;
  double margin = 0, lag_fraction = 0.01, rate = 0, load = 0, warm_up = 0;
  int speeds = 15, ripple_periods = 4;
  bool overwrite = false;
};

std::string text_of(const PlanResult& r) {
  std::ostringstream s;
  const ExperimentProfile& p = r.profile;
  s << "frictionlab plan " << r.method << ": " << p.command << " profile (" << r.drive << "), "
    << format_number(p.duration, 5) << " s at " << format_number(p.sample_rate, 5) << " Hz\n";
  for (const auto& f : p.figures)
    s << "  " << std::left << std::setw(24) << f.name << std::right << std::setw(12) << format_number(f.value, 5) << " "
      << std::left << std::setw(8) << f.unit << std::right << " " << f.what << "\n";
  s << "on the prior:\n";
  for (const auto& f : r.simulated)
    s << "  " << std::left << std::setw(24) << f.name << std::right << std::setw(12) << format_number(f.value, 5) << " "
      << f.unit << "\n";
  const auto& pr = r.prediction;
  s << "predicted std (" << pr.runs - pr.failed << " of " << pr.runs << " Monte Carlo runs, seed " << pr.seed << "):\n";
  s << "  " << std::left << std::setw(8) << "param" << std::right << std::setw(13) << "prior" << std::setw(13) << "bias"
    << std::setw(13) << "std (MC)" << std::setw(13) << "std (Fisher)" << std::setw(13) << "(a priori)" << std::setw(9)
    << "std %" << "  unit\n";
  auto row = [&](const ParameterSpread& x, const std::string& prefix) {
    const double ref = std::isfinite(x.prior) && x.prior != 0 ? x.prior : x.mean;
    s << "  " << std::left << std::setw(8) << (prefix + x.name) << std::right << std::setw(13) << format_number(x.prior, 5)
      << std::setw(13) << format_number(x.mean - x.prior, 3) << std::setw(13)
      << (x.undetermined ? std::string("null") : format_number(x.std_monte_carlo, 3)) << std::setw(13)
      << (std::isfinite(x.std_fisher) ? format_number(x.std_fisher, 3) : std::string("-")) << std::setw(13)
      << (std::isfinite(x.std_a_priori) ? format_number(x.std_a_priori, 3) : std::string("-")) << std::setw(9)
      << (x.undetermined ? std::string("-") : format_number(100 * x.std_monte_carlo / std::abs(ref), 3)) << "  "
      << x.unit << "\n";
  };
  for (const auto& x : pr.parameters) row(x, "");
  if (!pr.readoff.empty()) {
    s << "the lecture's read-offs:\n";
    for (const auto& x : pr.readoff) row(x, "");
  }
  if (!r.undetermined.empty()) {
    s << "undetermined:";
    for (const auto& u : r.undetermined) s << " " << u;
    s << "\n";
  }
  for (const auto& w : r.warnings) s << "warning: " << w << "\n";
  return s.str();
}

int run(const PlanArgs& a) {
  if (a.profile == "-") throw std::invalid_argument("-o -: the profile is written to a file (PROFILE.csv), not stdout");
  std::vector<RunFile> inputs{{"--prior", a.prior, RunFile::Kind::file}, {"--scenario", a.scenario, RunFile::Kind::file}};
  for (RunFile& f : scenario_inputs(a.scenario)) inputs.push_back(std::move(f));
  check_run_files(inputs, {{"-o", a.profile, RunFile::Kind::file}, {"--json", a.json, RunFile::Kind::file}}, a.overwrite);
  const PlanMethod method = parse_plan_method(a.method);
  PlanOptions o;
  o.noise = parse_sensor_noise(a.noise, "--noise");
  o.limits = parse_plan_limits(a.limits, "--limits");
  o.design.margin = a.margin;
  o.design.lag_fraction = a.lag_fraction;
  o.design.speeds = a.speeds;
  o.design.sample_rate = a.rate;
  o.design.load = a.load;
  o.design.warm_up = a.warm_up;
  o.design.ripple_periods = a.ripple_periods;
  o.runs = a.runs;
  o.seed = a.seed;
  if (a.runs == 1 || a.runs < 0) throw std::invalid_argument("--runs " + std::to_string(a.runs) + ": expected >= 2 Monte Carlo runs");
  const PlanRig rig = load_plan_rig(a.prior, a.scenario);
  progress_start("frictionlab plan " + a.method);
  o.progress = [](int k, int n) { progress_stage("Monte Carlo run " + std::to_string(k) + " of " + std::to_string(n)); };
  PlanResult r = plan_experiment(method, rig, o);
  progress_stop();
  // Without sensor noise the Monte Carlo runs differ only by round-off: the predicted std are
  // about 1e-19 and say nothing about a real measurement. Said in the text and the JSON.
  if (a.noise.empty())
    r.warnings.push_back("no --noise given: the predicted standard deviations come from round-off alone (a "
                         "noise-free measurement), not from a real one; give the sensors' noise, e.g. --noise "
                         "current=2e-4,velocity=0.5");
  const std::string text = text_of(r);
  const std::string json = plan_to_json(r, o, a.profile) + "\n";
  // Numbers or an error, never both (finite_output.hpp): the text, the profile and the JSON.
  std::string profile;
  if (r.ok) {
    profile = r.profile.to_csv();
    require_finite_output(text, "");
    require_finite_output(profile, a.profile);
    require_finite_output(json, a.json);
  }
  (a.json == "-" ? std::cerr : std::cout) << text;
  if (!r.ok) {
    if (a.json == "-") std::cout << plan_to_json(r, o, a.profile, -1) << "\n";
    else if (!a.json.empty()) write_file_atomic(a.json, json, {a.overwrite});
    print_error(r.message);
    return 2;
  }
  write_file_atomic(a.profile, profile, {a.overwrite});
  if (a.json == "-") std::cout << plan_to_json(r, o, a.profile, -1) << "\n";
  else if (!a.json.empty()) write_file_atomic(a.json, json, {a.overwrite});
  return 0;
}

}  // namespace

Handler register_plan(CLI::App& app) {
  auto a = std::make_shared<PlanArgs>();
  auto* cmd = app.add_subcommand(
      "plan",
      "Design an identification experiment (the profile for the rig's controller) from a prior model and a rig "
      "scenario, and predict each parameter's std before it is run");
  cmd->footer(
      "The plan is simulated on the prior, the sensor noise added R times, the method's identification run on each\n"
      "copy (Monte Carlo); sweep and idim also report the std their noisy least-squares fits give (Fisher) and\n"
      "the a-priori std: the Fisher information of the noise-free plan with the stated noise propagated through\n"
      "the method's averaging (sweep) or filtering and decimation (idim; the filtered noise's correlation counted).\n"
      "Methods and what they need in the scenario:\n"
      "  breakaway  trapezoid of current (dc-motor, drive: current) or force (axis): ramp slow against M / Fv,\n"
      "             peak --margin x Fs (1.4), hold to steady state, ramp down.  Columns time_s,current_A\n"
      "  sweep      velocity set points log-spaced from vs / 5 (at least 4 below vs) to the top speed, both\n"
      "             directions, under a velocity loop (controller: {loop: velocity, ...}).\n"
      "             Columns time_s,velocity_rad_s (or _m_s)\n"
      "  idim       trapezoidal velocity moves out and back at 1, 1/2, 1/4 of the top speed, under a position\n"
      "             loop (controller: {loop: position, ...}).  Columns time_s,position_m (or _rad)\n"
      "  lugre      presliding sine (0.8 Fs) then sliding sine (2 Fs) of force or current; a LuGre prior.\n"
      "  load-steps idim's moves at loads 0, --load / 2 and --load (the rig applies them: a third column,\n"
      "             load_N or load_N_m), for mu_load (idim's load term); a position loop.\n"
      "  warm-up    moves out and back at the top speed and half of it for --warm-up s (default 2 time constants\n"
      "             of the scenario's environment: {thermal: ...}) while the contact heats, for Fv_per_K (idim's\n"
      "             temperature term, the rig logging the temperature); a position loop.\n"
      "  ripple-scan slow moves over --ripple-periods of the prior's ripple_period, the top harmonic at 1/20\n"
      "             of idim's low-pass, at that speed and half of it, for the ripple's harmonics; a position loop.\n"
      "  The effects' plans warn when the design cannot separate the effect from the other terms (e.g. a\n"
      "  temperature that follows the speed schedule).\n"
      "--noise KEY=STD,... (repeatable): position (m or rad), velocity (m/s or rad/s), current (A: the force is\n"
      "  Kt times the measured current), force (N or N m: an axis's measured drive force), encoder (m or rad\n"
      "  per step: quantisation of the position).  Default: no noise.\n"
      "--limits KEY=VALUE,... (repeatable): current (A, peak motor current), force (N or N m, peak drive force),\n"
      "  speed (m/s or rad/s), min_speed (m/s or rad/s: slowest speed the drive holds), travel (m or rad from\n"
      "  the start).  A limit that leaves no experiment is exit status 2 naming it.\n"
      "A parameter the plan cannot determine (e.g. vs when no speed lies below it) has std null and a warning.\n"
      "Example: frictionlab plan breakaway --prior examples/plan/craig_motor_prior.json \\\n"
      "           --scenario examples/craig_motor_trapezoid.yaml --noise current=2e-4,velocity=0.5 -o ramp.csv");
  cmd->add_option("METHOD", a->method, "breakaway, sweep, idim, lugre, load-steps, warm-up or ripple-scan")->required();
  cmd->add_option("--prior", a->prior,
                  "Prior model: MODEL.json written by frictionlab identify ... --json (its law; parameters.M replaces "
                  "an axis plant's inertia), or a law file")
      ->required();
  cmd->add_option("--scenario", a->scenario,
                  "The rig: a scenario YAML with an axis or dc-motor plant (and controller); its friction and input "
                  "are replaced by the prior's law and the plan's profile")
      ->required();
  output_option(cmd->add_option("-o,--output", a->profile,
                                "PROFILE.csv: the profile for the rig's controller (time_s and the command with its unit)")
                    ->required());
  CLI::Option* json = output_option(
      cmd->add_option("--json", a->json, "Write the plan and prediction as JSON to FILE, or '-' for stdout"));
  cmd->add_option("--noise", a->noise, "Sensor noise, KEY=STD,... (see below)");
  cmd->add_option("--limits", a->limits, "Rig limits, KEY=VALUE,... (see below)");
  cmd->add_option("--runs", a->runs, "Monte Carlo runs (>= 2); default 40 (lugre 8)");
  cmd->add_option("--seed", a->seed, "First seed of the runs' noise generators")->capture_default_str();
  cmd->add_option("--margin", a->margin, "breakaway: peak / prior Fs (default 1.4); lugre: sliding amplitude / Fs (default 2)");
  cmd->add_option("--lag-fraction", a->lag_fraction,
                  "breakaway: the ramp's lag bias rate x M / Fv as a fraction of Fc (sets the ramp rate)")
      ->capture_default_str();
  cmd->add_option("--speeds", a->speeds, "sweep: set points per direction")->capture_default_str();
  cmd->add_option("--load", a->load, "load-steps: the largest load the rig applies, N or N m (> 0)");
  cmd->add_option("--warm-up", a->warm_up, "warm-up: length of the run, s (default: 2 thermal time constants)");
  cmd->add_option("--ripple-periods", a->ripple_periods, "ripple-scan: ripple periods each move covers (>= 2)")
      ->capture_default_str();
  cmd->add_option("--rate", a->rate, "Sample rate of the profile and of the simulated measurement, Hz (default: the "
                                     "scenario's output_rate)");
  cmd->add_flag("--overwrite", a->overwrite, "Replace an existing -o or --json file");
  register_json_output(cmd, json, [a] { return a->method.empty() ? std::string("plan") : a->method; });
  return [a]() -> int { return run(*a); };
}

}  // namespace frictionlab::cli
