#pragma once
// Dense output of CVODE's last step without a CVode call per output row (private to the engine).
//
// Why: at 1 kHz over the long steps of a stiff run, most output rows fall inside a step already
// taken. Asking CVode for each of them (it then calls CVodeGetDky) took a quarter of a Canudas
// stick-slip run. Here the first row inside a step still costs one CVodeGetDky; from the second
// on, the step's Taylor coefficients are fetched once (q + 1 CVodeGetDky calls) and each row is a
// Horner sum. The values equal CVODE's interpolation up to rounding.

#include <sundials/sundials_nvector.h>

#include <vector>

namespace frictionlab::detail {

class StepInterpolant {
 public:
  /// `work`: a serial N_Vector of the state's length, owned by the caller, that CVodeGetDky
  /// writes into.
  explicit StepInterpolant(N_Vector work) : work_(work) {}

  /// The state at time t (s) from the interpolating polynomial of the last step of `cvode_mem`,
  /// written to out[0..n). Valid for t in [tn - hu, tn] of that step (the caller's rows only move
  /// forward inside it). Returns false, writing nothing, when t is beyond tn or CVODE refuses
  /// (then ask CVode itself). Throws nothing but std::bad_alloc.
  bool eval(void* cvode_mem, double t, double* out);

  /// Forgets the step (call after CVodeReInit: a new step sequence starts).
  void reset() { step_ = {}; }

 private:
  struct Step {
    double tn = -1.0;  // end time of the step the cache belongs to (s)
    int q = -1;        // order of the coefficients in taylor_; -1: not fetched
    int rows = 0;      // rows served from this step
  };
  N_Vector work_;
  Step step_;
  std::vector<double> taylor_;  // (q + 1) x n: row k = y^(k)(tn) / k!
};

}  // namespace frictionlab::detail
