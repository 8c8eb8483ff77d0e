#pragma once
// What the library says about each identification method, so that a result's readers (the text
// table, the report, the JSON, Python) need no switch on the method's name: its name, one line
// on what it does, and the signal its fit figures measure. Each method stamps its Result with it
// (new_result); the result then carries its axis and its fit's quantity and unit itself.

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "frictionlab/identify/result.hpp"
#include "frictionlab/models/parameter.hpp"

#include "frictionlab/export.hpp"
namespace FRICTIONLAB_API frictionlab {

/// One identification method (or validation) of the library.
struct MethodInfo {
  std::string name;     ///< "idim", "sweep", "breakaway", "decay", "lugre", "validate"
  std::string summary;  ///< one line for reports, e.g. "inverse dynamic model least squares"
  /// The signal the fit figures (relative error, rmse) are computed on, in words ("drive force",
  /// "energy lost per half cycle", "position"); empty when there is no single one (validate
  /// reports per-signal errors).
  std::string fit_signal;
  /// Its quantity (hence the rmse's unit on the result's axis); nullopt with an empty fit_signal.
  std::optional<Quantity> fit_quantity;
};

/// The library's methods, in the order the command line and the docs list them. Adding a method:
/// its own files and one line in src/identify/method.cpp.
const std::vector<MethodInfo>& identification_methods();

/// The method named `name`. \throws std::invalid_argument listing the names.
const MethodInfo& method_info(std::string_view name);

/// An empty ok result of `method` fitting `model` on `axis`: method, model, axis, and the fit's
/// quantity (fit.quantity, words) and unit (fit.unit, e.g. "N m" on a rotary axis) set.
Result new_result(const MethodInfo& method, const std::string& model, Axis axis);

/// The fitted signal of a result in words and its unit: the result's own (fit.quantity, fit.unit),
/// or for a result made without new_result (by hand, an older program) its method's on the
/// result's axis; both empty when neither says.
std::pair<std::string, std::string> fit_signal_and_unit(const Result& r);

}  // namespace frictionlab
