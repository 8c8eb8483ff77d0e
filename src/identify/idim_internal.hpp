#pragma once
// Private pieces of IDIM (src/identify/idim.cpp) shared with IDIM-IV (src/identify/idim_iv.cpp).

#include <Eigen/Core>

#include "frictionlab/identify/idim.hpp"
#include "frictionlab/identify/result.hpp"

namespace frictionlab::detail {

/// Sets r.law from r's parameter values (Fs = Fc + Fs_minus_Fc with the Stribeck term), or leaves
/// it unset with a warning when the values break a law's rules. `vs`: the Stribeck velocity used.
void attach_idim_law(Result& r, const IdimOptions& o, double vs);

/// The figure series of a fit (time, force, force_model, friction, friction_model) from the
/// regression `reg` and the parameters `theta` (column order).
void set_idim_series(Result& r, const IdimData& data, const IdimRegression& reg, const Eigen::VectorXd& theta,
                     const IdimOptions& options);

/// The figure series of the condition terms, at the fitted samples of series "time" (nothing
/// without the terms or on an error result): "load" (|F_load|, N or N m) and
/// "law_force_zero_load" (the law curve at zero load) with the load term; "temperature" (degC or
/// K) and "temperature_viscous" (Fv + Fv_per_K (T - T_ref)) with the temperature term;
/// "ripple_position" (the position within the period, m or rad), "ripple_partial" (the fit's
/// residual plus the identified ripple, N or N m), "ripple_curve_position" and
/// "ripple_curve_force" (the identified ripple over one period) with the ripple term.
void add_idim_condition_series(Result& r, const IdimData& data, const IdimOptions& o);

/// The warnings on the parameters' values: poorly identified (std above half the value), negative
/// where a coefficient must not be.
void add_idim_parameter_warnings(Result& r);

/// The checks of IDIM-IV's inputs before anything is computed (options.iv.enabled).
/// \throws InputError naming the missing controller or reference (and what to give), a reference
///         or feedforward of another length than time or not finite, or a term IDIM-IV cannot
///         simulate.
void check_idim_iv_inputs(const IdimData& data, const IdimOptions& options);

/// IDIM-IV (IdimIvOptions) on the ok least-squares result `r` of `data` with the resolved
/// options `o` and mean step dt (s): replaces its values, std, fit figures and series with the IV
/// ones and adds the IV diagnostics, or sets status error (not converged, a simulation that fails).
void run_idim_iv(Result& r, const IdimData& data, const IdimOptions& o, double dt);

}  // namespace frictionlab::detail
