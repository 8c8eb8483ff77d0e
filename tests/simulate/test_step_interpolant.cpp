// The engine's dense output inside a step (src/simulate/step_interpolant.hpp) against CVODE's own
// CVodeGetDky, on a small stiff linear system stepped one step at a time.
#include <gtest/gtest.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "simulate/step_interpolant.hpp"

namespace {

// A lightly damped oscillator (like a bristle mode) driven by a slow decaying state:
// x' = v, v' = -1e4 x - 20 v + w, w' = -0.5 w.
int rhs(sunrealtype, N_Vector y, N_Vector dy, void*) {
  const double* s = NV_DATA_S(y);
  double* d = NV_DATA_S(dy);
  d[0] = s[1];
  d[1] = -1e4 * s[0] - 20.0 * s[1] + s[2];
  d[2] = -0.5 * s[2];
  return 0;
}

struct Cvode {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr, work = nullptr, ref = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  void* mem = nullptr;
  Cvode() {
    SUNContext_Create(nullptr, &ctx);
    y = N_VNew_Serial(3, ctx);
    work = N_VNew_Serial(3, ctx);
    ref = N_VNew_Serial(3, ctx);
    NV_Ith_S(y, 0) = 1e-3;
    NV_Ith_S(y, 1) = 0.0;
    NV_Ith_S(y, 2) = 1.0;
    mem = CVodeCreate(CV_BDF, ctx);
    CVodeInit(mem, rhs, 0.0, y);
    CVodeSStolerances(mem, 1e-9, 1e-12);
    A = SUNDenseMatrix(3, 3, ctx);
    LS = SUNLinSol_Dense(y, A, ctx);
    CVodeSetLinearSolver(mem, LS, A);
  }
  ~Cvode() {
    CVodeFree(&mem);
    SUNLinSolFree(LS);
    SUNMatDestroy(A);
    N_VDestroy(y);
    N_VDestroy(work);
    N_VDestroy(ref);
    SUNContext_Free(&ctx);
  }
};

}  // namespace

// Every step of a run, rows at 7 places inside it (the first served by one CVodeGetDky, the
// others by the Taylor coefficients), against CVodeGetDky at the same time.
TEST(StepInterpolant, EqualsCvodeInterpolationUpToRounding) {
  // Both sum the same q + 1 terms of the step polynomial (CVODE in s = (t - tn) / h with the
  // Nordsieck array, here in t - tn with y^(k) / k!); they differ by the rounding of those
  // terms, a few units of 1e-16 of the largest. 1e-13 of the state's scale leaves margin.
  constexpr double kRoundingTolerance = 1e-13;
  Cvode c;
  frictionlab::detail::StepInterpolant interp(c.work);
  const double scale[3] = {1e-3, 1e-1, 1.0};
  int rows = 0, orders_seen = 0;
  double t = 0.0;
  for (int step = 0; step < 400 && t < 5.0; ++step) {
    ASSERT_GE(CVode(c.mem, 10.0, c.y, &t, CV_ONE_STEP), 0);
    double hu = 0.0;
    int q = 0;
    CVodeGetLastStep(c.mem, &hu);
    CVodeGetLastOrder(c.mem, &q);
    orders_seen |= 1 << q;
    for (int j = 6; j >= 0; --j) {  // forward in time: rows only move forward inside a step
      const double tr = t - hu * j / 6.0;
      double out[3];
      ASSERT_TRUE(interp.eval(c.mem, tr, out)) << "t = " << tr;
      ASSERT_EQ(CVodeGetDky(c.mem, tr, 0, c.ref), CV_SUCCESS);
      for (int i = 0; i < 3; ++i)
        ASSERT_NEAR(out[i], NV_Ith_S(c.ref, i), kRoundingTolerance * scale[i]) << "state " << i << " at t = " << tr;
      ++rows;
    }
    double beyond[3] = {7.0, 7.0, 7.0};
    EXPECT_FALSE(interp.eval(c.mem, t + 0.5 * hu, beyond)) << "a time beyond the step must be refused";
    EXPECT_EQ(beyond[0], 7.0) << "a refused call writes nothing";
  }
  EXPECT_GT(rows, 1000);
  EXPECT_GE(__builtin_popcount(orders_seen), 3) << "the run should exercise several BDF orders";
}
