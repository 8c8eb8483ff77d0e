#pragma once
// What the feedforward and feedback compensations share: a friction law evaluated at a velocity s
// (the reference's or the measured one), with a different formula inside a band |s| <= b, and
// the band's edges as events.

#include <span>

#include "frictionlab/control/compensator.hpp"
#include "frictionlab/models/friction_law.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Output = the law's sliding force F(s) (steady-state force for dynamic laws; each direction its
/// own parameters for asymmetric laws) for |s| > b, and the derived class's formula inside.
/// One own state, discrete: the band region of s (-1 below -b, 0 inside, +1 above b), switched by
/// two events, g0 = s - b and g1 = s + b, so the edges are located exactly. At an event the region
/// goes to the side ds/dt points to where the derived class knows it, else crosses the edge. A
/// stored region more than 1 % of b off s (a run whose start did not see s) gives way to the region
/// of s itself, so the output is right before the first event. update() takes the region from s.
/// A law with load or temperature terms is evaluated at the input's load and temperature
/// (CompensatorInput::load, ::temperature; no temperature = the law's T_ref), both inside and
/// outside the band. A law with a position ripple adds r(q) at the derived class's position q
/// (ripple_position: the reference's or the measured one) inside the band as well as outside it,
/// since the ripple acts whether the contact slides or sticks: output = force(s, c) + r(q).
class BandCompensation : public Compensator {
 public:
  int num_states() const override { return 1; }
  void initial_states(const CompensatorInput& in, std::span<double> z) const override;
  double output(const CompensatorInput& in, std::span<const double> z) const override;
  int num_events() const override { return 2; }
  void events(const CompensatorInput& in, std::span<const double> z, std::span<double> g) const override;
  void on_event(const CompensatorInput& in, std::span<double> z, int k) const override;
  double update(const CompensatorInput& in, std::span<double> z, double dt) const override;

  /// The velocity part of the compensation force (N or N m) at velocity s (m/s or rad/s), the
  /// region taken from s, at conditions `c` (load N or N m, temperature degC or K; the position is
  /// not used): output() is this plus the law's ripple r(q), law().ripple(q), at ripple_position.
  /// \throws InputError (law.parameter) when the temperature lies outside the law's [T_min, T_max]
  ///         or makes a coefficient negative.
  double force(double s, const Conditions& c = {}) const;
  const FrictionLaw& law() const { return law_; }

 protected:
  /// Validation of b is the derived class's (it names its own parameter).
  BandCompensation(FrictionLaw law, double band) : law_(std::move(law)), band_(band) {}
  /// The velocity s the output switches on (m/s or rad/s).
  virtual double speed(const CompensatorInput& in) const = 0;
  /// The position q the ripple r(q) is taken at (m or rad).
  virtual double ripple_position(const CompensatorInput& in) const = 0;
  /// The sign of ds/dt where known, else 0.
  virtual double speed_direction(const CompensatorInput&) const { return 0.0; }
  /// The output inside the band (N or N m) at conditions c.
  virtual double inside(double s, const Conditions& c) const = 0;
  /// The conditions of `in` (its load and temperature).
  static Conditions conditions(const CompensatorInput& in) {
    Conditions c;
    c.load = in.load;
    c.temperature = in.temperature;
    c.position = in.position;
    return c;
  }

  FrictionLaw law_;
  double band_;  ///< b (m/s or rad/s)

 private:
  double force_in(double region, double s, const Conditions& c) const {
    return region == 0.0 ? inside(s, c) : law_.sliding(s, c);
  }
};

}  // namespace frictionlab
