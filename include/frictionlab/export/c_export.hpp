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
//   PREFIX_feedforward(vr) / PREFIX_feedback(v)
//   PREFIX_lugre_observer_state, _init(&s, v), _update(&s, x, v, r, dt)
//   PREFIX_disturbance_observer_state, _init(&s, v), _update(&s, v, drive, dt)
//                                        the compensations' update() (control/*.hpp)
// Units: SI, linear axis N, m, m/s, N s/m, N/m; rotary axis N m, rad, rad/s, N m s/rad, N m/rad;
// dt in s. Sign convention: friction has the sign of the velocity and is subtracted
// (M a = drive - F); a compensation's output estimates F and is ADDED to the drive's command.

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "frictionlab/control/disturbance_observer.hpp"
#include "frictionlab/control/feedback.hpp"
#include "frictionlab/control/feedforward.hpp"
#include "frictionlab/control/lugre_observer.hpp"
#include "frictionlab/models/friction_law.hpp"

#include "frictionlab/export.hpp"
namespace FRICTIONLAB_API frictionlab {

/// The compensation to export beside the law, with its parameters (their units in control/*.hpp);
/// std::monostate: the law alone.
using CompensationParams =
    std::variant<std::monostate, FeedforwardParams, FeedbackParams, LuGreObserverParams, DisturbanceObserverParams>;

/// Options of c_header.
struct CExportOptions {
  /// Prefix of every name in the header (functions, constants, types, include guard):
  /// a C identifier [A-Za-z][A-Za-z0-9_]*, at most 40 characters. Default "friction".
  std::string prefix = "friction";
  /// Single precision: `float` states, constants and math (expf, ...) for FPUs without double;
  /// the results then agree with the library's to float's precision only. Default false (double).
  bool single_precision = false;
  /// The compensation, if any. Default none.
  CompensationParams compensation;
  /// Where the law came from (a MODEL.json path), quoted in the header's first comment. Optional.
  std::string source;
};

/// The compensation types c_header knows, as a scenario and the CLI name them:
/// "feedforward", "feedback", "lugre-observer", "disturbance-observer".
const std::vector<std::string>& compensation_types();

/// The compensation named `type` (one of compensation_types()) with the parameters in `values`,
/// named as the fields of its options struct (SI units): feedforward: band (m/s or rad/s);
/// feedback: dead_band (m/s or rad/s); lugre-observer: gain (1/s); disturbance-observer:
/// bandwidth (rad/s), inertia (kg or kg m^2). A parameter left out keeps its default; the
/// disturbance observer's inertia has none: `model_inertia` (the model's identified M, kg or
/// kg m^2) when given, else 0, which c_header refuses. Values are checked by c_header.
/// \throws std::invalid_argument "compensation 'TYPE' is not known; valid types: ..." and
///         "compensation feedforward has no parameter 'gain'; it has band".
CompensationParams make_compensation(std::string_view type, const std::map<std::string, double>& values = {},
                                     std::optional<double> model_inertia = std::nullopt);

/// A model file as the export reads it: its law and, when the file has one (the MODEL.json of
/// `identify idim` or `decay`), the identified inertia M (kg or kg m^2), the disturbance
/// observer's default.
struct ExportModel {
  FrictionLaw law;
  std::optional<double> inertia;
};

/// Reads MODEL.json (read_model_json, law_from_json: the strict model reader) or a law file
/// (.yaml/.yml through load_law). \throws std::invalid_argument naming the file.
ExportModel read_export_model(const std::string& path);

/// The type name of `c` ("" for std::monostate).
std::string compensation_type(const CompensationParams& c);

/// The C99 header text (see the top of this file) for `law` and options.compensation.
/// Every static and dynamic law of the library is supported (GMS with its N elements).
/// \throws std::invalid_argument for a prefix that is not a C identifier (naming it), and what the
///         compensation's constructor throws for parameters that break its rules or do not fit
///         the law ("lugre-observer: law = stribeck must be lugre ...", "disturbance-observer:
///         inertia = 0 must be > 0 ...").
std::string c_header(const FrictionLaw& law, const CExportOptions& options = {});

}  // namespace frictionlab
