#pragma once
// The EMPS benchmark's discrete controller (control/emps_pd.hpp) closed around a plant, sampled
// every dt seconds, its output v(k) applied from sample k + delay on and held between samples;
// the plant's input is gtau * v (force, N, for an axis). The scenario input is the reference qg
// (m). Built by close_loop (simulate/closed_loop.hpp) or directly.

#include <memory>

#include "frictionlab/control/compensator.hpp"
#include "frictionlab/control/emps_pd.hpp"
#include "frictionlab/plants/plant.hpp"
#include "frictionlab/simulate/compensation_conditions.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

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
/// inside the saturation. Its states follow the 6 discrete ones (the sixth: qg(k-1), m). A law
/// with load or temperature terms is compensated at the load and temperature that with_conditions()
/// gives (sampled with the measurement; without them: load 0 and the law's T_ref).
class EmpsPdLoop : public SingleContactPlant {
 public:
  /// \throws std::invalid_argument when `inner` is null, kinematic or not 1-DOF, or as
  ///         EmpsPdParams::validate (a parameter out of range: the message names it, its value and unit).
  EmpsPdLoop(std::shared_ptr<const Plant> inner, EmpsPdParams p, std::shared_ptr<const Compensator> compensator = nullptr);
  std::string type() const override { return inner_->type(); }
  Axis motion_axis() const override { return inner_->motion_axis(); }
  int num_states() const override { return n_inner_ + kDiscrete + n_comp_; }
  using SingleContactPlant::initial_extras;
  void initial_extras(std::span<double> x, Inputs u) const override;
  double inertia(int = 0) const override { return inner_->inertia(); }
  double applied(double t, std::span<const double> x, const InputValue& r) const override;
  void derivatives(double t, std::span<const double> x, const InputValue& r, double friction,
                   std::span<double> dx) const override;
  PlantSignals signals(double t, std::span<const double> x, const InputValue& r) const override;
  double sample_period() const override { return pd_.params().dt; }
  void sample(double t, std::span<double> x, const InputValue& r) const override;
  const EmpsPdParams& params() const { return pd_.params(); }
  const Plant& inner() const { return *inner_; }
  /// The compensator, or nullptr.
  const Compensator* compensator() const { return compensator_.get(); }
  /// This loop with its compensator given the conditions `c` (replacing any it had).
  std::shared_ptr<const EmpsPdLoop> with_conditions(CompensationConditions c) const;
  const CompensationConditions& conditions() const { return conditions_; }

 private:
  CompensatorInput measured(double t, std::span<const double> x) const;

  static constexpr int kDiscrete = EmpsPd::kStates;  // the controller's own discrete states
  std::shared_ptr<const Plant> inner_;
  EmpsPd pd_;
  std::shared_ptr<const Compensator> compensator_;
  CompensationConditions conditions_;
  int n_inner_;
  int n_comp_ = 0;
};

}  // namespace frictionlab
