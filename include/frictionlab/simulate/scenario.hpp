#pragma once
// A complete simulation problem: plant, friction law, input and options.

#include <memory>
#include <vector>

#include "frictionlab/models/friction_law.hpp"
#include "frictionlab/plants/plant.hpp"
#include "frictionlab/core/input.hpp"
#include "frictionlab/simulate/options.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Everything simulate() needs. Scenario files (scenario/scenario.hpp) produce one.
struct Scenario {
  std::shared_ptr<const Plant> plant;  ///< required (closed loops are plants too)
  FrictionLaw law;                     ///< friction on every contact whose Contact::law is null
  InputSignal input;                   ///< a 1-input plant's input, or the reference of a closed loop
  /// The inputs of a plant with num_inputs() > 1 (exactly that many). Empty for a 1-input plant
  /// (then `input` is used; a single entry is accepted in its place).
  std::vector<InputSignal> inputs;
  SimulationOptions options;
};

}  // namespace frictionlab
