#include "frictionlab/models/table.hpp"

#include "table_knots.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace frictionlab {
namespace {
[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("table: " + what); }
}  // namespace

// Fritsch-Carlson monotone slopes, written here because neither Eigen nor the Debian Boost
// (1.74, before boost::math pchip) provide monotone Hermite interpolation.
std::vector<double> detail::monotone_slopes(const std::vector<double>& v, const std::vector<double>& f) {
  const std::size_t n = v.size();
  std::vector<double> d(n - 1), m(n, 0.0);
  for (std::size_t k = 0; k + 1 < n; ++k) d[k] = (f[k + 1] - f[k]) / (v[k + 1] - v[k]);
  m[0] = d[0];
  m[n - 1] = d[n - 2];
  for (std::size_t k = 1; k + 1 < n; ++k) m[k] = (d[k - 1] * d[k] <= 0) ? 0.0 : (d[k - 1] + d[k]) / 2;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (d[k] == 0.0) {
      m[k] = m[k + 1] = 0.0;
      continue;
    }
    const double a = m[k] / d[k], b = m[k + 1] / d[k];
    const double r = a * a + b * b;
    if (r > 9.0) {
      const double tau = 3.0 / std::sqrt(r);
      m[k] = tau * a * d[k];
      m[k + 1] = tau * b * d[k];
    }
  }
  return m;
}

void detail::table_sides(const std::vector<double>& velocity, const std::vector<double>& force, TableSide& pos,
                         TableSide& neg) {
  pos = {};
  neg = {};
  for (std::size_t k = 0; k < velocity.size(); ++k) {
    if (velocity[k] > 0) {
      pos.speed.push_back(velocity[k]);
      pos.level.push_back(force[k]);
    } else {
      neg.speed.insert(neg.speed.begin(), -velocity[k]);
      neg.level.insert(neg.level.begin(), -force[k]);
    }
  }
  if (neg.speed.empty()) neg = pos;  // only one direction measured: mirror it
  if (pos.speed.empty()) pos = neg;
}

Table::Branch Table::make_branch(std::vector<double> v, std::vector<double> f) {
  std::vector<double> m = detail::monotone_slopes(v, f);
  return Branch{std::move(v), std::move(f), std::move(m)};
}

Table::Table(std::vector<double> velocity, std::vector<double> force)
    : velocity_(std::move(velocity)), force_(std::move(force)) {
  validate();
  detail::TableSide pos, neg;
  detail::table_sides(velocity_, force_, pos, neg);
  pos_ = make_branch(std::move(pos.speed), std::move(pos.level));
  neg_ = make_branch(std::move(neg.speed), std::move(neg.level));
}

void Table::validate() const {
  if (velocity_.size() != force_.size()) {
    std::ostringstream s;
    s << "velocity has " << velocity_.size() << " points but force has " << force_.size() << "; they must be equal";
    fail(s.str());
  }
  std::size_t npos = 0, nneg = 0;
  for (std::size_t k = 0; k < velocity_.size(); ++k) {
    std::ostringstream s;
    s.precision(10);
    if (!std::isfinite(velocity_[k]) || !std::isfinite(force_[k])) {
      s << "point " << k << " (velocity " << velocity_[k] << ", force " << force_[k] << ") must be finite";
      fail(s.str());
    }
    if (velocity_[k] == 0.0) {
      s << "velocity[" << k << "] = 0 must be nonzero (the force at rest is the breakaway level, taken from the smallest |v|)";
      fail(s.str());
    }
    if (k > 0 && velocity_[k] <= velocity_[k - 1]) {
      s << "velocity[" << k << "] = " << velocity_[k] << " must be > velocity[" << k - 1 << "] = " << velocity_[k - 1]
        << " (strictly increasing, m/s or rad/s)";
      fail(s.str());
    }
    if (force_[k] * velocity_[k] < 0) {
      s << "force[" << k << "] = " << force_[k] << " must have the sign of velocity[" << k << "] = " << velocity_[k];
      fail(s.str());
    }
    (velocity_[k] > 0 ? npos : nneg)++;
  }
  if (npos == 1 || nneg == 1 || npos + nneg < 2) {
    std::ostringstream s;
    s << "each direction needs at least 2 points (has " << npos << " positive, " << nneg << " negative)";
    fail(s.str());
  }
}

}  // namespace frictionlab
