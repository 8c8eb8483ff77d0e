// The one regular-sampling check and the uniform resampler: see signal/sampling.hpp.
#include "frictionlab/signal/sampling.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "frictionlab/models/parameter.hpp"
#include "all_finite.hpp"

namespace frictionlab {
namespace {

// Time stamps are printed with 10 significant digits (two stamps 1 ms apart at t = 1000 s stay
// distinct), steps with 6 (the jitter, not the clock, is what a step message is about).
std::string stamp(double t) { return detail::format_value(t, 10); }
std::string step(double dt) { return detail::format_value(dt, 6); }

std::string label_of(const RowLabeller& labeller, Eigen::Index k) { return labeller ? labeller(k) : sample_label(k); }

// The k-th smallest of x[0..n) (0-based: the value std::nth_element puts at x + k); x is not
// changed (the values between the pivots are selected among in a copy of them). Why not std::nth_element alone: it was a tenth of an EMPS
// identification. Two pivots from a sample of x bracket rank k (Floyd and Rivest's selection);
// one branch-free pass counts the values below and above them and keeps those between, and
// only those are selected among. A clock's steps repeat a few values, so the pivots are often
// one value and the answer is that value, with no selection at all. nullopt when the bracket
// missed rank k: the caller selects over all of x.
std::optional<double> kth_bracketed(const double* x, Eigen::Index n, Eigen::Index k) {
  constexpr Eigen::Index kSample = 1024, kMargin = 48;  // margin ~1.5 sqrt(sample): misses are rare
  if (n < 4 * kSample) return std::nullopt;
  std::array<double, kSample> sample;
  for (Eigen::Index i = 0; i < kSample; ++i) sample[static_cast<std::size_t>(i)] = x[i * (n / kSample)];
  const Eigen::Index r = k * kSample / n;
  const auto at = [&](Eigen::Index rank) {
    const auto i = static_cast<std::size_t>(std::clamp<Eigen::Index>(rank, 0, kSample - 1));
    std::nth_element(sample.begin(), sample.begin() + static_cast<std::ptrdiff_t>(i), sample.end());
    return sample[i];
  };
  const double lo = at(r - kMargin), hi = at(r + kMargin);
  // Counted first (a loop the compiler vectorises); the values between are gathered only when
  // the pivots differ. A NaN counts in neither: the value returned is then some step.
  const Eigen::Map<const Eigen::ArrayXd> a(x, n);
  const Eigen::Index below = (a < lo).count(), between = (a >= lo && a <= hi).count();
  if (k < below || k >= below + between) return std::nullopt;
  if (lo == hi) return lo;
  std::vector<double> work(static_cast<std::size_t>(n));
  Eigen::Index kept = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double v = x[i];
    work[static_cast<std::size_t>(kept)] = v;
    kept += (v >= lo) & (v <= hi);
  }
  std::nth_element(work.begin(), work.begin() + (k - below), work.begin() + kept);
  return work[static_cast<std::size_t>(k - below)];
}

}  // namespace

std::string sample_label(Eigen::Index k) { return "sample " + std::to_string(k + 1); }

TimeSteps time_steps(const Eigen::VectorXd& t) {
  TimeSteps s;
  const Eigen::Index n = t.size();
  if (n < 2) return s;
  Eigen::VectorXd steps = t.tail(n - 1) - t.head(n - 1);
  s.min = steps.minCoeff();
  s.max = steps.maxCoeff();
  s.mean = (t(n - 1) - t(0)) / static_cast<double>(n - 1);
  const Eigen::Index mid = (n - 1) / 2;
  const std::optional<double> fast = kth_bracketed(steps.data(), n - 1, mid);
  if (fast) {
    s.median = *fast;
  } else {  // any values (a NaN's place is unspecified either way)
    std::nth_element(steps.data(), steps.data() + mid, steps.data() + (n - 1));
    s.median = steps(mid);
  }
  return s;
}

double check_regular_sampling(const Eigen::VectorXd& t, const RegularSamplingCheck& c) {
  const Eigen::Index n = t.size();
  const Eigen::Index needed = std::max<Eigen::Index>(c.min_samples, 2);
  if (n < needed) {
    throw SamplingError(SamplingProblem::too_few, c.where + "time has " + std::to_string(n) +
                                                      " samples; expected at least " + std::to_string(needed));
  }
  // The common case in vector instructions; else the loop finds the first offending sample.
  const auto steps = t.tail(n - 1) - t.head(n - 1);
  const double smallest = steps.minCoeff();
  const bool clean = detail::all_finite(t) && smallest > 0;
  for (Eigen::Index k = 0; k < n && !clean; ++k) {
    if (!std::isfinite(t(k))) {
      throw SamplingError(SamplingProblem::not_finite,
                          c.where + label_of(c.row_label, k) + ": time = " + stamp(t(k)) + " s is not a finite number");
    }
    if (k > 0 && !(t(k) > t(k - 1))) {
      const bool repeated = t(k) == t(k - 1);
      throw SamplingError(repeated ? SamplingProblem::repeated : SamplingProblem::backwards,
                          c.where + label_of(c.row_label, k) + ": time " + stamp(t(k)) +
                              " s is not greater than the previous " + stamp(t(k - 1)) + " s" +
                              (repeated ? " (a repeated time stamp)" : "") + "; expected strictly increasing time");
    }
  }
  const double mean = (t(n - 1) - t(0)) / static_cast<double>(n - 1);
  if (!c.require_regular) return mean;
  // The rule: every step within `tolerance` of the median step. (The median, not the mean: one
  // gap is then reported where it is, not at every other step.) When all steps lie within the
  // tolerance of the smallest, they lie within it of the median (which is between them): the
  // common case, decided without selecting the median.
  if (steps.maxCoeff() - smallest <= c.tolerance * smallest) return mean;
  const TimeSteps s = time_steps(t);
  const double limit = c.tolerance * s.median;
  if (s.max - s.median <= limit && s.median - s.min <= limit) return mean;
  for (Eigen::Index k = 1; k < n; ++k) {
    const double dt = t(k) - t(k - 1);
    if (std::abs(dt - s.median) > limit) {
      throw SamplingError(SamplingProblem::irregular,
                          c.where + label_of(c.row_label, k) + ": time step " + step(dt) +
                              " s differs from the median step " + step(s.median) + " s by more than " +
                              detail::format_value(100 * c.tolerance, 6) + " % (steps from " + step(s.min) + " to " +
                              step(s.max) + " s); " + c.requirement);
    }
  }
  return mean;
}

std::string UniformResampler::label(Eigen::Index k) const { return label_of(options_.row_label, k); }

UniformResampler::UniformResampler(const Eigen::VectorXd& t, const ResampleOptions& o) : options_(o) {
  const std::string& where = o.where;
  if (!(std::isfinite(o.dt) && o.dt >= 0)) {
    throw std::invalid_argument(where + o.dt_name + " = " + step(o.dt) +
                                ": expected the step of the uniform grid in s (> 0), or none for the median step");
  }
  if (!(std::isfinite(o.max_gap) && o.max_gap >= 0)) {
    throw std::invalid_argument(where + o.max_gap_name + " = " + step(o.max_gap) +
                                ": expected the longest gap to interpolate over in s (> 0)");
  }
  n_in_ = t.size();
  report_.samples_in = n_in_;
  for (Eigen::Index k = 0; k < n_in_; ++k) {
    if (!std::isfinite(t(k))) {
      throw SamplingError(SamplingProblem::not_finite, where + label(k) + ": time = " + stamp(t(k)) + " s is not a finite number");
    }
    if (k > 0 && t(k) < t(k - 1)) {
      throw SamplingError(SamplingProblem::backwards,
                          where + label(k) + ": time " + stamp(t(k)) + " s is before the previous " + stamp(t(k - 1)) +
                              " s; expected increasing time (repeated time stamps are merged, earlier ones are not sorted)");
    }
    if (k == 0 || t(k) != t(k - 1)) group_start_.push_back(k);
  }
  const auto m = static_cast<Eigen::Index>(group_start_.size());
  group_start_.push_back(n_in_);
  if (m < 2) {
    throw SamplingError(SamplingProblem::too_few, where + "time has " + std::to_string(m) +
                                                      " distinct time stamps; expected at least 2 to resample");
  }
  Eigen::VectorXd u(m);  // the distinct time stamps
  for (Eigen::Index j = 0; j < m; ++j) u(j) = t(group_start_[static_cast<std::size_t>(j)]);
  report_.merged = n_in_ - m;
  if (report_.merged > 0) {
    Eigen::Index first = 1;
    while (t(first) != t(first - 1)) ++first;
    report_.warnings.push_back(std::to_string(report_.merged) + " row(s) repeat the time stamp of the row before (first at " +
                               label(first) + ", t = " + stamp(t(first)) +
                               " s); the rows of each repeated time stamp were merged into their mean");
  }

  const TimeSteps s = time_steps(u);
  report_.dt_min = s.min;
  report_.dt_median = s.median;
  report_.dt_max = s.max;
  const double dt = o.dt > 0 ? o.dt : s.median;
  const bool default_gap = o.max_gap == 0;
  report_.max_gap = default_gap ? 10 * s.median : o.max_gap;
  report_.dt = dt;

  // Gaps: refuse them all at once, naming the first and the longest.
  Eigen::Index gaps = 0, first_gap = -1, longest = -1;
  for (Eigen::Index j = 0; j + 1 < m; ++j) {
    const double d = u(j + 1) - u(j);
    if (d > report_.max_gap) {
      ++gaps;
      if (first_gap < 0) first_gap = j;
      if (longest < 0 || d > u(longest + 1) - u(longest)) longest = j;
    }
  }
  if (gaps > 0) {
    // Rows on either side: the last row of the stamp before the gap, the first row after it.
    const auto rows = [&](Eigen::Index j) {
      return label(group_start_[static_cast<std::size_t>(j + 1)] - 1) + " to " + label(group_start_[static_cast<std::size_t>(j + 1)]);
    };
    const auto gap_text = [&](Eigen::Index j) {
      const double d = u(j + 1) - u(j);
      return "a gap of " + step(d) + " s in time (from " + stamp(u(j)) + " s to " + stamp(u(j + 1)) + " s, " +
             detail::format_value(d / s.median, 3) + " median steps of " + step(s.median) + " s)";
    };
    std::string msg = where + rows(first_gap) + ": " + gap_text(first_gap) + ", longer than " +
                      (default_gap ? "10 median steps" : o.max_gap_name + " = " + step(o.max_gap) + " s");
    if (gaps > 1) {
      msg += " (" + std::to_string(gaps) + " such gaps in all; the longest, " + rows(longest) + ", is " +
             step(u(longest + 1) - u(longest)) + " s)";
    }
    // The suggested limit is rounded up (1 % above the gap, 3 digits) so that it does allow it.
    msg += "; resampling would invent data there: cut the record there, or allow the gap with " + o.max_gap_name + " " +
           detail::format_value(1.01 * (u(longest + 1) - u(longest)), 3) + " (s)";
    throw SamplingError(SamplingProblem::gap, msg);
  }

  const double span = u(m - 1) - u(0);
  if (dt > span) {
    throw std::invalid_argument(where + o.dt_name + " = " + step(dt) + " s is longer than the record (" + step(span) +
                                " s from first to last time stamp)");
  }
  constexpr double kMaxGrid = 1e8;  // samples per column (800 MB): beyond, a step given by mistake
  if (span / dt > kMaxGrid) {
    throw std::invalid_argument(where + o.dt_name + " = " + step(dt) + " s would make " + detail::format_value(span / dt, 3) +
                                " samples of the " + step(span) + " s record; expected at most 1e+08 (a larger step)");
  }
  // Grid points u(0) + i dt up to the last stamp; the relative slack keeps a last point that
  // rounding puts a hair past the end (span / dt = 99.9999999 for 100 steps).
  const auto count = static_cast<Eigen::Index>(std::floor(span / dt * (1 + 1e-12) + 1e-9)) + 1;
  grid_.resize(count);
  left_.resize(static_cast<std::size_t>(count));
  weight_.resize(static_cast<std::size_t>(count));
  Eigen::Index j = 0;
  for (Eigen::Index i = 0; i < count; ++i) {
    const double g = std::min(u(0) + static_cast<double>(i) * dt, u(m - 1));
    grid_(i) = g;
    while (j + 2 < m && u(j + 1) <= g) ++j;
    left_[static_cast<std::size_t>(i)] = j;
    weight_[static_cast<std::size_t>(i)] = std::clamp((g - u(j)) / (u(j + 1) - u(j)), 0.0, 1.0);
  }
  report_.samples_out = count;
  if (dt > 1.5 * s.median) {
    report_.warnings.push_back("the grid step " + step(dt) + " s is coarser than the record's median step " + step(s.median) +
                               " s: linear interpolation does not filter, so content above " +
                               detail::format_value(0.5 / dt, 4) + " Hz aliases (low-pass filter the record first)");
  }
}

Eigen::VectorXd UniformResampler::apply(const Eigen::VectorXd& x, const std::string& name) const {
  if (x.size() != n_in_) {
    throw std::invalid_argument(options_.where + "column '" + name + "' has " + std::to_string(x.size()) +
                                " samples; expected " + std::to_string(n_in_) + " like time");
  }
  const std::size_t m = group_start_.size() - 1;
  std::vector<double> v(m);  // the mean of each repeated time stamp's rows
  for (std::size_t j = 0; j < m; ++j) {
    double sum = 0;
    for (Eigen::Index k = group_start_[j]; k < group_start_[j + 1]; ++k) {
      if (!std::isfinite(x(k))) {
        throw std::invalid_argument(options_.where + label(k) + ", column '" + name + "': value " + stamp(x(k)) +
                                    " is not a finite number; expected finite values to interpolate");
      }
      sum += x(k);
    }
    v[j] = sum / static_cast<double>(group_start_[j + 1] - group_start_[j]);
  }
  Eigen::VectorXd out(grid_.size());
  for (Eigen::Index i = 0; i < out.size(); ++i) {
    const auto j = static_cast<std::size_t>(left_[static_cast<std::size_t>(i)]);
    const double w = weight_[static_cast<std::size_t>(i)];
    out(i) = w == 0 ? v[j] : (1 - w) * v[j] + w * v[j + 1];
  }
  return out;
}

}  // namespace frictionlab
