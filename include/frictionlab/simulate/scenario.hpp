#pragma once
// A complete simulation problem: plant, friction law, input and options.

#include <memory>

#include "frictionlab/models/friction_law.hpp"
#include "frictionlab/plants/plant.hpp"
#include "frictionlab/simulate/input.hpp"
#include "frictionlab/simulate/options.hpp"

namespace frictionlab {

/// Everything simulate() needs. Scenario files (io/scenario.hpp) produce one.
struct Scenario {
  std::shared_ptr<const Plant> plant;  ///< required (closed loops are plants too)
  FrictionLaw law;                     ///< friction on the plant's friction body
  InputSignal input;                   ///< plant input, or the reference of a closed loop
  SimulationOptions options;
};

}  // namespace frictionlab
