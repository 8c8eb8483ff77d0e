// frictionlab validate: its command is app/cmd_validate.cpp; this file gives its result's
// figure and caption (measured and simulated signals) to the shared --plot and --report path.
#include "../figure_kit.hpp"
#include "method.hpp"

namespace frictionlab::cli {
namespace {

Figure validate_figure(const Result& r) {
  // A validation is drawn against its own run, not the identification data the model came from.
  return compare_figure(r, "Validation: measured and simulated", "drive",
                        r.validation ? r.validation->file : r.data_file);
}

}  // namespace

CliMethod validate_method() {
  return {"",
          {},
          {{"fit", "Measured signals and the simulation of the identified model driven by the same input.",
            validate_figure}},
          nullptr,
          {}};
}

}  // namespace frictionlab::cli
