#pragma once
// Feedforward friction compensation: the friction law evaluated at the reference velocity, with a
// linear smoothing band around zero velocity.

#include <span>
#include <string>

#include "frictionlab/control/band_compensation.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Options of the feedforward compensation.
struct FeedforwardParams {
  /// Half-width b of the smoothing band (m/s or rad/s), finite and > 0. Default 1e-3, the Stribeck
  /// velocity of a lubricated guide (Canudas de Wit et al. 1995, Table I). Inside |dr/dt| <= b the
  /// output runs linearly from the law's force at -b to its force at +b, so a reference that dwells
  /// near rest does not switch the full breakaway force back and forth (chatter); outside it is the
  /// law itself. A wider band chatters less and compensates less of the reversals' friction.
  double band = 1e-3;
};

/// Output = F(dr/dt), the law at the reference velocity, for |dr/dt| > b, and
///   F(-b) + (F(b) - F(-b)) (dr/dt + b) / (2 b)   inside the band (continuous at +-b; the mean of
/// the two levels at rest, 0 for a symmetric law). The band's region is the one own state
/// (BandCompensation); an edge event takes its direction from the reference's acceleration.
/// A law with load or temperature terms is evaluated at the input's load (measured, or estimated
/// from the plant's known load function by the loop) and temperature (measured; none = T_ref).
/// A law with a position ripple adds r(q) at q = the reference position (CompensatorInput::
/// reference), in and outside the band: the force the axis meets where the reference puts it.
class FeedforwardCompensation : public BandCompensation {
 public:
  /// \throws std::invalid_argument "feedforward: band = VALUE must be > 0 (m/s or rad/s)" when the
  ///         band is not finite and > 0.
  explicit FeedforwardCompensation(FrictionLaw law, FeedforwardParams p = {});

  std::string type() const override { return "feedforward"; }
  /// The output depends on the reference only (its ripple too): every entry is 0. Returns false
  /// (no analytic form) for a law with load or temperature terms, whose load may follow the plant's state.
  bool jacobian(const CompensatorInput& in, std::span<const double> z, std::span<double> doutput,
                std::span<double> dderiv) const override;
  const FeedforwardParams& params() const { return p_; }

 protected:
  double speed(const CompensatorInput& in) const override { return in.reference_rate; }
  double speed_direction(const CompensatorInput& in) const override { return in.reference_accel; }
  double ripple_position(const CompensatorInput& in) const override { return in.reference; }
  double inside(double vr, const Conditions& c) const override;

 private:
  FeedforwardParams p_;
  double at_plus_;   // F(+b), N or N m
  double at_minus_;  // F(-b)
};

}  // namespace frictionlab
