#pragma once
// When an option of a method applies, in words: the conditions of OptionSpec::applies_if as the
// flags' help (`frictionlab identify METHOD --help`) and the options reference (`frictionlab help
// --markdown`, docs/options.md) and the Python functions' docstrings say them, so a reader learns
// there that `--kp` (Python `kp`) is used only with `--iv` (`iv=True`), as the report's Options
// table already shows. One rendering of the table's conditions for all three.

#include <string>
#include <vector>

#include "frictionlab/export.hpp"
#include "frictionlab/identify/options.hpp"
namespace frictionlab FRICTIONLAB_API {

/// How applies_text names the other options.
enum class AppliesStyle {
  command_line,  ///< by flag: "applies with --iv", "applies when --terms holds stribeck"
  markdown,      ///< the same with flags and words in backticks: "applies with `--iv`"
  /// by Python keyword, as a docstring says it: "applies with iv=True" (a flag), "applies when
  /// segment is not given", "applies when terms holds 'stribeck'", "applies when model is
  /// 'stribeck' or 'stribeck-asymmetric'"
  python,
};

/// The conditions under which `spec` applies, in words, each naming the other option by its flag
/// and all of them holding together: "applies with --iv", "applies without --segment and without
/// --reference", "applies when --terms holds stribeck", "applies when --model is stribeck or
/// stribeck-asymmetric"; "" when it always applies. `table` is the method's option table (a
/// list option "holds" a word, a text "is" one). `style` picks flags, flags in backticks or
/// Python keywords (AppliesStyle).
/// \throws std::invalid_argument when a condition names an option that `table` lacks (a
///         programming error of the method's own file).
std::string applies_text(const OptionSpec& spec, const std::vector<OptionSpec>& table,
                         AppliesStyle style = AppliesStyle::command_line);

}  // namespace frictionlab
