// frictionlab identify decay: free oscillation of a pendulum or spring-mass: options, run,
// figure (the oscillation, its turning points and the fitted envelope).
#include <limits>
#include <optional>

#include "../figure_kit.hpp"
#include "frictionlab/models/friction_law.hpp"
#include "method.hpp"
#include "frictionlab/analysis/envelope.hpp"
#include "frictionlab/identify/decay.hpp"

namespace frictionlab::cli {
namespace {

struct DecayArgs {
  double stiffness = std::numeric_limits<double>::quiet_NaN();
  double inertia = std::numeric_limits<double>::quiet_NaN();
  double natural_frequency = std::numeric_limits<double>::quiet_NaN();
  bool pendulum = false;
};

Result run(const DecayArgs& a, const MethodIO& io) {
  const Dataset d = load_data(io.data, io.columns);
  DecayData x{time_column(d, io.columns), position_column(d, io.columns)};
  DecayOptions o;
  o.stiffness = a.stiffness;
  o.inertia = a.inertia;
  o.natural_frequency = a.natural_frequency;
  o.pendulum = a.pendulum;
  o.axis = io.columns.parsed_axis();
  Result r = identify_decay(x, o);
  stamp(r, d);
  return r;
}

MethodRun add_options(CLI::App* decay) {
  auto a = std::make_shared<DecayArgs>();
  decay->add_option("--stiffness", a->stiffness, "Restoring stiffness (N/m or N m/rad; m g l for a pendulum)");
  decay->add_option("--inertia", a->inertia, "Mass or inertia (kg or kg m^2), with --natural-frequency");
  decay->add_option("--natural-frequency", a->natural_frequency,
                    "sqrt(k/M) (rad/s): without --stiffness, report Fc/k and the damping ratio");
  decay->add_flag("--pendulum", a->pendulum, "Restoring torque is stiffness * sin(angle)");
  return [a](const MethodIO& io, const CLI::App&) { return run(*a, io); };
}

Figure decay_figure(const Result& r) {
  const Axis axis = r.axis;
  Figure f;
  f.title = title_for(r, "Free decay: turning points and the fitted envelope");
  const auto *t = find(r, "time"), *x = find(r, "position");
  if (!t || !x) return f;
  std::optional<EnvelopeResult> env;
  try {
    env = decay_envelope(*t, *x);
  } catch (const std::invalid_argument&) {  // too few swings for an envelope: the signal alone
  }
  const auto* pt = find(r, "peak_time");
  const auto* px = find(r, "peak_position");
  f.panels.push_back(position_with_envelope(*t, *x, pt ? *pt : std::vector<double>{}, px ? *px : std::vector<double>{},
                                            env, label("position", Quantity::displacement, axis)));
  return f;
}

}  // namespace

CliMethod decay_method() {
  return {"decay",
          "Free oscillation of a pendulum or spring-mass: Coulomb and viscous friction from the energy lost "
          "per half cycle",
          "linear",
          add_options,
          {{"fit", "Free oscillation with its turning points and the envelope fitted to their half swings.",
            decay_figure}}};
}

}  // namespace frictionlab::cli
