#pragma once
// The EMPS benchmark's discrete position controller closed around a plant (Janot, Gautier,
// Brunot 2019, "Data Set and Reference Models of EMPS"): sampled every dt seconds,
//   qf(k)   = 0.5 q(k) + 0.5 q(k-1)                 (two-tap filtered position, m)
//   qd_m(k) = (qf(k) - qf(k-1)) / dt                 (measured velocity, m/s)
//   v(k)    = sat(kp kv (qg(k) - q(k)) - kv qd_m(k)) (drive input, V, |v| <= limit)
//           + pulses(k)                              (V, added after the saturation)
// and v(k) is applied from sample k + delay on (EMPS: delay = 1), held between samples; the
// plant's input is gtau * v (force, N, for an axis). The scenario input is the reference qg (m).

#include <memory>

#include "frictionlab/control/compensator.hpp"
#include "frictionlab/plants/plant.hpp"
#include "frictionlab/core/input.hpp"

#include "frictionlab/export.hpp"
namespace FRICTIONLAB_API frictionlab {

/// Gains, limits and timing of the EMPS controller (EMPS values in brackets).
struct EmpsPdParams {
  double kp = 0.0;      ///< position-loop gain (1/s), >= 0 [160.18]
  double kv = 0.0;      ///< velocity-loop gain (V/(m/s) or V/(rad/s)), >= 0 [243.45]
  double gtau = 1.0;    ///< drive gain (N/V or N m/V), > 0: plant input = gtau * v [35.15]
  double limit = 10.0;  ///< output saturation |v| <= limit (V), > 0. Default 10.
  double dt = 1e-3;     ///< sample period (s), > 0. Default 1e-3.
  int delay = 1;        ///< samples from computing v(k) to applying it: 0 or 1. Default 1.
  /// Pulses added to the saturated output (V), sampled at the sample instants (EMPS PULSES
  /// file: 0 or 5 V). Default constant 0.
  InputSignal pulses;
};

/// Discrete EMPS PD loop around `inner`, integrated by the engine through Plant::sample_period()
/// and Plant::sample(). States: the inner plant's, then 6 discrete ones (derivative 0):
/// applied output (V), last computed output v(k) (V), q(k-1) (m), qf(k-1) (m), a flag that
/// is 1 once the first sample was taken, and qg(k-1) (m) (the memory then starts at the initial position: no
/// velocity kick at t = 0). Signals: voltage = the last computed output v(k) (V, with pulses),
/// the counterpart of the recorded drive input; drive = gtau v(k) (N or N m: the force the
/// controller commands, the counterpart of a recorded force); reference = qg (m).
///
/// An optional friction compensator runs at the samples as a drive's firmware runs it: its
/// fixed-step update (Compensator::update) over the sample period, fed with the measured position
/// q(k), the loop's own velocity estimate qd_m(k), the reference qg(k) and its backward difference
/// (qg(k) - qg(k-1)) / dt as the reference velocity (the reference is a sampled signal), and the
/// force held over the period just ended; its output F (N or N m) enters the drive as F / gtau (V)
/// inside the saturation. Its states follow the 6 discrete ones (the sixth: qg(k-1), m).
class EmpsPdLoop : public SingleContactPlant {
 public:
  /// \throws std::invalid_argument when `inner` is null or kinematic, or a parameter is out of
  ///         range (the message names it, with its value and unit).
  EmpsPdLoop(std::shared_ptr<const Plant> inner, EmpsPdParams p, std::shared_ptr<const Compensator> compensator = nullptr);
  std::string type() const override { return inner_->type(); }
  int num_states() const override { return n_inner_ + kDiscrete + n_comp_; }
  using SingleContactPlant::initial_extras;
  void initial_extras(std::span<double> x, Inputs u) const override;
  double inertia(int = 0) const override { return inner_->inertia(); }
  double applied(double t, std::span<const double> x, const InputValue& r) const override;
  void derivatives(double t, std::span<const double> x, const InputValue& r, double friction,
                   std::span<double> dx) const override;
  PlantSignals signals(double t, std::span<const double> x, const InputValue& r) const override;
  double sample_period() const override { return p_.dt; }
  void sample(double t, std::span<double> x, const InputValue& r) const override;
  const EmpsPdParams& params() const { return p_; }
  const Plant& inner() const { return *inner_; }
  /// The compensator, or nullptr.
  const Compensator* compensator() const { return compensator_.get(); }

 private:
  static constexpr int kDiscrete = 6;  // the loop's own discrete states (see the class comment)
  std::shared_ptr<const Plant> inner_;
  EmpsPdParams p_;
  std::shared_ptr<const Compensator> compensator_;
  int n_inner_;
  int n_comp_ = 0;
};

}  // namespace frictionlab
