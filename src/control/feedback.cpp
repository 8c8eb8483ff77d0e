#include "frictionlab/control/feedback.hpp"

#include <cmath>

namespace frictionlab {

FeedbackCompensation::FeedbackCompensation(FrictionLaw law, FeedbackParams p)
    : BandCompensation(std::move(law), p.dead_band), p_(p) {
  detail::require(std::isfinite(p.dead_band) && p.dead_band > 0, "feedback", "dead_band", p.dead_band,
                  "> 0 (m/s or rad/s)");
}

}  // namespace frictionlab
