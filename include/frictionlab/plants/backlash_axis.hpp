#pragma once
// Axis with backlash: a motor inertia that drives a load inertia through a dead zone (gear or
// coupling play) of total width w. The motor moves freely across the gap; where the gap closes it
// strikes the load (a plastic impact, or one with a restitution coefficient), and while engaged
// the two move as one body until the force between them would pull instead of push. Impacts and
// separations are events of the plant, located exactly by the engine (no smoothing of the gap).
//
//   gap open:  Mm am = u - Fm,            Ml al = offset - Fl
//   engaged:   (Mm + Ml) a = u + offset - F
// where F is the friction on the side that has it (Fl on the load by default, or Fm on the motor)
// and the other side has none.

#include "frictionlab/plants/plant.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Which body of a backlash axis the friction acts on (the plant's contact, whose motion the
/// trajectory records).
enum class FrictionSide { load, motor };

/// Parameters of an axis with backlash.
struct BacklashParams {
  double M_load = 1.0;       ///< load inertia (kg or kg m^2), > 0. Default 1.
  double M_motor = 1.0;      ///< motor inertia (kg or kg m^2), > 0. Default 1.
  double width = 0.0;        ///< total play w (m or rad), > 0: the motor moves w between the two flanks
  double restitution = 0.0;  ///< coefficient of restitution e of an impact, 0 <= e < 1. Default 0 (plastic)
  double offset = 0.0;       ///< constant force on the load (N or N m), e.g. gravity. Default 0
  FrictionSide friction_side = FrictionSide::load;  ///< the body the friction acts on. Default the load
  double initial_gap = 0.0;  ///< motor position less load position at t = 0 (m or rad), |.| <= w/2. Default 0 (centred)
};

/// Axis with backlash between a motor (driven by the input force u, N or N m) and a load.
/// States: x[0], x[1] = position and velocity of the friction side's body (the contact), x[2],
/// x[3] = those of the other body, x[4] = the contact state: 0 while the gap is open, +1 while
/// the motor pushes the load forward (motor position = load position + w/2), -1 backward.
/// Events: 0 the motor reaches the forward flank, 1 the backward flank (impacts); 2 the engaged
/// bodies separate (the force the motor transmits to the load changes sign). Signals: reference =
/// u, drive = the force the motor transmits to the load (N or N m; 0 while the gap is open).
class BacklashAxis : public SingleContactPlant {
 public:
  /// \throws std::invalid_argument naming the first parameter out of range (inertias <= 0,
  /// width <= 0, restitution outside [0, 1), |initial_gap| > width / 2, a value not finite).
  explicit BacklashAxis(BacklashParams p);
  std::string type() const override { return "axis"; }
  int num_states() const override { return 5; }
  /// The contact's body alone (its inertia while the gap is open).
  double inertia(int = 0) const override;
  void initial_extras(std::span<double> x) const override;
  double applied(double t, std::span<const double> x, const InputValue& u) const override;
  void derivatives(double t, std::span<const double> x, const InputValue& u, double friction,
                   std::span<double> dx) const override;
  PlantSignals signals(double t, std::span<const double> x, const InputValue& u) const override;

  int num_events() const override { return 3; }
  /// Every event function is a guard (impacts close the gap, separation opens it).
  bool guard_event(int) const override { return true; }
  using SingleContactPlant::events;
  void events(double t, std::span<const double> x, Inputs u, std::span<const double> friction,
              std::span<double> g) const override;
  /// Impact (k = 0, 1): momentum is kept and the relative velocity reversed by the restitution
  /// (the contact's velocity changes); a plastic impact engages the flank. Separation (k = 2):
  /// the gap opens with both bodies at their common velocity.
  void on_event(double t, std::span<double> x, Inputs u, int k) const override;
  const BacklashParams& params() const { return p_; }
  /// State index of the motor's position (its velocity is the next state): 0 when the friction
  /// acts on the motor, else 2.
  int motor_state() const { return p_.friction_side == FrictionSide::motor ? 0 : 2; }
  /// State index of the load's position (its velocity is the next state): 0 or 2.
  int load_state() const { return 2 - motor_state(); }

  /// The force (N or N m) the motor transmits to the load while engaged, at input u and friction
  /// F on the contact; 0 while the gap is open.
  double transmitted(std::span<const double> x, double u, double friction) const;

 private:
  // Motor position less load position (m or rad).
  double gap(std::span<const double> x) const;
  BacklashParams p_;
};

}  // namespace frictionlab
