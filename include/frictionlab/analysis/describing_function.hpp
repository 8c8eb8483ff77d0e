#pragma once
// Describing-function prediction of the hunting limit cycle of a PID position loop around a mass
// with Coulomb and static friction (Fc < Fs, no viscous part):
//   M x'' = u - F,   u = Kp e + Ki int(e) - Kd x',   e = r - x   (x measured from the setpoint r).
//
// Friction alone, as a function of velocity, never predicts this cycle (its stick phases are
// invisible to a sine), so the nonlinear element is the mass with its friction and the fast P and
// D terms, driven by the slow integrator force w = Ki int(e): while stuck at x the mass feels
// w - Kp x; it breaks away when that reaches Fs, slips (the PD loop against Fc, w frozen: the
// slip is short against the stick phases) and sticks again on the other side. Seen from w the
// element is a relay with hysteresis: its output jumps between -A and +A when |w| reaches
// h = Fs - Kp A, and A follows from the slip: starting at rest from -A, the damped oscillator
// M x'' + Kd x' + Kp x = w - Fc first stops at x_e + (x_e + A) rho, x_e = (h - Fc) / Kp,
// rho = exp(-pi zeta / sqrt(1 - zeta^2)) (zeta = Kd / (2 sqrt(Kp M)); rho = 0 when zeta >= 1),
// and landing on +A gives
//   A = (Fs - Fc) (1 + rho) / (2 Kp).
// The relay's describing function N(W) = 4 A / (pi W) exp(-j asin(h / W)) in the loop with the
// integrator -Ki / (j w) balances (1 + N Ki / (j w) = 0) at W = h (phase: the integrator's 90
// degrees and the relay's lag make 180) and
//   w = 4 A Ki / (pi h),   period T = pi^2 (Fs - Kp A) / (2 Ki A).
//
// Accuracy: the balance replaces the integrator force, a triangle between -h and +h, by its
// fundamental, and freezes it during the slip, while the slip in fact lasts a fair part of the
// cycle when the loop is well damped. Against exact simulations of five loops
// (tests/analysis/test_map.cpp: Kp 3..10, Ki 2..4, Kd 1..6, Fs/Fc 1.5..2.5) the predicted
// amplitude is off by -26 % .. +24 % and the period by -36 % .. +30 %, worst with a heavy Kd (the
// overdamped slip then lasts a good part of the cycle).
// Armstrong-Helouvry and Amin (Automatica 32(5), 1996) show how unreliable the plain describing
// function is on this problem: use this for the order of magnitude and the trends (A grows with
// Fs - Fc and falls with Kp; T falls with Ki), and simulate (frictionlab analyze map) for figures.
// Without stiction (Fs == Fc) A = 0: no hunting, as for the real loop (it converges).

#include <string>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The loop of predict_hunting. SI units; a rotary axis reads kg m^2, N m, rad.
struct HuntingLoop {
  double M = 1.0;   ///< inertia (kg), > 0
  double Kp = 0.0;  ///< proportional gain (N/m), > 0
  double Ki = 0.0;  ///< integral gain (N/(m s)), > 0 (no integrator: no hunting)
  double Kd = 0.0;  ///< velocity feedback gain (N s/m), >= 0
  double Fc = 1.0;  ///< Coulomb friction (N), > 0
  double Fs = 1.5;  ///< static friction (N), >= Fc
  /// \throws std::invalid_argument naming the first parameter out of range.
  void validate() const;
};

/// The predicted cycle, or why there is none.
struct HuntingPrediction {
  bool found = false;
  double amplitude = 0.0;       ///< half peak-to-peak of the position around the setpoint (m)
  double first_harmonic = 0.0;  ///< amplitude of the position's first harmonic, 4 A / pi (m)
  double period = 0.0;          ///< s
  double switch_force = 0.0;    ///< h = Fs - Kp A: the integrator force at breakaway (N)
  double damping_ratio = 0.0;   ///< zeta of the slip (dimensionless)
  /// Empty when found; else why not ("no stiction ...", "the linear loop is unstable ...").
  std::string message;
};

/// Harmonic balance of the loop (see the top of this file for the method and its accuracy).
/// No cycle when Fs == Fc, or when the loop without friction is unstable (Kd Kp <= M Ki: the
/// motion then is not a hunting around the setpoint).
/// \throws std::invalid_argument as HuntingLoop::validate.
HuntingPrediction predict_hunting(const HuntingLoop& loop);

}  // namespace frictionlab
