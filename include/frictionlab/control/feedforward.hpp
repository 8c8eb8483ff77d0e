#pragma once
// Feedforward friction compensation: the friction law evaluated at the reference velocity, with a
// linear smoothing band around zero velocity.

#include <span>
#include <string>

#include "frictionlab/control/compensator.hpp"
#include "frictionlab/models/friction_law.hpp"

namespace frictionlab {

/// Options of the feedforward compensation.
struct FeedforwardParams {
  /// Half-width b of the smoothing band (m/s or rad/s), finite and > 0. Default 1e-3, the Stribeck
  /// velocity of a lubricated guide (Canudas de Wit et al. 1995, Table I). Inside |dr/dt| < b the
  /// output runs linearly from the law's force at -b to its force at +b, so a reference that dwells
  /// near rest does not switch the full breakaway force back and forth (chatter); outside it is the
  /// law itself. A wider band chatters less and compensates less of the reversals' friction.
  double band = 1e-3;
};

/// Output = F(dr/dt): the law's sliding force (steady-state force for dynamic laws; each direction
/// its own parameters for asymmetric laws) at the reference velocity for |dr/dt| >= b, and
///   F(-b) + (F(b) - F(-b)) (dr/dt + b) / (2 b)   inside the band (continuous at +-b; the mean of
/// the two levels at rest, 0 for a symmetric law).
/// One own state, discrete: the band region of dr/dt (-1 below -b, 0 inside, +1 above b), switched
/// by two events, g0 = dr/dt - b and g1 = dr/dt + b, so the kinks at +-b are located exactly. At an
/// event the region goes to the side the reference's acceleration points to (crosses the edge when
/// it is 0). A stored region more than 1 % of b off dr/dt (a run whose start did not see the
/// reference) gives way to the region of dr/dt itself, so the output is right before the first event.
class FeedforwardCompensation : public Compensator {
 public:
  /// \throws std::invalid_argument "feedforward: band = VALUE must be > 0 (m/s or rad/s)" when the
  ///         band is not finite and > 0.
  explicit FeedforwardCompensation(FrictionLaw law, FeedforwardParams p = {});

  std::string type() const override { return "feedforward"; }
  int num_states() const override { return 1; }
  void initial_states(const CompensatorInput& in, std::span<double> z) const override;
  double output(const CompensatorInput& in, std::span<const double> z) const override;
  int num_events() const override { return 2; }
  void events(const CompensatorInput& in, std::span<const double> z, std::span<double> g) const override;
  void on_event(const CompensatorInput& in, std::span<double> z, int k) const override;
  /// The output depends on the reference only: every entry is 0.
  bool jacobian(const CompensatorInput& in, std::span<const double> z, std::span<double> doutput,
                std::span<double> dderiv) const override;
  double update(const CompensatorInput& in, std::span<double> z, double dt) const override;

  /// The compensation force (N or N m) at reference velocity vr (m/s or rad/s), the region taken from vr.
  double force(double vr) const;
  const FrictionLaw& law() const { return law_; }
  const FeedforwardParams& params() const { return p_; }

 private:
  double force_in(double region, double vr) const;
  FrictionLaw law_;
  FeedforwardParams p_;
  double at_plus_;   // F(+b), N or N m
  double at_minus_;  // F(-b)
};

}  // namespace frictionlab
