// frictionlab analyze envelope|stick-slip|contour DATA [--time C] [--position C] [--velocity C] [--force C]  (map: app/map_command.cpp)
//                     [--x C --y C --x-reference C --y-reference C --centre X,Y --radius R]
//                     [--json FILE|-] [--plot FILE] [--overwrite]: out through emit (output.hpp),
//                     the one output path of identify and validate.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <iomanip>
#include <sstream>

#include "commands.hpp"
#include "contour_figure.hpp"
#include "data_options.hpp"
#include "figures.hpp"
#include "map_command.hpp"
#include "frictionlab/io/json_text.hpp"
#include "frictionlab/models/parameter.hpp"
#include "report/figure.hpp"
#include "output.hpp"
#include "frictionlab/analysis/contour.hpp"
#include "frictionlab/analysis/envelope.hpp"
#include "frictionlab/analysis/stick_slip.hpp"
#include "frictionlab/error.hpp"
#include "frictionlab/format.hpp"
#include "methods/method.hpp"
#include "frictionlab/io/column_expression.hpp"
#include "frictionlab/io/load.hpp"

namespace frictionlab::cli {
namespace {

struct AnalyzeArgs {
  std::string method;
  std::string data;
  std::string time = "time", position = "position", velocity = "velocity", force = "friction";
  // contour: the measured path and its reference (xy-table columns of `frictionlab simulate`)
  std::string x = "x.position", y = "y.position", x_reference = "x.reference", y_reference = "y.reference";
  std::vector<double> centre;  // m, empty: from the reference or a fit
  double radius = std::numeric_limits<double>::quiet_NaN();  // m
  CLI::Option *x_reference_opt = nullptr, *y_reference_opt = nullptr;
  OutputOptions output;  // --json, --plot, --overwrite (no --report)
  double threshold = 0.0;
  std::string axis = "linear";  // envelope, stick-slip: the units of the text (m or rad, m/s or rad/s, N or N m)
  ReadOptions read;  // --names, --resample, --max-gap, --drop-invalid
  MapArgs map;       // analyze map: --vary, --jobs, --shard, --contact, -o, --transient, --tolerance
};

// NaN is not JSON: null instead.
nlohmann::json num(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

// A column (or an expression of columns) the analysis uses, checked finite (io/column_expression.hpp).
std::vector<double> column(const Dataset& d, const std::string& name, const std::string& option) {
  const Eigen::VectorXd c = finite_signal(d, name, option);
  return {c.data(), c.data() + c.size()};
}

nlohmann::json envelope_json(const EnvelopeResult& r) {
  auto fit = [](const EnvelopeFit& f) {
    return nlohmann::json{{"lambda", num(f.lambda)}, {"p", num(f.p)}, {"q", num(f.q)}, {"slope", num(f.slope)},
                          {"relative_rms", num(f.relative_rms)}};
  };
  return {{"kind", decay_kind_name(r.kind)},
          {"half_cycles", r.amplitudes.size()},
          {"half_period", num(r.half_period)},
          {"decay_fraction", num(r.decay_fraction)},
          {"decrement_per_half_cycle", num(r.decrement_per_half_cycle)},
          {"log_decrement", num(r.log_decrement)},
          {"fits", {{"linear", fit(r.linear)}, {"exponential", fit(r.exponential)}, {"mixed", fit(r.mixed)}}},
          {"peak_times", r.peak_times},
          {"amplitudes", r.amplitudes}};
}

nlohmann::json stick_slip_json(const StickSlipResult& r) {
  auto intervals = [](const std::vector<TimeInterval>& v) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& i : v) a.push_back({i.start, i.end});
    return a;
  };
  return {{"slips", r.slip.size()},
          {"period", num(r.period)},
          {"peak_slip_velocity", num(r.peak_slip_velocity)},
          {"mean_slip_duration", num(r.mean_slip_duration)},
          {"velocity_threshold", num(r.velocity_threshold)},
          {"mean_breakaway_force", num(r.mean_breakaway_force)},
          {"mean_restick_force", num(r.mean_restick_force)},
          {"mean_force_drop", num(r.mean_force_drop)},
          {"breakaway_force", r.breakaway_force},
          {"restick_force", r.restick_force},
          {"stick", intervals(r.stick)},
          {"slip", intervals(r.slip)}};
}

std::string envelope_text(const EnvelopeResult& r, Axis axis) {
  const auto n = [](double x) { return format_number(x); };
  const std::string pos = " " + std::string(unit(Quantity::displacement, axis));
  std::ostringstream o;
  o << "decay        " << decay_kind_name(r.kind) << " (" << r.amplitudes.size() << " half cycles, half period "
    << n(r.half_period) << " s)\n"
    << "amplitude    " << n(r.amplitudes.front()) << pos << " -> " << n(r.amplitudes.back()) << pos << " (lost "
    << n(100.0 * r.decay_fraction) << " %)\n"
    << "linear       " << n(r.decrement_per_half_cycle) << pos << " per half cycle (rms " << n(100 * r.linear.relative_rms)
    << " %)\n"
    << "exponential  rate " << n(r.exponential.lambda) << " 1/s, log decrement " << n(r.log_decrement) << " (rms "
    << n(100 * r.exponential.relative_rms) << " %)\n"
    << "mixed        rate " << n(r.mixed.lambda) << " 1/s, offset " << n(r.mixed.q) << pos << " (rms "
    << n(100 * r.mixed.relative_rms) << " %)\n";
  return o.str();
}

std::string stick_slip_text(const StickSlipResult& r, bool with_force, Axis axis) {
  const auto n = [](double x) { return format_number(x); };
  const std::string vel = " " + std::string(unit(Quantity::velocity, axis));
  const std::string force = " " + std::string(unit(Quantity::force, axis));
  std::ostringstream o;
  o << "slips        " << r.slip.size() << " (velocity threshold " << n(r.velocity_threshold) << vel << ")\n"
    << "period       " << (std::isfinite(r.period) ? n(r.period) + " s" : std::string("n/a (fewer than two slips)"))
    << "\n"
    << "peak slip    " << n(r.peak_slip_velocity) << vel << "\n"
    << "slip length  " << n(r.mean_slip_duration) << " s (mean)\n";
  if (with_force)
    o << "breakaway    " << n(r.mean_breakaway_force) << force << " (mean)\n"
      << "re-stick     " << n(r.mean_restick_force) << force << " (mean)\n"
      << "force drop   " << n(r.mean_force_drop) << force << " (mean)\n";
  return o.str();
}

std::string contour_text(const ContourResult& r) {
  // Micrometres to 3 significant digits: a ballbar trace holds no more.
  const auto um = [](double m) { return format_number(m * 1e6, 3) + " um"; };
  const auto n = [](double x) { return format_number(x, 4); };
  // A centre within a nanometre of an axis is on it (the roundoff of a fit is not a position).
  const auto mm = [&](double m) { return n(std::abs(m) < 1e-9 ? 0.0 : m * 1e3); };
  std::ostringstream o;
  o << "circle       R " << n(r.radius * 1e3) << " mm about (" << mm(r.centre_x) << ", " << mm(r.centre_y)
    << ") mm ("
    << (r.centre_source == "given"     ? "given"
        : r.centre_source == "reference" ? "from the reference"
                                         : "fitted to the measured path")
    << "), " << format_number(r.turns, 3) << " turns\n"
    << "roundness    " << um(r.roundness_m) << " (max - min radial error)\n"
    << "max error    " << um(r.max_radial_error_m) << " (largest |r - R|)\n"
    << "quadrant glitches (peak over the local level, outward +; extent above half the peak):\n";
  for (const auto& g : r.glitches)
    o << "  " << std::setw(3) << g.reversal_deg << " deg    " << std::setw(9) << um(g.peak_m) << " at "
      << format_number(g.angle_deg, 3) << " deg, extent " << format_number(g.extent_deg, 2) << " deg (t "
      << format_number(g.time, 4) << " s)\n";
  return o.str();
}

// diagnostics.quadrant_glitch_m (the four peaks, m, at 0, 90, 180, 270 deg) and
// diagnostics.max_radial_error_m next to the reading notes: Diagnostics has no plain array, so
// the section replaces "diagnostics" with the result's own diagnostics plus the array.
void contour_diagnostics(Result& r, const ContourResult& c) {
  r.diagnostics.numbers["max_radial_error_m"] = c.max_radial_error_m;
  r.diagnostics.numbers["roundness_m"] = c.roundness_m;
  nlohmann::json d = nlohmann::json::parse(to_json(r, -1))["diagnostics"];
  d["quadrant_glitch_m"] = nlohmann::json::array();
  for (const auto& g : c.glitches) d["quadrant_glitch_m"].push_back(num(g.peak_m));
  r.json_sections["diagnostics"] = json_text(d);
}

// analyze envelope: its figures under "result", its figure and text; false when the record cannot
// give an answer (r then holds the error).
bool run_envelope(const AnalyzeArgs& a, const Dataset& d, const std::vector<double>& t, const std::string& name, Result& r,
                  std::vector<ReportFigure>& figures, std::string& text) {
  const std::vector<double> x = column(d, a.position, "--position");
  EnvelopeResult e;
  try {
    e = decay_envelope(t, x);
  } catch (const std::invalid_argument& ex) {
    throw std::invalid_argument(d.where() + ex.what());
  }
  // Numbers or an error, never a NaN or inf printed with exit 0: positions near the range of a
  // double (1e307) overflow the fits' sums of squares.
  const double figures_of_fit[] = {e.half_period, e.decrement_per_half_cycle, e.linear.relative_rms, e.exponential.lambda,
                                   e.exponential.relative_rms, e.mixed.lambda, e.mixed.q, e.mixed.relative_rms};
  if (!std::all_of(std::begin(figures_of_fit), std::end(figures_of_fit), [](double v) { return std::isfinite(v); })) {
    r.status = ResultStatus::error;
    r.code = errc::output_not_finite;
    r.message = d.where() + "decay envelope: a figure of the fits is not a finite number (positions up to " +
                format_number(*std::max_element(e.amplitudes.begin(), e.amplitudes.end())) +
                " overflow double arithmetic); expected positions in m or rad of ordinary size";
    return false;
  }
  r.json_sections["result"] = json_text(envelope_json(e));
  if (!a.output.plot.empty()) figures.push_back({"fit", "", envelope_figure(t, x, e, name)});
  text = envelope_text(e, parse_axis(a.axis));
  return true;
}

// analyze contour: its figures under "result", its figure and text; false when the record cannot
// give an answer (r then holds the error).
bool run_contour(const AnalyzeArgs& a, const Dataset& d, const std::vector<double>& t, const std::string& name, Result& r,
                 std::vector<ReportFigure>& figures, std::string& text) {
  const std::vector<double> x = column(d, a.x, "--x"), y = column(d, a.y, "--y");
  // The reference is optional by default; asked for by name, it must be there.
  const bool asked = a.x_reference_opt->count() > 0 || a.y_reference_opt->count() > 0;
  std::vector<double> xr, yr;
  if (asked || (d.has_column(a.x_reference) && d.has_column(a.y_reference))) {
    xr = column(d, a.x_reference, "--x-reference");
    yr = column(d, a.y_reference, "--y-reference");
  }
  ContourOptions o;
  if (!a.centre.empty()) o.centre = std::array<double, 2>{a.centre[0], a.centre[1]};
  o.radius = a.radius;
  ContourResult c;
  try {
    c = analyze_contour(t, x, y, xr, yr, o);
  } catch (const std::invalid_argument& ex) {
    throw std::invalid_argument(d.where() + ex.what());
  }
  if (!std::isfinite(c.radius) || !std::isfinite(c.roundness_m) || !std::isfinite(c.max_radial_error_m)) {
    r.status = ResultStatus::error;
    r.code = errc::output_not_finite;
    r.message = d.where() + "contour: the radius or the radial errors are not finite numbers (coordinates that overflow "
                            "double arithmetic); expected positions in m of ordinary size";
    return false;
  }
  r.json_sections["result"] = contour_json(c);
  contour_diagnostics(r, c);
  if (!a.output.plot.empty()) figures.push_back({"fit", "", contour_figure(t, c, name)});
  text = contour_text(c);
  return true;
}

// analyze stick-slip: its figures under "result", its figure and text; false when the record cannot
// give an answer (r then holds the error).
bool run_stick_slip(const AnalyzeArgs& a, const Dataset& d, const std::vector<double>& t, const std::string& name, Result& r,
                    std::vector<ReportFigure>& figures, std::string& text) {
  const std::vector<double> v = column(d, a.velocity, "--velocity");
  std::vector<double> f;
  if (d.has_column(a.force) || is_column_expression(d, a.force)) f = column(d, a.force, "--force");
  StickSlipOptions o;
  o.velocity_threshold = a.threshold;
  StickSlipResult ss;
  try {
    ss = detect_stick_slip(t, v, f, o);
  } catch (const std::invalid_argument& ex) {
    throw std::invalid_argument(d.where() + ex.what());
  }
  if (!ss.found()) {  // data that cannot give an answer: exit 2, with the JSON if asked for
    r.status = ResultStatus::error;
    r.message = d.where() + ss.message;
    return false;
  }
  r.json_sections["result"] = json_text(stick_slip_json(ss));
  if (!a.output.plot.empty()) figures.push_back({"fit", "", stick_slip_figure(t, v, f, ss, name)});
  text = stick_slip_text(ss, !f.empty(), parse_axis(a.axis));
  return true;
}

/// One kind of `frictionlab analyze`: its name (the positional argument) and what runs it on a
/// record (map is its own command: a scenario, not a record, see map_command.hpp).
struct AnalyzeKind {
  std::string name;
  bool (*run)(const AnalyzeArgs& a, const Dataset& d, const std::vector<double>& t, const std::string& name, Result& r,
              std::vector<ReportFigure>& figures, std::string& text);
};

/// The analyze kinds that read a record, in the order of the help: one line each.
const std::vector<AnalyzeKind>& analyze_kinds() {
  static const std::vector<AnalyzeKind> kinds = {
      {"envelope", run_envelope},
      {"stick-slip", run_stick_slip},
      {"contour", run_contour},
  };
  return kinds;
}

constexpr const char* kMap = "map";  // analyze map: a scenario over a grid (map_command.hpp)

}  // namespace

Handler register_analyze(CLI::App& app) {
  auto a = std::make_shared<AnalyzeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "analyze",
      "Analyse a motion record: decay envelope, stick-slip, or a two-axis circular test (contour); or map a scenario "
      "over a grid of its parameters (map: each point simulated and classified as converged, steady sliding, "
      "stick-slip, hunting or oscillating, with the cycle's amplitude and period and the theory where it applies).");
  cmd->add_option("method", a->method,
                  "envelope (free-oscillation decay), stick-slip (exit 2 with a message when the record never "
                  "slips), contour (a two-axis circular test: radial error, quadrant glitches, roundness) or map (DATA is a "
                  "scenario file: see the Map options)")
      ->required()
      ->check(CLI::IsMember([] {
        std::vector<std::string> names;
        for (const auto& k : analyze_kinds()) names.push_back(k.name);
        names.push_back(kMap);
        return names;
      }()));
  cmd->add_option("data", a->data,
                  "CSV file, with a header row (the output of `frictionlab simulate` works) or without one (see "
                  "--names), or .mat")
      ->required();
  cmd->add_option("--time", a->time, "time column (s)")->capture_default_str();
  cmd->add_option("--position", a->position, "position column (envelope)")->capture_default_str();
  cmd->add_option("--velocity", a->velocity, "velocity column (stick-slip)")->capture_default_str();
  cmd->add_option("--force", a->force, "friction force column (stick-slip; optional: skipped if absent)")
      ->capture_default_str();
  cmd->add_option("--x", a->x, "contour: measured x position column (m)")->capture_default_str();
  cmd->add_option("--y", a->y, "contour: measured y position column (m)")->capture_default_str();
  a->x_reference_opt = cmd->add_option("--x-reference", a->x_reference,
                                       "contour: reference x column (m); when the file has no such column (and the "
                                       "option is not given) the centre and radius come from a circle fit")
                           ->capture_default_str();
  a->y_reference_opt =
      cmd->add_option("--y-reference", a->y_reference, "contour: reference y column (m)")->capture_default_str();
  cmd->add_option("--centre", a->centre, "contour: centre of the nominal circle X,Y (m); default from the reference")
      ->expected(2)
      ->delimiter(',');
  cmd->add_option("--radius", a->radius, "contour: radius of the nominal circle (m); default from the reference")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--threshold", a->threshold,
                  "stick-slip: |v| at or below counts as stuck (0 = automatic: exact zeros or 1 % of max |v|)");
  cmd->add_option("--axis", a->axis,
                  "envelope, stick-slip: linear (m, m/s, N) or rotary (rad, rad/s, N m): the units of the text")
      ->check(CLI::IsMember({"linear", "rotary"}))
      ->capture_default_str();
  CLI::Option* json =
      output_option(cmd->add_option("--json", a->output.json, "write the result as JSON to FILE, or '-' for stdout"));
  add_plot_option(cmd, a->output.plot);
  cmd->add_flag("--overwrite", a->output.overwrite, "replace an existing --json or --plot file");
  add_read_options(cmd, a->read);
  add_map_options(cmd, a->map);
  a->output.command = cmd;
  register_json_output(cmd, json, [a] { return a->method.empty() ? std::string("analyze") : a->method; });
  return [a]() -> int {
    if (a->method == kMap) return run_map_command(a->data, a->map, a->output);
    if (!a->map.vary.empty() || !a->map.shard.empty() || !a->map.out.empty() || !a->map.contact.empty())
      throw std::invalid_argument("--vary, --shard, --contact and -o belong to analyze map; analyze " + a->method +
                                  " writes --json and --plot");
    check_outputs(a->output, command_inputs(a->output.command));
    const Dataset d = load_data(a->data, a->read, a->time);
    // The analysis goes out as identify's results do (emit): its figures as JSON under "result",
    // the data file, its digest and the data notes (resampling, warnings) in the usual places.
    Result r;
    r.method = a->method;
    stamp(r, d);
    std::vector<ReportFigure> figures;
    const std::string name = std::filesystem::path(a->data).filename().string();
    const std::vector<double> t = column(d, a->time, "--time");
    std::string text;
    const AnalyzeKind* kind = nullptr;
    for (const auto& k : analyze_kinds())
      if (k.name == a->method) kind = &k;
    if (!kind->run(*a, d, t, name, r, figures, text)) return emit(r, a->output);
    return emit(r, a->output, data_note(d) + text, &figures);
  };
}

}  // namespace frictionlab::cli
