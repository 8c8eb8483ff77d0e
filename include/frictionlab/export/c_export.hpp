#pragma once
// Code for the drive: a friction law and, optionally, one friction compensation written as one
// dependency-free C99 header (static inline functions, the parameters as static const constants,
// no allocation, nothing from libc beyond math.h) that a drive's firmware includes as it is.
//
// The header computes what the library computes, with the same formulas in the same order:
//   PREFIX_friction(v)                   the law's force at velocity v (N or N m; sign of v): a
//                                        static law's sliding force, a dynamic law's steady-state
//                                        force (FrictionLaw::sliding); each direction its own
//                                        parameters for an asymmetric law
//   PREFIX_friction_stuck(v, applied)    static laws: the force with stiction (friction_force in
//                                        models/static_law.hpp; Karnopp's band), and
//   PREFIX_breakaway_pos(), _neg()       the breakaway levels (N or N m)
//   PREFIX_state, PREFIX_init(&s), PREFIX_update(&s, v, dt)
//                                        dynamic laws: the state (m or rad), zero at start, and
//                                        the fixed-step update at constant v over dt seconds
//                                        (FrictionLaw::step: stable for any dt), returning the
//                                        force at the end of the step
//   PREFIX_ripple(q), PREFIX_friction_at(v[, q][, load][, T]), PREFIX_breakaway_pos_at([load][, T]),
//   PREFIX_breakaway_neg_at(...)         a law with a position ripple (q in m or rad) and a static
//                                        law with load (N or N m) or temperature (degC or K)
//                                        terms: the force with the levels moved (sliding(v, c) +
//                                        ripple(q)); the arguments are the terms the law has
//   PREFIX_feedforward(vr) / PREFIX_feedback(v), and with load or temperature terms
//   PREFIX_feedforward_at(vr[, load][, T]) / PREFIX_feedback_at(v[, load][, T])
//   PREFIX_lugre_observer_state, _init(&s, v), _update(&s, x, v, r, dt)
//   PREFIX_disturbance_observer_state, _init(&s, v), _update(&s, v, drive, dt)
//                                        the compensations' update() (control/*.hpp)
// Units: SI, linear axis N, m, m/s, N s/m, N/m; rotary axis N m, rad, rad/s, N m s/rad, N m/rad;
// dt in s. Sign convention: friction has the sign of the velocity and is subtracted
// (M a = drive - F); a compensation's output estimates F and is ADDED to the drive's command.

#include <string>

#include "frictionlab/control/compensation_spec.hpp"
#include "frictionlab/models/friction_law.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Options of c_header.
struct CExportOptions {
  /// Prefix of every name in the header (functions, constants, types, include guard):
  /// a C identifier [A-Za-z][A-Za-z0-9_]*, at most 40 characters. Default "friction".
  std::string prefix = "friction";
  /// Single precision: `float` states, constants and math (expf, ...) for FPUs without double;
  /// the results then agree with the library's to float's precision only. Default false (double).
  bool single_precision = false;
  /// The compensation, if any (control/compensation_spec.hpp: make_compensation). Default none.
  CompensationParams compensation;
  /// Where the law came from (a MODEL.json path), quoted in the header's first comment. Optional.
  std::string source;
};

/// The C99 header text (see the top of this file) for `law` and options.compensation.
/// Every static and dynamic law of the library is supported (GMS with its N elements), with a
/// position ripple, and a static law with load and temperature terms.
/// \throws std::invalid_argument for a prefix that is not a C identifier (naming it), and what the
///         compensation's constructor throws for parameters that break its rules or do not fit
///         the law ("lugre-observer: law = stribeck must be lugre ...", "disturbance-observer:
///         inertia = 0 must be > 0 ..."); InputError (law.parameter, key mu_load or T_ref) for a
///         dynamic law with load or temperature terms (its state update runs on fixed levels), and
///         (key ripple_period) for a compensation of a law with a ripple; InputError
///         (output.not_finite) for a constant that is not finite or, with single_precision, beyond
///         float's range, naming the constant; std::invalid_argument for a nonzero constant below
///         float's smallest magnitude with single_precision; InputError (output.not_finite, key
///         sigma0), with single_precision, for a bristle law whose sigma0 / Fc exceeds 1e15 (its rate would overflow
///         float at a finite speed).
std::string c_header(const FrictionLaw& law, const CExportOptions& options = {});

}  // namespace frictionlab
