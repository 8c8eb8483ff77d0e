#pragma once
// A friction compensation named by its spec: its type as a scenario and the CLI name it, with its
// parameters (the options struct of control/*.hpp), and the compensator made from it for a law.
// The one list of compensation types: the scenario factory, the C export and the CLI use it.

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "frictionlab/control/compensator.hpp"
#include "frictionlab/control/disturbance_observer.hpp"
#include "frictionlab/control/feedback.hpp"
#include "frictionlab/control/feedforward.hpp"
#include "frictionlab/control/lugre_observer.hpp"
#include "frictionlab/models/friction_law.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// A compensation's type with its parameters (their units in control/*.hpp); std::monostate:
/// none.
using CompensationParams =
    std::variant<std::monostate, FeedforwardParams, FeedbackParams, LuGreObserverParams, DisturbanceObserverParams>;

/// The compensation types, as a scenario and the CLI name them, in CompensationParams' order:
/// "feedforward", "feedback", "lugre-observer", "disturbance-observer".
const std::vector<std::string>& compensation_types();

/// The compensation named `type` (one of compensation_types()) with the parameters in `values`,
/// named as the fields of its options struct (SI units): feedforward: band (m/s or rad/s);
/// feedback: dead_band (m/s or rad/s); lugre-observer: gain (1/s); disturbance-observer:
/// bandwidth (rad/s), inertia (kg or kg m^2). A parameter left out keeps its default; the
/// disturbance observer's inertia has none: `model_inertia` (the model's identified M, kg or
/// kg m^2) when given, else 0, which make_compensator refuses. Values are checked by
/// make_compensator (the compensator's constructor).
/// \throws std::invalid_argument "compensation 'TYPE' is not known; valid types: ..." and
///         "compensation feedforward has no parameter 'gain'; it has band".
CompensationParams make_compensation(std::string_view type, const std::map<std::string, double>& values = {},
                                     std::optional<double> model_inertia = std::nullopt);

/// The type name of `c` ("" for std::monostate).
std::string compensation_type(const CompensationParams& c);

/// The compensator `params` describe, compensating `law` (the model of the friction it cancels;
/// the disturbance observer uses none: null is fine there); nullptr for std::monostate.
/// \throws std::invalid_argument "compensation TYPE needs a friction law" when `law` is null for a
///         type that uses one, and what the compensator's constructor throws: a parameter that
///         breaks its rule ("feedforward: band = -1 must be > 0 (m/s or rad/s)"), a law that does
///         not fit ("lugre-observer: law = stribeck must be lugre ..."), "disturbance-observer:
///         inertia = 0 must be > 0 ...".
std::shared_ptr<const Compensator> make_compensator(const CompensationParams& params, const FrictionLaw* law);

}  // namespace frictionlab
