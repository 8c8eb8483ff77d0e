#include "frictionlab/signal/segments.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace frictionlab {
namespace {

void check_lengths(const Eigen::VectorXd& time, const Eigen::VectorXd& velocity, const char* who) {
  if (time.size() != velocity.size()) {
    std::ostringstream msg;
    msg << who << ": time has " << time.size() << " samples but velocity has " << velocity.size()
        << "; expected equal lengths";
    throw std::invalid_argument(msg.str());
  }
}

void check_threshold(double threshold, const char* who) {
  if (!(threshold >= 0.0) || !std::isfinite(threshold)) {
    std::ostringstream msg;
    msg << who << ": velocity threshold = " << threshold << " m/s (rad/s) must be a finite number >= 0";
    throw std::invalid_argument(msg.str());
  }
}

IndexRange make_range(const Eigen::VectorXd& time, std::size_t begin, std::size_t end) {
  return {begin, end, time(static_cast<Eigen::Index>(begin)), time(static_cast<Eigen::Index>(end - 1))};
}

// Maximal runs where moving(k) has the wanted value, lasting at least min_duration.
std::vector<IndexRange> runs(const Eigen::VectorXd& time, const Eigen::VectorXd& velocity, double threshold,
                             double min_duration, bool moving) {
  std::vector<IndexRange> out;
  const auto n = static_cast<std::size_t>(velocity.size());
  std::size_t k = 0;
  while (k < n) {
    const auto is = [&](std::size_t i) { return (std::abs(velocity(static_cast<Eigen::Index>(i))) > threshold) == moving; };
    if (!is(k)) {
      ++k;
      continue;
    }
    std::size_t end = k;
    while (end < n && is(end)) ++end;
    IndexRange r = make_range(time, k, end);
    if (r.duration() >= min_duration) out.push_back(r);
    k = end;
  }
  return out;
}

}  // namespace

std::vector<IndexRange> steady_segments(const Eigen::VectorXd& time, const Eigen::VectorXd& velocity,
                                        const SteadySegmentOptions& options) {
  check_lengths(time, velocity, "steady_segments");
  if (!(options.velocity_tolerance >= 0.0) || !(options.relative_tolerance >= 0.0) ||
      !(options.velocity_tolerance > 0.0 || options.relative_tolerance > 0.0)) {
    std::ostringstream msg;
    msg << "steady_segments: velocity_tolerance = " << options.velocity_tolerance
        << " m/s (rad/s) and relative_tolerance = " << options.relative_tolerance
        << " must be >= 0, and one of them positive";
    throw std::invalid_argument(msg.str());
  }
  const auto n = static_cast<std::size_t>(velocity.size());
  std::vector<IndexRange> out;
  // Sliding window [i, j) with monotonic deques of its maximum and minimum: O(N).
  std::deque<std::size_t> maxq, minq;
  std::size_t i = 0;
  double sum = 0;  // of v over the window [i, j]
  auto v = [&](std::size_t k) { return velocity(static_cast<Eigen::Index>(k)); };
  auto too_wide = [&](std::size_t j) {
    const double mean = sum / static_cast<double>(j - i + 1);
    const double band = 2.0 * std::max(options.velocity_tolerance, options.relative_tolerance * std::abs(mean));
    return v(maxq.front()) - v(minq.front()) > band;
  };
  auto keep = [&](std::size_t begin, std::size_t end) {
    if (end <= begin) return false;
    IndexRange r = make_range(time, begin, end);
    if (r.duration() < options.min_duration) return false;
    const double mean = velocity.segment(static_cast<Eigen::Index>(begin), static_cast<Eigen::Index>(end - begin)).mean();
    if (std::abs(mean) >= options.min_speed) out.push_back(r);
    return true;
  };
  for (std::size_t j = 0; j < n; ++j) {
    while (!maxq.empty() && v(maxq.back()) <= v(j)) maxq.pop_back();
    maxq.push_back(j);
    while (!minq.empty() && v(minq.back()) >= v(j)) minq.pop_back();
    minq.push_back(j);
    sum += v(j);
    if (!too_wide(j)) continue;
    // Sample j breaks the band of [i, j).
    if (keep(i, j)) {
      i = j;
      sum = v(j);
      maxq.assign(1, j);
      minq.assign(1, j);
      continue;
    }
    while (too_wide(j)) {
      sum -= v(i);
      ++i;
      while (maxq.front() < i) maxq.pop_front();
      while (minq.front() < i) minq.pop_front();
    }
  }
  keep(i, n);
  return out;
}

double difference_noise_std(const Eigen::VectorXd& x) {
  if (x.size() < 2) return 0.0;
  std::vector<double> d(static_cast<std::size_t>(x.size() - 1));
  for (Eigen::Index k = 0; k + 1 < x.size(); ++k) d[static_cast<std::size_t>(k)] = std::abs(x(k + 1) - x(k));
  auto mid = d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2);
  std::nth_element(d.begin(), mid, d.end());
  constexpr double kMadToStd = 1.4826;  // std / median absolute deviation of a Gaussian
  return kMadToStd * *mid / std::sqrt(2.0);
}

Eigen::VectorXd moving_average(const Eigen::VectorXd& x, Eigen::Index window) {
  if (window < 1) throw std::invalid_argument("moving_average: window = " + std::to_string(window) + " samples must be >= 1");
  const Eigen::Index n = x.size(), half = window / 2;
  Eigen::VectorXd c(n + 1);  // prefix sums
  c(0) = 0;
  for (Eigen::Index k = 0; k < n; ++k) c(k + 1) = c(k) + x(k);
  Eigen::VectorXd out(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index b = std::max<Eigen::Index>(0, k - half), e = std::min(n, k - half + window);
    out(k) = (c(e) - c(b)) / static_cast<double>(e - b);
  }
  return out;
}

std::optional<std::size_t> motion_onset(const Eigen::VectorXd& velocity, double threshold, std::size_t start) {
  check_threshold(threshold, "motion_onset");
  for (auto k = static_cast<Eigen::Index>(start); k < velocity.size(); ++k) {
    if (std::abs(velocity(k)) > threshold) return static_cast<std::size_t>(k);
  }
  return std::nullopt;
}

std::vector<IndexRange> standstill_intervals(const Eigen::VectorXd& time, const Eigen::VectorXd& velocity,
                                             double threshold, double min_duration) {
  check_lengths(time, velocity, "standstill_intervals");
  check_threshold(threshold, "standstill_intervals");
  return runs(time, velocity, threshold, min_duration, false);
}

std::vector<IndexRange> motion_intervals(const Eigen::VectorXd& time, const Eigen::VectorXd& velocity,
                                         double threshold, double min_duration) {
  check_lengths(time, velocity, "motion_intervals");
  check_threshold(threshold, "motion_intervals");
  return runs(time, velocity, threshold, min_duration, true);
}

}  // namespace frictionlab
