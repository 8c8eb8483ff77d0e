#include "frictionlab/io/columns.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace frictionlab {
namespace {

bool parse_number(const std::string& text, double& value) {
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  if (begin != end && *begin == '+') ++begin;
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  return ec == std::errc() && ptr == end && begin != end && std::isfinite(value);
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
    throw std::invalid_argument(data.where() + "no column '" + name + "'" + (role.empty() ? "" : " (" + role + ")") +
                                "; the file has columns: " + data.describe_contents());
  }
  return data.column(name);
}

double resolve_constant(const Dataset& data, const std::string& text, const std::string& parameter) {
  double value = 0;
  if (parse_number(text, value)) return value;
  const auto it = data.scalars.find(text);
  if (it != data.scalars.end()) {
    if (!std::isfinite(it->second)) {
      throw std::invalid_argument(data.where() + parameter + " = '" + text + "': the scalar is not a finite number");
    }
    return it->second;
  }
  throw std::invalid_argument(data.where() + parameter + " = '" + text +
                              "': expected a number or the name of a scalar in the file; scalars: " + scalar_list(data));
}

ScaleFactor parse_scale(const std::string& spec) {
  const auto eq = spec.find('=');
  ScaleFactor s;
  if (eq == std::string::npos || eq == 0 || !parse_number(spec.substr(eq + 1), s.factor)) {
    throw std::invalid_argument("--scale '" + spec + "': expected NAME=FACTOR with a finite number, e.g. position=1e-3");
  }
  s.column = spec.substr(0, eq);
  return s;
}

void apply_scales(Dataset& data, const std::vector<std::string>& specs) {
  for (const auto& spec : specs) {
    const ScaleFactor s = parse_scale(spec);
    if (!data.has_column(s.column)) {
      throw std::invalid_argument(data.where() + "--scale '" + spec + "': no column '" + s.column +
                                  "'; the file has columns: " + data.describe_contents());
    }
    data.column(s.column) *= s.factor;
  }
}

double check_time(const Dataset& data, const Eigen::VectorXd& time, const TimeCheckOptions& options) {
  const Eigen::Index n = time.size();
  if (n < 2) {
    throw std::invalid_argument(data.where() + "time has " + std::to_string(n) + " samples; expected at least 2");
  }
  std::ostringstream msg;
  msg.precision(12);
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!std::isfinite(time(k))) {
      msg << data.where() << data.row_label(k) << ": time = " << time(k) << " s is not a finite number";
      throw std::invalid_argument(msg.str());
    }
    if (k > 0 && !(time(k) > time(k - 1))) {
      msg << data.where() << data.row_label(k) << ": time " << time(k) << " s is not greater than the previous "
          << time(k - 1) << " s; expected strictly increasing time";
      throw std::invalid_argument(msg.str());
    }
  }
  const double dt = (time(n - 1) - time(0)) / static_cast<double>(n - 1);
  if (options.require_regular) {
    // Compare with the median step, so one gap is reported where it is, not at every other step.
    std::vector<double> steps(static_cast<std::size_t>(n - 1));
    for (Eigen::Index k = 1; k < n; ++k) steps[static_cast<std::size_t>(k - 1)] = time(k) - time(k - 1);
    auto mid = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
    std::nth_element(steps.begin(), mid, steps.end());
    const double median = *mid;
    for (Eigen::Index k = 1; k < n; ++k) {
      const double step = time(k) - time(k - 1);
      if (std::abs(step - median) > options.regular_tolerance * median) {
        msg << data.where() << data.row_label(k) << ": time step " << step << " s differs from the median step " << median
            << " s by more than " << 100 * options.regular_tolerance << " %; expected regularly sampled data";
        throw std::invalid_argument(msg.str());
      }
    }
  }
  return dt;
}

}  // namespace frictionlab
