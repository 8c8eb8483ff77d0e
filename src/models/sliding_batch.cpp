// FrictionLaw::sliding over arrays: the law's type is resolved once per call, then a plain loop
// over its inline scalar formula (which the compiler may vectorise where the formula allows), so
// each value equals the scalar call's to the bit on every CPU.

#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

#include "frictionlab/models/friction_law.hpp"

namespace frictionlab {

void FrictionLaw::sliding(std::span<const double> v, std::span<double> F) const {
  if (F.size() != v.size())
    throw std::invalid_argument("FrictionLaw::sliding: F (N or N m) has " + std::to_string(F.size()) +
                                " values but v (m/s or rad/s) has " + std::to_string(v.size()) +
                                "; they must have the same length");
  std::visit(
      [&](const auto& law) {
        using Law = std::decay_t<decltype(law)>;
        if constexpr (DynamicLaw<Law>) {
          // The steady state of a dynamic law, as the scalar call computes it.
          for (std::size_t i = 0; i < v.size(); ++i) F[i] = sliding(v[i]);
        } else {
          for (std::size_t i = 0; i < v.size(); ++i) F[i] = law.sliding(v[i]);
        }
      },
      variant());
}

}  // namespace frictionlab
