#pragma once
// Validation of a two-axis machine's models on a circular test: the scenario (an xy-table whose
// axes carry the identified models, scenario/scenario.hpp ScenarioOptions::axis_models) is simulated
// over a measured run and compared axis by axis (identify/validate.hpp validate_axes), and the
// contour of the measured and of the simulated path (analysis/contour.hpp: quadrant glitches,
// roundness) are compared against the scenario's reference.

#include <map>
#include <optional>
#include <string>

#include "frictionlab/analysis/contour.hpp"
#include "frictionlab/identify/result.hpp"
#include "frictionlab/identify/validate.hpp"
#include "frictionlab/simulate/scenario.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Result of validate_contour.
struct ContourValidation {
  /// validate_axes's result; when the reference is a circle, its validation has the JSON section
  /// "contour": {"measured": {...}, "simulated": {...}} (each contour_json, m), "difference":
  /// {"max_quadrant_glitch_m", "roundness_m", "max_radial_error_m"} (simulated less measured, m)
  /// and "relative_error_percent": {"radial_error": 100 ||e - e_sim|| / ||e||} (the radial error
  /// traces, every sample), and diagnostics.numbers "max_quadrant_glitch_m",
  /// "max_quadrant_glitch_sim_m", "roundness_m", "roundness_sim_m" (m) and
  /// "radial_error_relative_error_percent" (%).
  Result result;
  /// The circular test of the measured and of the simulated path about the reference's centre
  /// and radius; nullopt when the reference is not a circle of at least one turn (a path), or
  /// a path does not close a turn (a warning in the result then says why).
  std::optional<ContourResult> measured, simulated;
};

/// Validates the models of a two-axis plant on a measured run. `data` must have the axes "x" and
/// "y" (their positions, m; forces optional). Units and errors as validate_axes.
/// \throws std::invalid_argument as validate_axes, and naming the missing axis when "x" or "y"
///         is absent from `data`; std::runtime_error when the simulation fails.
ContourValidation validate_contour(const Scenario& scenario, const MultiAxisValidationData& data,
                                   const std::map<std::string, IdentifiedModel>& models,
                                   const ValidateOptions& options = {});

}  // namespace frictionlab
