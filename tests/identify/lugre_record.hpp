#pragma once
// The LuGre identification record of tests/identify/test_lugre.cpp, also used by
// bench/bench_lugre_fit.cpp and the lugre_fit task of bench/compare_driver.cpp: Canudas de Wit 1995 Table I friction on a unit mass,
// a slow force ramp to 0.95 Fs and back (presliding, 0..4 s), then a force sine of amplitude 2 Fs
// at 0.5 Hz (sliding both ways, 4..10 s), simulated by CVODE (stiff mode, rtol 1e-8) and sampled at
// 1 kHz. Noise-free and deterministic (no random numbers): the same doubles on every run.
// bench/peers/common.py (lugre_input_table) holds the same input table.

#include <Eigen/Core>
#include <cmath>
#include <numbers>

#include "frictionlab/identify/lugre.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/simulate/simulate.hpp"

namespace frictionlab::testing {

/// The applied force (N) as a table whose corners sit on the 1 kHz sample times, so that the
/// recorded samples interpolated linearly reproduce it exactly.
inline InputSignal lugre_experiment(const LuGre& truth) {
  InputSignal in;
  in.shape = InputShape::table;
  in.times = {0.0, 2.0, 4.0};
  in.values = {0.0, 0.95 * truth.Fs, 0.0};
  constexpr double kCorner = 0.02;  // s between table corners of the sine (50 Hz)
  for (int i = 1; 4.0 + i * kCorner <= 10.0 + 1e-9; ++i) {
    const double t = 4.0 + i * kCorner;
    in.times.push_back(t);
    in.values.push_back(2 * truth.Fs * std::sin(std::numbers::pi * (t - 4.0)));
  }
  return in;
}

/// 10 s of 1 kHz time (s), applied force (N) and position (m) with the Table I law (LuGre{}).
inline LugreData lugre_record() {
  const LuGre truth{};
  SimulationOptions o;
  o.duration = 10;
  o.output_rate = 1000;
  o.mode = SolverMode::stiff;
  const Trajectory tr = simulate(RigidAxis(AxisParams{1.0, 0.0}), FrictionLaw(truth), lugre_experiment(truth), o);
  LugreData d;
  const auto n = static_cast<Eigen::Index>(tr.rows());
  d.time = Eigen::Map<const Eigen::VectorXd>(tr.time.data(), n);
  d.force = Eigen::Map<const Eigen::VectorXd>(tr.applied.data(), n);
  d.position = Eigen::Map<const Eigen::VectorXd>(tr.position.data(), n);
  return d;
}

/// The static part of Table I as a Stribeck law (Fc, Fs, vs, delta, Fv = sigma2), for fits with
/// the static part given.
inline FrictionLaw lugre_static_part() {
  const LuGre t{};
  return FrictionLaw(Stribeck{t.Fc, t.Fs, t.vs, t.delta, t.sigma2});
}

}  // namespace frictionlab::testing
