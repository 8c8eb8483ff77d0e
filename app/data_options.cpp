#include "data_options.hpp"

#include "frictionlab/error.hpp"
#include "frictionlab/format.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "frictionlab/io/column_expression.hpp"
#include "frictionlab/io/columns.hpp"
#include "frictionlab/io/load.hpp"
#include "frictionlab/signal/sampling.hpp"

namespace frictionlab::cli {
namespace {

std::vector<std::string> split_names(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  if (!text.empty() && text.back() == ',') out.emplace_back();  // "t,q," names an empty third column: refused
  return out;
}

// --resample's DT: "" (the median step) or a step in s > 0.
double parse_step(const std::string& text) {
  if (text.empty()) return 0;
  double v = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (ec != std::errc() || ptr != end || !std::isfinite(v) || v <= 0) {
    throw InputError(errc::option_out_of_range,
                     "--resample '" + text +
                         "': expected the grid step in seconds (> 0, e.g. 0.001), or no value for the median "
                         "step (put --resample after DATA, or write --resample=DT)",
                     {.option = "--resample", .value = text});
  }
  return v;
}

}  // namespace

void add_read_options(CLI::App* cmd, ReadOptions& o) {
  cmd->add_option("--format", o.format,
                  "How DATA is read: csv (a text table, whatever the file's name: a robot's .log, a .dat), mat, or "
                  "auto (by the extension: .csv .tsv .txt or .mat)")
      ->check(CLI::IsMember({"auto", "csv", "mat"}))
      ->capture_default_str()
      ->group("Data columns");
  cmd->add_option("--names", o.names,
                  "Names of a CSV file's columns in order, for a file without a header row (its "
                  "columns are otherwise c1, c2, ...); with a header row they replace its names. Fewer names than "
                  "columns name the first ones")
      ->type_name("NAME,...")
      ->group("Data columns");
  o.resample_opt = cmd->add_option("--resample", o.resample,
                                   "Interpolate every column linearly onto a uniform time grid of step DT s "
                                   "(default: the median step), for irregularly sampled data; repeated time stamps "
                                   "are merged. The jitter and the samples made are reported")
                       ->expected(0, 1)
                       ->type_name("[DT]")
                       ->group("Data columns");
  cmd->add_option("--max-gap", o.max_gap,
                  "Longest time gap (s) --resample may interpolate over (default: 10 median steps; a longer gap "
                  "is an error naming its rows)")
      ->check(CLI::PositiveNumber)
      ->type_name("S")
      ->needs(o.resample_opt)
      ->group("Data columns");
  cmd->add_flag("--drop-invalid", o.drop_invalid, "Drop CSV rows with empty or NaN cells instead of refusing the file")
      ->group("Data columns");
}

void add_data_options(CLI::App* cmd, DataOptions& o, const std::string& default_axis) {
  o.axis = default_axis;
  cmd->add_option("--time", o.time, "Time column or variable (s)")->capture_default_str()->group("Data columns");
  o.position_opt = cmd->add_option("--position", o.position, "Position column, or an expression of columns (m or rad)")->capture_default_str()->group("Data columns");
  o.velocity_opt = cmd->add_option("--velocity", o.velocity, "Velocity column, or an expression of columns (m/s or rad/s)")->capture_default_str()->group("Data columns");
  o.current_opt = cmd->add_option("--current", o.current, "Motor current column or expression (A), turned into torque by --kt")
                      ->capture_default_str()
                      ->group("Data columns");
  o.force_opt = cmd->add_option("--force", o.force, "Applied force or torque column (N or N m), or an expression of columns after --scale, e.g. 'TorqueCur1 - Torque1'")->capture_default_str()->group("Data columns");
  o.input_opt = cmd->add_option("--input", o.input, "Drive command column or expression, turned into force by --gain")
                    ->capture_default_str()
                    ->group("Data columns");
  cmd->add_option("--gain", o.gain, "Force per unit of --input: a number or a scalar variable of the file (e.g. gtau)")
      ->group("Data columns");
  cmd->add_option("--kt", o.kt, "Torque constant (N m/A): a number or a scalar variable of the file")->group("Data columns");
  cmd->add_option("--scale", o.scales, "NAME=FACTOR: multiply column NAME by FACTOR to get SI units (repeatable)")
      ->group("Data columns");
  cmd->add_option("--axis", o.axis, "linear (N, m/s, kg) or rotary (N m, rad/s, kg m^2): the units reported")
      ->check(CLI::IsMember({"linear", "rotary"}))
      ->capture_default_str()
      ->group("Data columns");
  add_read_options(cmd, o.read);
}

namespace {

// The file as read (CSV header rule, --names, --drop-invalid), not resampled.
Dataset read_data(const std::string& path, const ReadOptions& o) {
  CsvOptions csv;
  csv.drop_invalid = o.drop_invalid;
  csv.header = CsvHeader::detect;
  if (!o.names.empty()) csv.names = split_names(o.names);
  csv.names_option = "--names";
  csv.drop_invalid_option = "--drop-invalid";
  csv.defer_invalid = true;  // only the columns a command uses are checked
  Dataset d = load_dataset(path, csv, parse_data_format(o.format, "--format"));
  if (!o.names.empty() && d.lines.empty()) {
    throw InputError(errc::option_conflict,
                     d.where() + "--names names the columns of a CSV file; a MAT file's variables have their "
                                 "own names: " + d.describe_contents(),
                     {.file = d.file, .option = "--names"});
  }
  return d;
}

// --resample onto a uniform grid of the time column, when asked (dt checked by the caller).
void resample_if_asked(Dataset& d, const ReadOptions& o, const std::string& time_column, double dt) {
  if (o.resample_given()) {
    select_column(d, time_column, "--time");  // a missing time column is named with its option
    ResampleOptions r;
    r.dt = dt;
    r.max_gap = o.max_gap;
    r.dt_name = "--resample";
    r.max_gap_name = "--max-gap";
    resample_dataset(d, time_column, r);
  }
}

}  // namespace

Dataset load_data(const std::string& path, const ReadOptions& o, const std::string& time_column) {
  const double dt = o.resample_given() ? parse_step(o.resample) : 0.0;  // a bad DT is named before the file is read
  Dataset d = read_data(path, o);
  resample_if_asked(d, o, time_column, dt);
  return d;
}

Dataset load_data(const std::string& path, const DataOptions& o) {
  // The --scale factors first, then --resample: a time column in ms with --scale TIME=0.001 is
  // resampled in seconds, so --resample DT, --max-gap and the resampling report are in s.
  const double dt = o.read.resample_given() ? parse_step(o.read.resample) : 0.0;
  Dataset d = read_data(path, o.read);
  apply_scales(d, o.scales, "--scale");
  resample_if_asked(d, o.read, o.time, dt);
  return d;
}

void stamp(Result& r, const Dataset& d) {
  r.data_file = d.file;
  r.data_sha256 = d.sha256;
  note_data(r, d);
}

void note_data(Result& r, const Dataset& d) {
  if (d.resampling) {
    const ResampleReport& s = *d.resampling;
    r.diagnostics.groups["resampling"] = {{"dt_min", s.dt_min},
                                          {"dt_median", s.dt_median},
                                          {"dt_max", s.dt_max},
                                          {"dt", s.dt},
                                          {"max_gap", s.max_gap},
                                          {"samples_in", static_cast<double>(s.samples_in)},
                                          {"samples_out", static_cast<double>(s.samples_out)},
                                          {"merged", static_cast<double>(s.merged)}};
  }
  r.diagnostics.warnings.insert(r.diagnostics.warnings.end(), d.warnings.begin(), d.warnings.end());
}

std::string data_note(const Dataset& d) {
  std::string out;
  if (d.resampling) {
    const ResampleReport& s = *d.resampling;
    out += "resampled    " + std::to_string(s.samples_in) + " samples (steps " + format_number(s.dt_min) + " to " + format_number(s.dt_max) +
           " s, median " + format_number(s.dt_median) + " s) onto " + std::to_string(s.samples_out) + " at dt " + format_number(s.dt) + " s\n";
  }
  for (const auto& w : d.warnings) out += "warning: " + w + "\n";
  return out;
}

void require_finite(const Dataset& d, const Eigen::VectorXd& x, const std::string& column) {
  for (Eigen::Index k = 0; k < x.size(); ++k)
    if (!std::isfinite(x[k]))
      throw InputError(errc::data_not_finite,
                       d.where() + d.row_label(k) + ", column '" + column + "': value is not a finite number",
                       {.file = d.file,
                        .row = !d.resampling && static_cast<std::size_t>(k) < d.lines.size() ? d.lines[static_cast<std::size_t>(k)]
                                                                                             : static_cast<std::size_t>(k + 1),
                        .column = column});
}

std::string data_option_unit(const std::string& flag, Axis axis) {
  const bool rotary = axis == Axis::rotary;
  if (flag == "--time" || flag == "--resample" || flag == "--max-gap") return "s";
  if (flag == "--position") return rotary ? "rad" : "m";
  if (flag == "--velocity") return rotary ? "rad/s" : "m/s";
  if (flag == "--force") return rotary ? "N m" : "N";
  if (flag == "--current") return "A";
  if (flag == "--kt") return "N m/A";
  if (flag == "--gain") return rotary ? "N m per unit of --input" : "N per unit of --input";
  return "";
}

Eigen::VectorXd time_column(const Dataset& d, const DataOptions& o) {
  o.columns_read["--time"] = o.time;
  const Eigen::VectorXd& t = select_column(d, o.time, "--time");
  try {
    check_time(d, t);
  } catch (const SamplingError& e) {
    const ErrorFields fields{.file = d.file, .column = o.time, .option = "--time"};
    if (e.problem() == SamplingProblem::irregular)
      throw InputError(errc::data_time,
                       std::string(e.what()) +
                           "; --resample [DT] interpolates every column onto a uniform grid (default DT: the median step)",
                       fields);
    if (e.problem() == SamplingProblem::repeated)
      throw InputError(errc::data_time,
                       std::string(e.what()) + "; --resample merges repeated time stamps (and puts the record on a uniform grid)",
                       fields);
    throw InputError(errc::data_time, e.what(), fields);
  }
  return t;
}

Eigen::VectorXd force_column(const Dataset& d, const DataOptions& o) {
  const bool force_given = o.force_opt && o.force_opt->count() > 0;
  const bool input_given = (o.input_opt && o.input_opt->count() > 0) || !o.gain.empty();
  const bool current_given = (o.current_opt && o.current_opt->count() > 0) || !o.kt.empty();
  if (force_given || (!input_given && !current_given && d.has_column(o.force))) {
    o.columns_read["--force"] = o.force;
    return finite_signal(d, o.force, "--force");
  }
  if (input_given || (!current_given && d.has_column(o.input))) {
    o.columns_read["--input"] = o.input;
    if (o.gain.empty())
      throw InputError(errc::option_invalid,
                       d.where() + "--gain is needed to turn the drive input '" + o.input +
                           "' into force (a number, N per unit of input, or a scalar variable of the file)",
                       {.file = d.file, .column = o.input, .option = "--gain"});
    return resolve_constant(d, o.gain, "--gain") * finite_signal(d, o.input, "--input");
  }
  if (d.has_column(o.current) || current_given) {
    o.columns_read["--current"] = o.current;
    if (o.kt.empty())
      throw InputError(errc::option_invalid,
                       d.where() + "--kt is needed to turn the current '" + o.current +
                           "' into torque (a number in N m/A, or a scalar variable of the file)",
                       {.file = d.file, .column = o.current, .option = "--kt"});
    return resolve_constant(d, o.kt, "--kt") * finite_signal(d, o.current, "--current");
  }
  throw InputError(errc::data_column_missing,
                   d.where() + "no applied force: expected a column '" + o.force + "' (--force), '" + o.input +
                       "' with --gain (--input), or '" + o.current + "' with --kt (--current); the file has columns: " +
                       d.describe_contents(),
                   {.file = d.file, .column = o.force, .option = "--force"});
}

Eigen::VectorXd velocity_column(const Dataset& d, const DataOptions& o) {
  o.columns_read["--velocity"] = o.velocity;
  return finite_signal(d, o.velocity, "--velocity");
}

Eigen::VectorXd position_column(const Dataset& d, const DataOptions& o) {
  o.columns_read["--position"] = o.position;
  return finite_signal(d, o.position, "--position");
}

}  // namespace frictionlab::cli
