#include "frictionlab/signal/decimate.hpp"

#include <stdexcept>
#include <string>

#include "frictionlab/signal/chebyshev.hpp"
#include "frictionlab/signal/filtfilt.hpp"

namespace frictionlab {

namespace {

// scipy 1.10's default IIR anti-aliasing filter for a factor q.
SecondOrderSections decimation_filter(int q) {
  if (q < 1) throw std::invalid_argument("decimate: factor q = " + std::to_string(q) + " must be a positive integer");
  constexpr int kOrder = 8;                // scipy's default IIR order
  constexpr double kRippleDb = 0.05;       // scipy's default pass-band ripple
  constexpr double kCutoffFraction = 0.8;  // of the new Nyquist frequency
  return cheby1_sos(kOrder, kRippleDb, kCutoffFraction / q);
}

}  // namespace

Eigen::VectorXd decimate(const Eigen::VectorXd& x, int q) {
  return decimate_columns(ColumnViews{{x.data(), x.size()}}, q).col(0);
}

Eigen::MatrixXd decimate_columns(const Eigen::MatrixXd& x, int q) {
  return sosfiltfilt_columns(decimation_filter(q), x, {}, q);
}

Eigen::MatrixXd decimate_columns(const ColumnViews& x, int q) {
  return sosfiltfilt_columns(decimation_filter(q), x, {}, q);
}

Eigen::MatrixXd decimate_columns(const ColumnViews& x, int q, FilterWorkspace& workspace) {
  return sosfiltfilt_columns(decimation_filter(q), x, {}, q, workspace);
}

}  // namespace frictionlab
