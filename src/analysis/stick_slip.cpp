#include "frictionlab/analysis/stick_slip.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "frictionlab/format.hpp"

namespace frictionlab {

StickSlipResult detect_stick_slip(std::span<const double> t, std::span<const double> v, std::span<const double> force,
                                  const StickSlipOptions& options) {
  if (t.size() != v.size() || (!force.empty() && force.size() != t.size()))
    throw std::invalid_argument("stick-slip: time, velocity and force must have equal lengths, got " +
                                std::to_string(t.size()) + ", " + std::to_string(v.size()) + ", " +
                                std::to_string(force.size()));
  if (t.size() < 3) throw std::invalid_argument("stick-slip: need at least 3 samples, got " + std::to_string(t.size()));
  for (std::size_t i = 1; i < t.size(); ++i)
    if (!(t[i] > t[i - 1]))
      throw std::invalid_argument("stick-slip: time must increase strictly; sample " + std::to_string(i + 1) +
                                  " has t = " + format_number(t[i]) + " after " + format_number(t[i - 1]));
  if (!(options.velocity_threshold >= 0))
    throw std::invalid_argument("stick-slip: velocity_threshold = " + std::to_string(options.velocity_threshold) +
                                " must be >= 0 (m/s or rad/s; 0 = 1 % of the largest |v|)");
  StickSlipResult r;
  double vmax = 0;
  for (double x : v) vmax = std::max(vmax, std::abs(x));
  std::size_t zeros = 0;
  for (double x : v) zeros += x == 0.0 ? 1 : 0;
  const bool exact = static_cast<double>(zeros) >= 0.05 * static_cast<double>(v.size());
  r.velocity_threshold = options.velocity_threshold > 0 ? options.velocity_threshold : (exact ? 0.0 : 0.01 * vmax);
  const double thr = r.velocity_threshold;
  const std::size_t n = t.size();

  // Runs of slipping samples [i0, i1).
  struct Run {
    std::size_t i0, i1;
  };
  std::vector<Run> runs;
  for (std::size_t i = 0; i < n;) {
    if (std::abs(v[i]) > thr) {
      std::size_t j = i;
      while (j < n && std::abs(v[j]) > thr) ++j;
      runs.push_back({i, j});
      i = j;
    } else {
      ++i;
    }
  }
  // Merge short slips into the stick around them.
  if (options.min_slip_duration > 0) {
    std::erase_if(runs, [&](const Run& run) {
      return run.i1 < n && t[run.i1 - 1] - t[run.i0] < options.min_slip_duration;
    });
  }
  std::size_t cursor = 0;
  for (const Run& run : runs) {
    if (run.i0 > cursor) r.stick.push_back({t[cursor], t[run.i0 - 1]});
    r.slip.push_back({t[run.i0], t[run.i1 - 1]});
    for (std::size_t i = run.i0; i < run.i1; ++i) r.peak_slip_velocity = std::max(r.peak_slip_velocity, std::abs(v[i]));
    cursor = run.i1;
  }
  if (cursor < n) r.stick.push_back({t[cursor], t[n - 1]});

  // Period from slip starts that follow a stick.
  std::vector<double> starts;
  for (const Run& run : runs)
    if (run.i0 > 0) starts.push_back(t[run.i0]);
  if (runs.empty()) {
    r.message = "no slip found: velocity never exceeded " + format_number(thr) +
                " m/s (rad/s on a rotary axis; the stuck threshold" +
                (options.velocity_threshold > 0 ? std::string(" given") : std::string(", 1 % of the largest |v|")) +
                ", largest |v| = " + format_number(vmax) + ")";
  } else if (starts.empty()) {
    r.message = "no slip from stick found: the record slides from its start (|v| above " + format_number(thr) +
                " m/s or rad/s) and never sticks then slips again";
  }
  if (starts.size() < 2) {
    r.period = std::numeric_limits<double>::quiet_NaN();
  } else {
    const std::size_t first = starts.size() >= 3 ? 1 : 0;
    r.period = (starts.back() - starts[first]) / static_cast<double>(starts.size() - 1 - first);
  }
  double dur = 0;
  int complete = 0;
  for (const Run& run : runs) {
    if (run.i0 == 0 || run.i1 >= n) continue;
    dur += 0.5 * (t[run.i1] + t[run.i1 - 1]) - 0.5 * (t[run.i0] + t[run.i0 - 1]);  // mid-sample edges
    ++complete;
    if (!force.empty()) {
      // The larger of the last two stuck samples: a sample taken at the very instant of the
      // switch may already show the sliding level.
      double fb = force[run.i0 - 1];
      if (run.i0 >= 2 && std::abs(force[run.i0 - 2]) > std::abs(fb)) fb = force[run.i0 - 2];
      r.breakaway_force.push_back(fb);
      r.restick_force.push_back(force[run.i1]);
    }
  }
  r.mean_slip_duration = complete ? dur / complete : std::numeric_limits<double>::quiet_NaN();
  if (!r.breakaway_force.empty()) {
    double b = 0, s = 0;
    for (std::size_t k = 0; k < r.breakaway_force.size(); ++k) {
      b += r.breakaway_force[k];
      s += r.restick_force[k];
    }
    const double m = static_cast<double>(r.breakaway_force.size());
    r.mean_breakaway_force = b / m;
    r.mean_restick_force = s / m;
    r.mean_force_drop = (b - s) / m;
  }
  return r;
}

}  // namespace frictionlab
