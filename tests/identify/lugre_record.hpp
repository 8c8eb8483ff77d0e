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
#include <random>

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

/// A one-record experiment as a rig runs it: a sum of two sinusoids of the applied force, faded in
/// over the first slow period so the record starts at rest, drives the mass through presliding,
/// breakaway in both directions and reversals; the encoder position carries white noise and is
/// quantised to its resolution.
struct MultisineRecord {
  LuGre truth{};            ///< the friction law simulated (Table I by default)
  double inertia = 1.0;     ///< kg
  double amplitude = 2.0;   ///< peak of each sinusoid's envelope, in units of truth.Fs
  double frequency = 0.5;   ///< Hz of the slow sinusoid; the fast one runs 2.7 times faster at 0.4 of its amplitude
  double duration = 8.0;    ///< s
  double rate = 1000.0;     ///< samples per second
  double noise = 2e-7;      ///< position noise std (m)
  double resolution = 5e-8; ///< encoder resolution (m); 0 = not quantised
  unsigned seed = 1;        ///< phases of the fast sinusoid and the noise
};

/// Time (s), applied force (N) and noisy, quantised position (m) of `spec`, simulated by CVODE
/// (stiff mode). The force table has corners every 10 samples, on sample times, so the recorded
/// force is the applied one.
inline LugreData multisine_record(const MultisineRecord& spec) {
  std::mt19937_64 rng(spec.seed);
  std::uniform_real_distribution<double> phase(0.0, 2 * std::numbers::pi);
  const double phi = phase(rng);
  const double fade = 1.0 / spec.frequency;  // s
  const double a = spec.amplitude * spec.truth.Fs;
  InputSignal in;
  in.shape = InputShape::table;
  const double corner = 10.0 / spec.rate;
  for (int i = 0; i * corner <= spec.duration + 1e-9; ++i) {
    const double t = i * corner;
    const double w = std::min(1.0, t / fade);
    const double u = a * w * (std::sin(2 * std::numbers::pi * spec.frequency * t) +
                              0.4 * std::sin(2 * std::numbers::pi * 2.7 * spec.frequency * t + phi));
    in.times.push_back(t);
    in.values.push_back(u);
  }
  SimulationOptions o;
  o.duration = spec.duration;
  o.output_rate = spec.rate;
  o.mode = SolverMode::stiff;
  const Trajectory tr = simulate(RigidAxis(AxisParams{spec.inertia, 0.0}), FrictionLaw(spec.truth), in, o);
  LugreData d;
  const auto n = static_cast<Eigen::Index>(tr.rows());
  d.time = Eigen::Map<const Eigen::VectorXd>(tr.time.data(), n);
  d.force = Eigen::Map<const Eigen::VectorXd>(tr.applied.data(), n);
  d.position = Eigen::Map<const Eigen::VectorXd>(tr.position.data(), n);
  std::normal_distribution<double> noise(0.0, spec.noise);
  for (Eigen::Index k = 0; k < n; ++k) {
    double x = d.position[k] + (spec.noise > 0 ? noise(rng) : 0.0);
    if (spec.resolution > 0) x = spec.resolution * std::round(x / spec.resolution);
    d.position[k] = x;
  }
  return d;
}

}  // namespace frictionlab::testing
