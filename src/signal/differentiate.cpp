#include "frictionlab/signal/differentiate.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace frictionlab {

Eigen::VectorXd gradient(const Eigen::VectorXd& x, double dt) {
  Eigen::VectorXd d(x.size());
  gradient(x, dt, d);
  return d;
}

void gradient(const Eigen::Ref<const Eigen::VectorXd>& x, double dt, Eigen::Ref<Eigen::VectorXd> d) {
  if (!(dt > 0.0) || !std::isfinite(dt)) {
    std::ostringstream msg;
    msg << "gradient: sample time dt = " << dt << " s must be a positive finite number";
    throw std::invalid_argument(msg.str());
  }
  const Eigen::Index n = x.size();
  if (n < 2) throw std::invalid_argument("gradient: needs at least 2 samples, got " + std::to_string(n));
  if (d.size() != n) {
    throw std::invalid_argument("gradient: output has " + std::to_string(d.size()) + " samples; expected " +
                                std::to_string(n) + " like the input");
  }
  // numpy.gradient(x, dt): (x[k+1] - x[k-1]) / (2 dt) inside, first differences at the ends.
  // Times the reciprocal rather than divided (a division costs several multiplies; the two
  // differ by a rounding, about 1e-16 relative).
  if (n > 2) d.segment(1, n - 2) = (x.segment(2, n - 2) - x.segment(0, n - 2)) * (0.5 / dt);
  d(0) = (x(1) - x(0)) / dt;
  d(n - 1) = (x(n - 1) - x(n - 2)) / dt;
}

}  // namespace frictionlab
