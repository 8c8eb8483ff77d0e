#include "frictionlab/io/columns.hpp"
#include "frictionlab/error.hpp"
#include "io/error_place.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "frictionlab/models/parameter.hpp"

namespace frictionlab {
namespace {

using detail::option_of;
using detail::row_number;

bool parse_number(const std::string& text, double& value) {
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  if (begin != end && *begin == '+') ++begin;
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  return ec == std::errc() && ptr == end && begin != end && std::isfinite(value);
}

std::string format_double(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string scalar_list(const Dataset& data) {
  if (data.scalars.empty()) return "(none)";
  std::string out;
  for (const auto& [name, value] : data.scalars) out += (out.empty() ? "" : ", ") + name;
  return out;
}

}  // namespace

const Eigen::VectorXd& select_column(const Dataset& data, const std::string& name, const std::string& role) {
  if (!data.has_column(name)) {
    throw InputError(errc::data_column_missing, data.missing_column_message(name, role),
                     {.file = data.file, .column = name, .option = option_of(role)});
  }
  // A bad cell the reader left to the command that uses the column (CsvOptions::defer_invalid).
  if (const auto bad = data.invalid_cells.find(name); bad != data.invalid_cells.end()) throw bad->second;
  return data.column(name);
}

const Eigen::VectorXd& finite_column(const Dataset& data, const std::string& name, const std::string& role) {
  const Eigen::VectorXd& x = select_column(data, name, role);
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    if (!std::isfinite(x(k))) {
      throw InputError(errc::data_not_finite,
                       data.where() + data.row_label(k) + ", column '" + name + "': value is not a finite number",
                       {.file = data.file, .row = row_number(data, k), .column = name, .option = option_of(role),
                        .value = format_double(x(k))});
    }
  }
  return x;
}

double resolve_constant(const Dataset& data, const std::string& text, const std::string& parameter) {
  double value = 0;
  if (parse_number(text, value)) return value;
  const auto it = data.scalars.find(text);
  if (it != data.scalars.end()) {
    if (!std::isfinite(it->second)) {
      throw InputError(errc::data_not_finite, data.where() + parameter + " = '" + text + "': the scalar is not a finite number",
                       {.file = data.file, .column = text, .option = parameter, .value = text});
    }
    return it->second;
  }
  throw InputError(errc::option_invalid,
                   data.where() + parameter + " = '" + text +
                       "': expected a number or the name of a scalar in the file; scalars: " + scalar_list(data),
                   {.file = data.file, .option = parameter, .value = text});
}

ScaleFactor parse_scale(const std::string& spec, const std::string& option) {
  const auto eq = spec.find('=');
  ScaleFactor s;
  if (eq == std::string::npos || eq == 0 || !parse_number(spec.substr(eq + 1), s.factor)) {
    throw InputError(errc::option_invalid,
                     option + " '" + spec + "': expected NAME=FACTOR with a finite number, e.g. position=1e-3",
                     {.option = option, .value = spec});
  }
  s.column = spec.substr(0, eq);
  return s;
}

void apply_scales(Dataset& data, const std::vector<std::string>& specs, const std::string& option) {
  for (const auto& spec : specs) {
    const ScaleFactor s = parse_scale(spec, option);
    if (!data.has_column(s.column)) {
      throw InputError(errc::data_column_missing, data.missing_column_message(s.column, option + " '" + spec + "'"),
                       {.file = data.file, .column = s.column, .option = option, .value = spec});
    }
    data.column(s.column) *= s.factor;
  }
}

double check_time(const Dataset& data, const Eigen::VectorXd& time, const TimeCheckOptions& options) {
  RegularSamplingCheck c;
  c.tolerance = options.regular_tolerance;
  c.require_regular = options.require_regular;
  c.where = data.where();
  c.row_label = [&data](Eigen::Index k) { return data.row_label(k); };
  return check_regular_sampling(time, c);
}

void resample_dataset(Dataset& data, const std::string& time_column, ResampleOptions options) {
  const Eigen::VectorXd time = select_column(data, time_column, "time");
  options.where = data.where();
  options.row_label = [&data](Eigen::Index k) { return data.row_label(k); };
  const UniformResampler resampler(time, options);
  // The resampled copy must fit in memory beside the original: refuse, rather than fail to allocate.
  constexpr double kMaxBytes = 8e9;
  const double bytes = 8.0 * static_cast<double>(resampler.report().samples_out) * static_cast<double>(data.column_names().size());
  if (bytes > kMaxBytes) {
    throw InputError(errc::option_out_of_range, data.where() + options.dt_name + " = " + detail::format_value(resampler.report().dt, 6) +
                                " s: " + std::to_string(resampler.report().samples_out) + " samples x " +
                                std::to_string(data.column_names().size()) + " columns would take " +
                                detail::format_value(bytes / 1e9, 3) + " GB; expected at most 8 GB (a larger step)",
                     {.file = data.file, .option = options.dt_name});
  }
  // Every column is interpolated before any is replaced, so a bad value leaves `data` unchanged.
  std::vector<std::pair<std::string, Eigen::VectorXd>> out;
  for (const auto& name : data.column_names()) {
    if (name == time_column) out.emplace_back(name, resampler.time());
    else if (data.invalid_cells.count(name) != 0)  // unusable either way: its use refuses it, naming the file's line
      out.emplace_back(name, Eigen::VectorXd::Constant(resampler.time().size(), std::numeric_limits<double>::quiet_NaN()));
    else out.emplace_back(name, resampler.apply(data.column(name), name));
  }
  Dataset resampled;
  resampled.file = data.file;
  resampled.sha256 = data.sha256;
  resampled.scalars = data.scalars;
  resampled.header_row = data.header_row;
  resampled.names_option = data.names_option;
  resampled.unusable = data.unusable;
  resampled.warnings = data.warnings;
  resampled.invalid_cells = data.invalid_cells;
  for (auto& [name, values] : out) resampled.add_column(name, std::move(values));
  resampled.resampling = resampler.report();
  for (const auto& w : resampler.report().warnings) resampled.warnings.push_back(data.where() + w);
  data = std::move(resampled);
}

}  // namespace frictionlab
