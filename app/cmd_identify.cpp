// frictionlab identify METHOD DATA: friction parameters from measured data.
#include <array>
#include <limits>
#include <memory>
#include <sstream>

#include "commands.hpp"
#include "data_options.hpp"
#include "frictionlab/identify/breakaway.hpp"
#include "frictionlab/identify/decay.hpp"
#include "frictionlab/identify/idim.hpp"
#include "frictionlab/identify/lugre.hpp"
#include "frictionlab/identify/sweep.hpp"
#include "flag_names.hpp"
#include "frictionlab/io/law_file.hpp"
#include "output.hpp"

namespace frictionlab::cli {
namespace {

// Everything the identify subcommands parse into; one instance lives for the whole run.
// The data file, column and output options of one method subcommand (each has its own, so
// that "was --force given?" is asked of the method the user chose).
struct MethodIO {
  std::string data;
  DataOptions columns;
  OutputOptions output;
};

struct IdentifyArgs {
  // idim
  std::string terms = "inertia,viscous,coulomb,offset";
  double cutoff = 100, delta = 2;  // cutoff, decimate, skip: from the sample rate unless given
  std::string from;                // "position", "velocity" or "" (position unless only --velocity is given)
  std::string vs = "0.01";
  long delay = 0;
  int decimate = 10;
  long skip = 49;
  std::string validate;
  // breakaway, decay, sweep
  double inertia = std::numeric_limits<double>::quiet_NaN();
  double threshold = std::numeric_limits<double>::quiet_NaN();
  double stiffness = std::numeric_limits<double>::quiet_NaN();
  double natural_frequency = std::numeric_limits<double>::quiet_NaN();
  bool pendulum = false;
  std::string model = "stribeck";
  double fixed_delta = 0;
  double relative_tolerance = 0.01, min_duration = 0.5;
  std::vector<std::string> segments;
  std::string reference;  // commanded-velocity column to segment on
  // lugre
  double lugre_inertia = std::numeric_limits<double>::quiet_NaN();
  std::string lugre_static;
  int lugre_substeps = 4;
  double lugre_vd = 0;
};

std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

CLI::App* method(CLI::App* identify, const std::string& name, const std::string& help, MethodIO& io,
                 const std::string& default_axis) {
  auto* cmd = identify->add_subcommand(name, help);
  cmd->add_option("DATA", io.data, "Measured data: a CSV file (with a header row, or without one: see --names), or a MATLAB .mat file")->required();
  add_data_options(cmd, io.columns, default_axis);
  add_output_options(cmd, io.output);
  return cmd;
}

void stamp(Result& r, const Dataset& d) {
  r.data_file = d.file;
  r.data_sha256 = d.sha256;
  note_data(r, d);
}

IdimData idim_data(const Dataset& d, const DataOptions& c, const std::string& from) {
  IdimData x;
  x.time = time_column(d, c);
  const bool use_velocity =
      from == "velocity" || (from.empty() && c.velocity_opt->count() > 0 && c.position_opt->count() == 0);
  if (use_velocity) x.velocity = velocity_column(d, c);
  else x.position = position_column(d, c);
  x.force = force_column(d, c);
  x.file = d.file;
  x.sha256 = d.sha256;
  return x;
}

IdimData idim_data(const std::string& path, const DataOptions& c, const std::string& from) {
  return idim_data(load_data(path, c), c, from);
}

int run_idim(const IdentifyArgs& a, const MethodIO& io, const CLI::App& cmd) {
  check_outputs(io.output);
  IdimOptions o;
  o.terms = split_list(a.terms);
  o.cutoff_hz = a.cutoff;
  o.decimation = a.decimate;
  o.skip = a.skip;
  // Not given: chosen from the sample rate (idim_rate_defaults; the EMPS recipe at 1 kHz).
  o.auto_cutoff = cmd.get_option("--cutoff")->count() == 0;
  o.auto_decimation = cmd.get_option("--decimate")->count() == 0;
  o.auto_skip = cmd.get_option("--skip")->count() == 0;
  if (a.from == "position") o.source = IdimSource::position;
  else if (a.from == "velocity") o.source = IdimSource::velocity;
  else if (!a.from.empty())
    throw std::invalid_argument("--from '" + a.from + "': expected position or velocity");
  if (a.vs == "search") {
    o.search_stribeck_vs = true;
  } else {
    try {
      o.stribeck_vs = std::stod(a.vs);
    } catch (const std::exception&) {
      throw std::invalid_argument("--vs '" + a.vs + "': expected a Stribeck velocity (m/s or rad/s) or 'search'");
    }
  }
  o.input_delay = a.delay;
  o.stribeck_delta = a.delta;
  o.axis = io.columns.parsed_axis();
  const Dataset d = load_data(io.data, io.columns);
  const IdimData data = idim_data(d, io.columns, a.from);
  Result r = identify_idim(data, o);
  r.data_file = data.file;
  r.data_sha256 = data.sha256;
  note_data(r, d);
  if (r.ok() && !a.validate.empty()) r.validation = cross_test(r, idim_data(a.validate, io.columns, a.from), o);
  name_flags(r);
  return emit(r, io.output);
}

int run_breakaway(const IdentifyArgs& a, const MethodIO& io) {
  check_outputs(io.output);
  const Dataset d = load_data(io.data, io.columns);
  BreakawayData x{time_column(d, io.columns), force_column(d, io.columns), velocity_column(d, io.columns)};
  BreakawayOptions o;
  o.inertia = a.inertia;
  o.velocity_threshold = a.threshold;
  o.axis = io.columns.parsed_axis();
  Result r = identify_breakaway(x, o);
  stamp(r, d);
  return emit(r, io.output);
}

int run_sweep(const IdentifyArgs& a, const MethodIO& io) {
  check_outputs(io.output);
  const Dataset d = load_data(io.data, io.columns);
  SweepData x{time_column(d, io.columns), force_column(d, io.columns), velocity_column(d, io.columns)};
  SweepOptions o;
  if (!a.reference.empty()) {
    DataOptions ref = io.columns;
    ref.velocity = a.reference;
    o.reference = velocity_column(d, ref);
  }
  o.fit.model = parse_static_fit_model(a.model);
  o.fit.fixed_delta = a.fixed_delta;
  o.relative_tolerance = a.relative_tolerance;
  o.min_duration = a.min_duration;
  o.axis = io.columns.parsed_axis();
  for (const auto& s : a.segments) {
    const auto colon = s.find(':');
    try {
      if (colon == std::string::npos) throw std::invalid_argument("");
      o.windows.push_back({std::stod(s.substr(0, colon)), std::stod(s.substr(colon + 1))});
    } catch (const std::exception&) {
      throw std::invalid_argument("--segment '" + s + "': expected T_BEGIN:T_END in seconds, e.g. 2.5:4.0");
    }
  }
  Result r = identify_sweep(x, o);
  stamp(r, d);
  return emit(r, io.output);
}

int run_decay(const IdentifyArgs& a, const MethodIO& io) {
  check_outputs(io.output);
  const Dataset d = load_data(io.data, io.columns);
  DecayData x{time_column(d, io.columns), position_column(d, io.columns)};
  DecayOptions o;
  o.stiffness = a.stiffness;
  o.inertia = a.inertia;
  o.natural_frequency = a.natural_frequency;
  o.pendulum = a.pendulum;
  o.axis = io.columns.parsed_axis();
  Result r = identify_decay(x, o);
  stamp(r, d);
  return emit(r, io.output);
}

int run_lugre(const IdentifyArgs& a, const MethodIO& io) {
  check_outputs(io.output);
  LugreOptions o;
  o.inertia = a.lugre_inertia;
  o.substeps = a.lugre_substeps;
  o.vd = a.lugre_vd;
  o.axis = io.columns.parsed_axis();
  if (!a.lugre_static.empty()) o.static_law = load_law(a.lugre_static);
  const Dataset d = load_data(io.data, io.columns);
  LugreData x{time_column(d, io.columns), force_column(d, io.columns), position_column(d, io.columns)};
  o.progress = [](int iteration, double cost, double) {
    progress_stage("output-error fit, iteration " + std::to_string(iteration) + ", cost " + std::to_string(cost) + " m^2");
  };
  Result r = identify_lugre(x, o);
  stamp(r, d);
  name_flags(r);
  return emit(r, io.output);
}

}  // namespace

Handler register_identify(CLI::App& app) {
  auto* identify = app.add_subcommand("identify", "Identify friction parameters from measured data");
  identify->require_subcommand(1);
  auto a = std::make_shared<IdentifyArgs>();
  auto io = std::make_shared<std::array<MethodIO, 5>>();

  auto* idim = method(identify, "idim",
                      "Inverse dynamic model least squares on a trajectory: force = M qdd + friction(qd) + offset "
                      "(EMPS benchmark recipe). Best cross-test on EMPS: --terms inertia,asymmetric,stribeck --delay 1",
                      (*io)[0], "linear");
  idim->add_option("--terms", a->terms,
                   "Comma-separated regressors: inertia, viscous, coulomb, offset, asymmetric (Fv_pos, Fc_pos, Fv_neg, "
                   "Fc_neg; then leave out offset), stribeck (Fs_minus_Fc with --vs, --delta)")
      ->capture_default_str();
  idim->add_option("--cutoff", a->cutoff,
                   "Position low-pass cut-off (Hz). Default from the sample rate fs: min(100 Hz, fs/10) (EMPS: 100 Hz at "
                   "1 kHz)");
  idim->add_option("--decimate", a->decimate,
                   "Keep one sample in N after the anti-alias filter. Default from fs: floor(fs/100 Hz), 1 to 10 (EMPS: 10)");
  idim->add_option("--skip", a->skip,
                   "Samples dropped at the start (filter transient). Default from fs: five periods of the cut-off less one "
                   "sample (EMPS: 49)");
  idim->add_option("--from", a->from,
                   "What the regressors are built from when the file has both: position (filtered, differentiated "
                   "twice) or velocity (the measured velocity filtered like the position, differentiated once). "
                   "Default: position, or velocity when only --velocity is given")
      ->check(CLI::IsMember({"position", "velocity"}));
  idim->add_option("--vs", a->vs, "Stribeck velocity of the stribeck term (m/s or rad/s), or 'search' for the value "
                                  "that minimises the identification error")
      ->capture_default_str();
  idim->add_option("--delay", a->delay,
                   "Samples by which the applied force lags the recorded input (EMPS: 1, its controller output is "
                   "applied one sample later)")
      ->capture_default_str();
  idim->add_option("--delta", a->delta, "Stribeck exponent of the stribeck term")->capture_default_str();
  idim->add_option("--validate", a->validate, "Second data file for a cross-test with the identified parameters");

  auto* breakaway = method(identify, "breakaway",
                           "Torque-mode trapezoid experiment (ramp up, hold, ramp down): Fs, Fc, Fv (and M) from "
                           "time, torque (or current with --kt) and velocity",
                           (*io)[1], "rotary");
  breakaway->add_option("--inertia", a->inertia, "Rotor inertia (kg m^2 or kg); estimated when not given");
  breakaway->add_option("--velocity-threshold", a->threshold, "Speed above which the axis moves (default 1 % of max)");

  auto* sweep = method(identify, "sweep",
                       "Constant-velocity tests: friction-velocity points from steady segments (found on the smoothed "
                       "velocity with a noise-aware band, or on --reference) and a fitted law; vs and delta get std "
                       "null when no level is slow enough to show the Stribeck part",
                       (*io)[2], "rotary");
  sweep->add_option("--model", a->model, "Law to fit: coulomb-viscous, coulomb-viscous-asymmetric, stribeck, stribeck-asymmetric")
      ->capture_default_str();
  sweep->add_option("--delta", a->fixed_delta, "Hold the Stribeck exponent at this value (default: fitted)");
  sweep->add_option("--tolerance", a->relative_tolerance, "Relative velocity band of a steady segment")->capture_default_str();
  sweep->add_option("--min-duration", a->min_duration, "Shortest steady segment (s)")->capture_default_str();
  sweep->add_option("--segment", a->segments, "T_BEGIN:T_END (s) of a steady segment, instead of detection (repeatable)");
  sweep->add_option("--reference", a->reference,
                    "Column of the commanded velocity: steady segments are found on it instead of on the measured "
                    "velocity (which is smoothed, with a band that covers its measured noise)");

  auto* decay = method(identify, "decay",
                       "Free oscillation of a pendulum or spring-mass: Coulomb and viscous friction from the energy lost "
                       "per half cycle",
                       (*io)[3], "linear");
  decay->add_option("--stiffness", a->stiffness, "Restoring stiffness (N/m or N m/rad; m g l for a pendulum)");
  decay->add_option("--inertia", a->inertia, "Mass or inertia (kg or kg m^2), with --natural-frequency");
  decay->add_option("--natural-frequency", a->natural_frequency,
                    "sqrt(k/M) (rad/s): without --stiffness, report Fc/k and the damping ratio");
  decay->add_flag("--pendulum", a->pendulum, "Restoring torque is stiffness * sin(angle)");

  auto* lugre = method(identify, "lugre",
                       "LuGre parameters by output error: simulate the axis with the measured force, compare positions, "
                       "Ceres least squares. From one record that starts at rest and breaks away both ways (presliding, "
                       "sliding, reversals), all six: sigma0, sigma1 and the static part Fc, Fs, vs, sigma2 (started "
                       "from the sliding samples and a grid of Fs and vs), unless --static gives the static part. A "
                       "parameter the record cannot determine, or that ends at a bound, has std null (nan) and a warning",
                       (*io)[4], "linear");
  lugre->add_option("--inertia", a->lugre_inertia, "Mass or inertia of the axis (kg or kg m^2), > 0")->required();
  lugre->add_option("--static", a->lugre_static,
                    "MODEL.json (or .yaml) with the static law (stribeck, lugre, static-coulomb-viscous, coulomb-viscous), "
                    "e.g. from identify sweep: held fixed instead of identified");
  lugre->add_option("--vd", a->lugre_vd,
                    "Damping decay velocity (m/s or rad/s) of the damping sigma1 exp(-(v/vd)^2), held fixed; 0 = constant "
                    "damping. A --static lugre model with vd > 0 gives its own")
      ->capture_default_str();
  lugre->add_option("--substeps", a->lugre_substeps, "Simulation steps per sample interval of the fit")->capture_default_str();

  return [a, io, idim, breakaway, sweep, decay, lugre]() -> int {
    if (idim->parsed()) return run_idim(*a, (*io)[0], *idim);
    if (breakaway->parsed()) return run_breakaway(*a, (*io)[1]);
    if (sweep->parsed()) return run_sweep(*a, (*io)[2]);
    if (decay->parsed()) return run_decay(*a, (*io)[3]);
    if (lugre->parsed()) return run_lugre(*a, (*io)[4]);
    return 2;
  };
}

}  // namespace frictionlab::cli
