#pragma once
// The unit of a figure of a result's diagnostics groups (Result::diagnostics.groups), for the
// text output and the report: the JSON keeps these figures bare (docs/contract.md names them),
// and a reader of `readoff: Fc = 0.0012` must not guess N or N m.

#include <string>

#include "frictionlab/export.hpp"
#include "frictionlab/identify/result.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The unit of r.diagnostics.groups[group][key], on the result's axis: a read-off or an estimate
/// of a parameter in the parameter's unit (breakaway's readoff, IDIM-IV's ls_estimate, lugre's
/// start, multistart and static_fit), the controller IDIM-IV simulated (iv_controller) in its
/// options' units as the run decided them (the recorded options, r.json_sections["options"]:
/// kp in 1/s with emps-pd; sample_period in s), a relative error in %, the resampling's steps in s,
/// the rate defaults' cutoff in Hz and skip in samples, the residual checks' residual_std in the
/// fit's unit and standstill_speed in m/s or rad/s; "" for a pure number (a correlation, such as
/// iv_instrument_correlation's, a count, a share) and for a figure it does not know. Never throws (unreadable recorded options give "").
std::string diagnostic_unit(const Result& r, const std::string& group, const std::string& key);

}  // namespace frictionlab
