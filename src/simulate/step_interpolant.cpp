#include "step_interpolant.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>

#include <algorithm>
#include <cstddef>

namespace frictionlab::detail {

bool StepInterpolant::eval(void* cvode_mem, double t, double* out) {
  double tn = 0.0;
  if (CVodeGetCurrentTime(cvode_mem, &tn) != CV_SUCCESS || !(t <= tn)) return false;
  const auto n = static_cast<std::size_t>(NV_LENGTH_S(work_));
  if (tn != step_.tn) step_ = {tn, -1, 0};
  if (step_.q < 0 && step_.rows++ == 0) {
    // One row in a step is common in fast phases: one CVodeGetDky is cheaper than q + 1.
    if (CVodeGetDky(cvode_mem, t, 0, work_) != CV_SUCCESS) return false;
    std::copy_n(NV_DATA_S(work_), n, out);
    return true;
  }
  if (step_.q < 0) {
    int q = 0;
    if (CVodeGetLastOrder(cvode_mem, &q) != CV_SUCCESS || q < 0) return false;
    taylor_.resize(static_cast<std::size_t>(q + 1) * n);
    double factorial = 1.0;
    for (int k = 0; k <= q; ++k) {
      if (k > 0) factorial *= k;
      if (CVodeGetDky(cvode_mem, tn, k, work_) != CV_SUCCESS) return false;
      const double* d = NV_DATA_S(work_);
      for (std::size_t i = 0; i < n; ++i) taylor_[static_cast<std::size_t>(k) * n + i] = d[i] / factorial;
    }
    step_.q = q;
  }
  const double dt = t - tn;
  const auto q = static_cast<std::size_t>(step_.q);
  for (std::size_t i = 0; i < n; ++i) {
    double v = taylor_[q * n + i];
    for (std::size_t k = q; k-- > 0;) v = v * dt + taylor_[k * n + i];
    out[i] = v;
  }
  return true;
}

}  // namespace frictionlab::detail
