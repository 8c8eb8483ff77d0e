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

Result run(const MethodIO& io, const OptionValues& options) {
  const Dataset d = load_data(io.data, io.columns);
  DecayData x{time_column(d, io.columns), position_column(d, io.columns)};
  DecayOptions o = make_decay_options(options);
  o.axis = io.columns.parsed_axis();
  Result r = identify_decay(x, o);
  stamp(r, d);
  return r;
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
  return {"Free oscillation of a pendulum or spring-mass: Coulomb and viscous friction from the energy lost "
          "per half cycle",
          run,
          {{"fit", "Free oscillation with its turning points and the envelope fitted to their half swings.",
            decay_figure}},
          nullptr,
          {}};
}

}  // namespace frictionlab::cli
