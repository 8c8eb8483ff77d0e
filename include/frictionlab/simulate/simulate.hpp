#pragma once
// The simulation engine: one entry point for every plant and law.
//
// Static laws with stiction (hybrid mode). The body is either stuck or sliding in a direction s:
//  - stuck: velocity is exactly 0, position is frozen, friction = applied; the plant's other
//    states (motor current, controller integrator, base position) keep evolving. Root functions
//    applied - breakaway_positive (rising) and applied + breakaway_negative (falling) end it: the
//    switch to sliding happens at the instant applied reaches the level, located by CVODE's root
//    finder to about 100 unit roundoffs of t.
//  - sliding in s: friction = sliding(v), with its one-sided limit at v -> 0 from the s side
//    (so the right-hand side stays smooth across the step that finds the zero). The root
//    function v (crossing towards 0) ends it at the instant v = 0: velocity is set to exactly 0,
//    then the body sticks if -breakaway_negative <= applied <= breakaway_positive at that state,
//    otherwise it slides on in the direction of applied (reversal).
//  After every switch (and at every corner of the input) CVODE is re-initialised from the exact
//  state, so there is no creep, no chatter, and no tiny steps near v = 0.
// Several contacts (Plant::num_contacts() > 1): each contact has its own mode, frozen position
// and pair of root functions (2 per contact), and its own law (Contact::law, else the law given
// to simulate()). By the plant's contract a contact's applied force does not depend on any
// friction force, so each stuck contact is decided from its own applied force, alone. Dynamic
// laws' states follow the plant's states, contact by contact.
// The plant's own event functions (Plant::events) are root functions too: at a root the engine
// calls Plant::on_event, decides the stuck contacts again (their applied force may have jumped),
// records a PlantEvent and restarts CVODE.
// Continuous static laws and dynamic laws: CVODE BDF with dense Newton; with a dynamic law and a
// plant that has an analytic Jacobian the exact Newton matrix (StiffSystem), refreshed at every
// update, else difference quotients. Output rows inside a step come from the step's polynomial.
// Fixed-step mode: see SolverMode::fixed_step; each contact steps with its own law, and a plant
// event fires (on_event) at the first step after its function changed sign.

#include "frictionlab/models/friction_law.hpp"
#include "frictionlab/plants/plant.hpp"
#include "frictionlab/core/input.hpp"
#include "frictionlab/simulate/options.hpp"
#include "frictionlab/simulate/scenario.hpp"
#include "frictionlab/simulate/trajectory.hpp"

#include <span>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Simulates `plant` with friction `law` driven by `input`.
/// \returns rows at t = k / output_rate (see SimulationOptions).
/// \throws std::invalid_argument for bad options (non-positive duration, rate, tolerance or step,
///         a dt that does not divide the output period, a solver mode that does not fit the law),
///         naming the option and its value;
///         std::runtime_error when the integrator fails ("simulation failed at t = T s: REASON");
///         nothing partial is returned.
///         std::invalid_argument too when the plant takes more than one input; InputError
///         (output.not_finite, naming the column and the time) when a column would hold an inf or
///         NaN (a parameter beyond double precision).
Trajectory simulate(const Plant& plant, const FrictionLaw& law, const InputSignal& input,
                    const SimulationOptions& options);

/// Simulates `plant` driven by `inputs` (one per plant input, Plant::num_inputs()); `law` is the
/// friction of every contact whose Contact::law is null. Each contact has its own mode (stuck,
/// sliding) and switches; ModeSwitch::contact says which switched.
/// \throws what the one-input form throws, and std::invalid_argument naming the plant type and
///         both counts when inputs.size() != plant.num_inputs(), or when the plant's contacts are
///         malformed (a state index out of range or shared, an unnamed contact among several).
Trajectory simulate(const Plant& plant, const FrictionLaw& law, std::span<const InputSignal> inputs,
                    const SimulationOptions& options);

/// simulate(*scenario.plant, scenario.law, inputs, scenario.options) with inputs = {scenario.input}
/// for a one-input plant (or scenario.inputs when it has one entry), scenario.inputs otherwise.
/// \throws std::invalid_argument when scenario.plant is null, when scenario.inputs does not have
///         the plant's input count, and what the other forms throw.
Trajectory simulate(const Scenario& scenario);

/// The solver mode for several contacts' laws: automatic gives hybrid when any law has stiction,
/// else stiff; an explicit mode must fit every law (as resolve_solver_mode(law, requested)).
SolverMode resolve_solver_mode(std::span<const FrictionLaw* const> laws, SolverMode requested);

/// The solver mode `automatic` resolves to for `law` (hybrid, stiff), or `requested` itself after
/// checking it fits. \throws std::invalid_argument when it does not (hybrid with a dynamic law,
/// stiff with a static law that has a breakaway level).
SolverMode resolve_solver_mode(const FrictionLaw& law, SolverMode requested);

}  // namespace frictionlab
