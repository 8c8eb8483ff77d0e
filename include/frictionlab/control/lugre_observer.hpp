#pragma once
// Observer-based friction compensation of Canudas de Wit, Olsson, Astrom and Lischinsky (1995),
// section V: a copy of the LuGre bristle state, driven by the measured velocity and corrected by
// the position error, whose friction force the loop adds to its command.

#include <optional>
#include <span>
#include <string>

#include "frictionlab/control/compensator.hpp"
#include "frictionlab/models/friction_law.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Options of the LuGre observer.
struct LuGreObserverParams {
  /// Observer gain k (1/s: bristle rate, m/s or rad/s, per metre or radian of position error),
  /// finite and >= 0. Default 0.01 (the value the hunting test of tests/control uses). k = 0 runs
  /// the model open loop (the estimate then follows the true friction only as far as the model's
  /// state does); k > 0 makes the estimate integrate the position error while the body is at rest
  /// (force rate sigma0 k e), the term that lets section V's compensated loop reach the
  /// reference: the larger k, the faster, and the less margin.
  double gain = 0.01;
};

/// With e = x - r (position error) and the law's g(v), sigma1(v) (LuGreT):
///   dz^/dt = v - sigma0 |v| z^ / g(v) - k e
///   output F^ = sigma0 z^ + sigma1(v) dz^/dt + sigma2 v       (N or N m)
/// One own state, continuous: z^ (m or rad), starting at the law's steady state at the first
/// measured velocity (0 at rest). No events: the output is continuous in v.
/// A law with a position ripple adds r(x), its ripple at the measured position
/// (CompensatorInput::position), to F^, as the feedback compensation does: the ripple is a known
/// function of the position and acts whether the body slides or sticks, so the bristle copy and
/// its position-error integral are left with what the model does not know.
class LuGreObserver : public Compensator {
 public:
  /// \throws std::invalid_argument "lugre-observer: law = NAME must be lugre ..." when the law is
  ///         not LuGre, and "lugre-observer: gain = VALUE must be >= 0 (1/s)" for a bad gain.
  explicit LuGreObserver(const FrictionLaw& law, LuGreObserverParams p = {});

  std::string type() const override { return "lugre-observer"; }
  int num_states() const override { return 1; }
  void initial_states(const CompensatorInput& in, std::span<double> z) const override;
  double output(const CompensatorInput& in, std::span<const double> z) const override;
  void derivatives(const CompensatorInput& in, std::span<const double> z, std::span<double> dz) const override;
  bool jacobian(const CompensatorInput& in, std::span<const double> z, std::span<double> doutput,
                std::span<double> dderiv) const override;
  /// Exact over the step at the held v and e (z^ relaxes exponentially, or ramps at v = 0).
  double update(const CompensatorInput& in, std::span<double> z, double dt) const override;

  const LuGre& law() const { return law_; }
  /// The ripple the output carries (the law's), or none.
  const std::optional<PositionRipple>& ripple() const { return ripple_; }
  const LuGreObserverParams& params() const { return p_; }

 private:
  LuGre law_;
  std::optional<PositionRipple> ripple_;  ///< the law's ripple, if it has one
  LuGreObserverParams p_;
};

}  // namespace frictionlab
