#include "data_options.hpp"

#include <cmath>

#include "frictionlab/io/columns.hpp"
#include "frictionlab/io/load.hpp"

namespace frictionlab::cli {

void add_data_options(CLI::App* cmd, DataOptions& o, const std::string& default_axis) {
  o.axis = default_axis;
  cmd->add_option("--time", o.time, "Time column or variable (s)")->capture_default_str()->group("Data columns");
  o.position_opt = cmd->add_option("--position", o.position, "Position column (m or rad)")->capture_default_str()->group("Data columns");
  o.velocity_opt = cmd->add_option("--velocity", o.velocity, "Velocity column (m/s or rad/s)")->capture_default_str()->group("Data columns");
  o.current_opt = cmd->add_option("--current", o.current, "Motor current column (A), turned into torque by --kt")
                      ->capture_default_str()
                      ->group("Data columns");
  o.force_opt = cmd->add_option("--force", o.force, "Applied force or torque column (N or N m)")->capture_default_str()->group("Data columns");
  o.input_opt = cmd->add_option("--input", o.input, "Drive command column, turned into force by --gain")
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
  cmd->add_flag("--drop-invalid", o.drop_invalid, "Drop CSV rows with empty or NaN cells instead of refusing the file")
      ->group("Data columns");
}

Dataset load_data(const std::string& path, const DataOptions& o) {
  CsvOptions csv;
  csv.drop_invalid = o.drop_invalid;
  Dataset d = load_dataset(path, csv);
  apply_scales(d, o.scales);
  return d;
}

void require_finite(const Dataset& d, const Eigen::VectorXd& x, const std::string& column) {
  for (Eigen::Index k = 0; k < x.size(); ++k)
    if (!std::isfinite(x[k]))
      throw std::invalid_argument(d.where() + d.row_label(k) + ", column '" + column + "': value is not a finite number");
}

Eigen::VectorXd time_column(const Dataset& d, const DataOptions& o) {
  const Eigen::VectorXd& t = select_column(d, o.time, "--time");
  check_time(d, t);
  return t;
}

namespace {
Eigen::VectorXd checked(const Dataset& d, const std::string& name, const std::string& role) {
  Eigen::VectorXd x = select_column(d, name, role);
  require_finite(d, x, name);
  return x;
}
}  // namespace

Eigen::VectorXd force_column(const Dataset& d, const DataOptions& o) {
  const bool force_given = o.force_opt && o.force_opt->count() > 0;
  const bool input_given = (o.input_opt && o.input_opt->count() > 0) || !o.gain.empty();
  const bool current_given = (o.current_opt && o.current_opt->count() > 0) || !o.kt.empty();
  if (force_given || (!input_given && !current_given && d.has_column(o.force))) return checked(d, o.force, "--force");
  if (input_given || (!current_given && d.has_column(o.input))) {
    if (o.gain.empty())
      throw std::invalid_argument(d.where() + "--gain is needed to turn the drive input '" + o.input +
                                  "' into force (a number, N per unit of input, or a scalar variable of the file)");
    return resolve_constant(d, o.gain, "--gain") * checked(d, o.input, "--input");
  }
  if (d.has_column(o.current) || current_given) {
    if (o.kt.empty())
      throw std::invalid_argument(d.where() + "--kt is needed to turn the current '" + o.current +
                                  "' into torque (a number in N m/A, or a scalar variable of the file)");
    return resolve_constant(d, o.kt, "--kt") * checked(d, o.current, "--current");
  }
  throw std::invalid_argument(d.where() + "no applied force: expected a column '" + o.force + "' (--force), '" + o.input +
                              "' with --gain (--input), or '" + o.current + "' with --kt (--current); the file has columns: " +
                              d.describe_contents());
}

Eigen::VectorXd velocity_column(const Dataset& d, const DataOptions& o) { return checked(d, o.velocity, "--velocity"); }

Eigen::VectorXd position_column(const Dataset& d, const DataOptions& o) { return checked(d, o.position, "--position"); }

}  // namespace frictionlab::cli
