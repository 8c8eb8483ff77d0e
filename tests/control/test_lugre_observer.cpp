// LuGre observer (Canudas de Wit et al. 1995, section V): converges to the true friction of a
// LuGre plant at constant velocity with the bristle rate sigma0 |v| / g(v), its correction term
// k e at rest, the exact fixed-step form, the Jacobian against central differences, and its errors.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "control/harness.hpp"
#include "error_message.hpp"
#include "frictionlab/control/lugre_observer.hpp"

namespace frictionlab {
namespace {

using testing::error_of;

// Table I set of the 1995 paper (N/m, N s/m, N s/m, N, N, m/s).
LuGre table_one() { return LuGre{}; }

LuGre revisited() {
  LuGre l;
  l.vd = 0.002;  // m/s: damping that decays with speed
  return l;
}

class ObserverConvergence : public ::testing::TestWithParam<LuGre> {};

TEST_P(ObserverConvergence, FollowsTheTrueFrictionAtConstantVelocity) {
  const LuGre law = GetParam();
  const LuGreObserver obs(law, {.gain = 0.01});
  const double v = 0.01;  // m/s, ten Stribeck velocities: g(v) = Fc
  const testing::InputAt at = [&](double t) {
    CompensatorInput in;
    in.t = t;
    in.position = v * t;
    in.reference = v * t;  // tracking exactly: e = 0, the correction is idle
    in.velocity = v;
    return in;
  };
  // The plant starts unloaded (z = 0), the observer at the opposite bristle bound (worst guess).
  std::vector<double> z_true{0.0}, z_hat{-law.Fs / law.sigma0};
  const double F0_err = obs.output(at(0), z_hat) - law.force(z_true[0], v);
  const double rate = law.sigma0 * v / law.level(v);  // 1/s: 1000 here
  double t = 0;
  for (double t_next : {0.5e-3, 2e-3, 10e-3}) {
    // RK4 with h rate = 1e-3: its relative error on the decay is below 1e-12.
    testing::run(obs, at, z_hat, t, t_next, static_cast<long>(std::lround((t_next - t) / 1e-6)));
    law.step(z_true, v, t_next - t);  // exact at constant v
    t = t_next;
    const double F = law.force(z_true[0], v);
    const double F_hat = obs.output(at(t), z_hat);
    // Both states obey the same linear equation, so the error decays as exp(-rate t) exactly.
    constexpr double kDecayRelTol = 1e-8;  // RK4 and the exact step, compared after cancellation
    EXPECT_NEAR((F_hat - F) / F0_err, std::exp(-rate * t), kDecayRelTol) << "t " << t;
  }
  // After 10 bristle time constants the estimate is the friction to a few 1e-4 N (Fc = 1 N).
  const double F = law.force(z_true[0], v);
  EXPECT_LT(std::abs(obs.output(at(t), z_hat) - F), 1e-3 * std::abs(F));
  EXPECT_NEAR(F, law.Fc + law.sigma2 * v, 1e-3);  // and the plant itself has reached its Stribeck force
}

INSTANTIATE_TEST_SUITE_P(Laws, ObserverConvergence, ::testing::Values(table_one(), revisited()));

TEST(LuGreObserver, CorrectionAtRest) {
  // At rest short of the target (e = x - r = -0.01 m) the state integrates -k e and the output
  // is sigma0 z + sigma1 (-k e): the term that breaks the body loose where a PID alone hunts.
  const LuGre law = table_one();
  const double k = 0.02;  // 1/s
  const LuGreObserver obs(law, {.gain = k});
  CompensatorInput in;
  in.position = 0.99;
  in.reference = 1.0;
  std::vector<double> z{3e-6}, dz(1);
  obs.derivatives(in, z, dz);
  constexpr double kRelTol = 1e-14;  // one multiply-add apart
  EXPECT_NEAR(dz[0], k * 0.01, kRelTol * k * 0.01);
  const double want = law.sigma0 * 3e-6 + law.sigma1 * k * 0.01;
  EXPECT_NEAR(obs.output(in, z), want, kRelTol * want);
  // The fixed step at v = 0 is the exact ramp.
  const double want_step = law.sigma0 * (3e-6 + 0.5 * k * 0.01) + law.sigma1 * k * 0.01;
  EXPECT_NEAR(obs.update(in, z, 0.5), want_step, kRelTol * want_step);
  EXPECT_NEAR(z[0], 3e-6 + 0.5 * k * 0.01, kRelTol * 1.03e-4);
}

TEST(LuGreObserver, FixedStepIsTheLawsExactStepWhenTracking) {
  // With e = 0 the update is the law's own exact step, at any step length.
  for (const LuGre& law : {table_one(), revisited()}) {
    const LuGreObserver obs(law, {.gain = 0.05});
    for (double dt : {1e-5, 1e-3, 0.1}) {
      for (double v : {-0.02, 5e-4, 0.3}) {
        std::vector<double> z_hat{2e-6}, z{2e-6};
        CompensatorInput in;
        in.velocity = v;
        in.position = in.reference = 0.3;
        const double F_hat = obs.update(in, z_hat, dt);
        const double F = law.step(z, v, dt);
        constexpr double kRelTol = 1e-12;  // the same formula, grouped differently
        EXPECT_NEAR(z_hat[0], z[0], kRelTol * std::abs(z[0])) << "dt " << dt << " v " << v;
        EXPECT_NEAR(F_hat, F, kRelTol * std::max(std::abs(F), 1.0)) << "dt " << dt << " v " << v;
      }
    }
  }
}

TEST(LuGreObserver, JacobianMatchesCentralDifferences) {
  // Central differences with a relative step of 1e-6: truncation ~1e-12, rounding ~1e-9 relative.
  constexpr double kFdRelTol = 1e-6;
  for (const LuGre& law : {table_one(), revisited()}) {
    const LuGreObserver obs(law, {.gain = 0.03});
    for (double v : {-0.004, 7e-4, 0.05}) {
      CompensatorInput in;
      in.position = 0.2;
      in.reference = 0.21;
      in.velocity = v;
      in.drive = 1.3;
      testing::expect_jacobian_matches(obs, in, {5e-6}, kFdRelTol);
    }
  }
}

TEST(LuGreObserver, InitialStateIsTheSteadyState) {
  const LuGre law = table_one();
  const LuGreObserver obs(law);
  std::vector<double> z{1.0};
  CompensatorInput in;
  obs.initial_states(in, z);
  EXPECT_EQ(z[0], 0.0);
  in.velocity = -0.1;
  obs.initial_states(in, z);
  EXPECT_DOUBLE_EQ(z[0], -law.Fc / law.sigma0);
}

TEST(LuGreObserver, RejectsOtherLawsAndABadGain) {
  EXPECT_EQ(error_of([] { LuGreObserver(Coulomb{}); }),
            "lugre-observer: law = coulomb must be lugre (the observer runs a copy of the LuGre bristle state)");
  EXPECT_EQ(error_of([] { LuGreObserver(LuGre{}, {.gain = -1.0}); }),
            "lugre-observer: gain = -1 must be >= 0 (1/s: bristle rate per position error)");
  EXPECT_EQ(error_of([] { LuGreObserver(LuGre{}, {.gain = std::nan("")}); }),
            "lugre-observer: gain = nan must be >= 0 (1/s: bristle rate per position error)");
}

}  // namespace
}  // namespace frictionlab
