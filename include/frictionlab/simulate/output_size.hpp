#pragma once
// How large a run's output is, and the largest simulate() accepts: checked before anything is
// allocated, so that `duration: 1e9` is a clear error naming the memory it would need rather
// than an out-of-memory failure.

#include <string>

#include "frictionlab/budget.hpp"
#include "frictionlab/simulate/options.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Rows a run outputs: floor(duration * output_rate) + 1, as a double (it may not fit a size_t).
double output_rows(const SimulationOptions& o);

/// Memory (bytes) a run's output takes: output_rows * (9 + law_states) columns * 8 bytes.
double output_bytes(const SimulationOptions& o, int law_states = 0);

/// The largest output (bytes) simulate() accepts: the memory budget (frictionlab/budget.hpp).
/// simulate() throws InputError (budget.memory) for a larger one.
double max_output_bytes();

}  // namespace frictionlab
