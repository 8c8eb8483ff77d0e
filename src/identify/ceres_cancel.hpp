#pragma once
// Cancellation of a Ceres fit (frictionlab/cancellation.hpp): an iteration callback that aborts
// the solve once the token current when the fit started is set. The fit calls
// throw_if_cancelled() after ceres::Solve, so an aborted solve is never read as a result.

#include <ceres/iteration_callback.h>

#include "frictionlab/cancellation.hpp"

namespace frictionlab::detail {

class CancelCallback final : public ceres::IterationCallback {
 public:
  CancelCallback() noexcept : token_(current_cancel_token()) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
    return token_ != nullptr && token_->cancelled() ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
  }

 private:
  const CancelToken* token_;
};

}  // namespace frictionlab::detail
