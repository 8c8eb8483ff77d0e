// frictionlab identify auto: model selection on held-out data: what experiment the record holds
// (a free decay, a breakaway ramp or presliding get their own method),
// every candidate structure it supports (the inverse dynamic model's term sets, a sweep's laws
// when it has plateaus), and the one with the lowest held-out drive-force error: options, run,
// figures (measured and reconstructed force; the candidates' held-out errors).
#include "../figure_kit.hpp"
#include "../flag_names.hpp"
#include "frictionlab/identify/auto.hpp"
#include "method.hpp"

namespace frictionlab::cli {
namespace {

Result run(const MethodIO& io, const OptionValues& options) {
  AutoOptions o = make_auto_options(options);
  o.axis = io.columns.parsed_axis();
  const std::string from = options.text("from");
  const Dataset d = load_data(io.data, io.columns);
  const IdimData data = trajectory_record(d, io.columns, from);
  if (options.given("validate"))
    o.heldout = trajectory_record(load_data(options.text("validate"), io.columns), io.columns, from);
  Result r = identify_auto(data, o);
  note_data(r, d);
  name_flags(r);
  return r;
}

Figure fit_figure(const Result& r) {
  Figure f;
  f.title = title_for(r, "Chosen model " + r.model + ": measured and modelled " + force_name(r.axis));
  const Axis axis = r.axis;
  const auto *t = find(r, "time"), *y = find(r, "force"), *m = find(r, "force_model");
  if (!t || !y || !m) return f;
  add_force_fit_panels(f, axis, *t, *y, m, "chosen model", "measured - model");
  return f;
}

}  // namespace

CliMethod auto_method() {
  return {"Model selection: says what experiment the record holds (a free decay: runs decay; a slow force ramp "
          "with stick: runs breakaway; presliding: the bristle stiffness only, and names lugre; a trajectory; "
          "constant-speed plateaus), fits every structure it supports (inverse dynamic model Coulomb-viscous, + Stribeck with vs searched, "
          "asymmetric; a sweep's laws with M from the trajectory) and answers with the one that predicts held-out "
          "time blocks (or --validate FILE) best; refuses physically impossible fits. The candidates are listed "
          "with their held-out errors",
          run,
          {{"fit",
            "Measured drive force and the force the chosen model reconstructs (top), and their difference "
            "(bottom), on the identification data after filtering and decimation. The candidates' held-out "
            "errors are in the diagnostics table (selection).",
            fit_figure}},
          nullptr,
          {}};
}

}  // namespace frictionlab::cli
