#pragma once
// What the library says about each identification method, so that a result's readers (the text
// table, the report, the JSON, Python) need no switch on the method's name: its name, one line
// on what it does, the signal its fit figures measure, and its options (identify/options.hpp).
// Each method stamps its Result with it (new_result); the result then carries its axis and its
// fit's quantity and unit itself.
//
// The methods are registered in one place, FRICTIONLAB_METHODS below: adding a method means its
// own files (src/identify/NAME.cpp with NAME_method_info(), app/methods/NAME.cpp with
// NAME_method(), python/src/methods/NAME.cpp with NAME_binding(), python/frictionlab/methods/NAME.py)
// and one line there. The method's name is that line's word; nowhere else is it written.

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "frictionlab/identify/options.hpp"
#include "frictionlab/identify/result.hpp"
#include "frictionlab/models/parameter.hpp"

/// Every identification method (and validate), in the order the command line, Python and the docs
/// list them: X(NAME) for each. The library, the command line and the Python module expand it.
#define FRICTIONLAB_METHODS(X) \
  X(idim)                      \
  X(breakaway)                 \
  X(sweep)                     \
  X(decay)                     \
  X(lugre)                     \
  X(auto)                      \
  X(validate)

/// The MethodId enumerator of a registered name: the name itself, except for a name that is a C++
/// keyword (auto), whose enumerator is spelled out (MethodId::automatic).
#define FRICTIONLAB_METHOD_ENUM_auto ~, automatic,
#define FRICTIONLAB_METHOD_SECOND_(a, b, ...) b
#define FRICTIONLAB_METHOD_SECOND(...) FRICTIONLAB_METHOD_SECOND_(__VA_ARGS__)
#define FRICTIONLAB_METHOD_ENUM(name) FRICTIONLAB_METHOD_SECOND(FRICTIONLAB_METHOD_ENUM_##name, name, ~)

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// A method by its registration (FRICTIONLAB_METHODS): MethodId::sweep.
enum class MethodId {
#define FRICTIONLAB_METHOD_ID(name) FRICTIONLAB_METHOD_ENUM(name),
  FRICTIONLAB_METHODS(FRICTIONLAB_METHOD_ID)
#undef FRICTIONLAB_METHOD_ID
};

/// One identification method (or validation) of the library.
struct MethodInfo {
  std::string name;     ///< "idim", "sweep", "breakaway", "decay", "lugre", "auto", "validate"
  std::string summary;  ///< one line for reports, e.g. "inverse dynamic model least squares"
  /// The signal the fit figures (relative error, rmse) are computed on, in words ("drive force",
  /// "energy lost per half cycle", "position"); empty when there is no single one (validate
  /// reports per-signal errors).
  std::string fit_signal;
  /// Its quantity (hence the rmse's unit on the result's axis); nullopt with an empty fit_signal.
  std::optional<Quantity> fit_quantity;
  /// The method's options, in the order of its help and reference (identify/options.hpp).
  std::vector<OptionSpec> options;
  /// Its id (FRICTIONLAB_METHODS).
  MethodId id = MethodId::idim;

  /// The option named `name` (its flag without "--"), or nullptr.
  const OptionSpec* option(const std::string& name) const;
  /// Empty option values over this method's table (set them, then make the method's options).
  OptionValues values() const { return OptionValues(options); }
};

/// The library's methods, in the order of FRICTIONLAB_METHODS.
const std::vector<MethodInfo>& identification_methods();

/// The method named `name`. \throws std::invalid_argument listing the names.
const MethodInfo& method_info(std::string_view name);
/// The method `id`.
const MethodInfo& method_info(MethodId id);

/// The options reference of every method as Markdown (`frictionlab help --markdown`): per method a
/// heading, its summary and a table of its options (flag, Python keyword, type, unit, default,
/// valid values, help).
std::string options_markdown();

/// An empty ok result of `method` fitting `model` on `axis`: method, model, axis, and the fit's
/// quantity (fit.quantity, words) and unit (fit.unit, e.g. "N m" on a rotary axis) set.
Result new_result(const MethodInfo& method, const std::string& model, Axis axis);

/// The fitted signal of a result in words and its unit: the result's own (fit.quantity, fit.unit),
/// or for a result made without new_result (by hand, an older program) its method's on the
/// result's axis; both empty when neither says.
std::pair<std::string, std::string> fit_signal_and_unit(const Result& r);

}  // namespace frictionlab
