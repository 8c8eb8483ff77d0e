#pragma once
// When an option of a method applies, in words: the conditions of OptionSpec::applies_if as the
// flags' help (`frictionlab identify METHOD --help`) and the options reference (`frictionlab help
// --markdown`, docs/options.md) say them, so a reader learns there that `--kp` is used only with
// `--iv`, as the report's Options table already shows.

#include <string>
#include <vector>

#include "frictionlab/export.hpp"
#include "frictionlab/identify/options.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The conditions under which `spec` applies, in words, each naming the other option by its flag
/// and all of them holding together: "applies with --iv", "applies without --segment and without
/// --reference", "applies when --terms holds stribeck", "applies when --model is stribeck or
/// stribeck-asymmetric"; "" when it always applies. `table` is the method's option table (a
/// list option "holds" a word, a text "is" one). With `markdown`, flags and words are in backticks.
/// \throws std::invalid_argument when a condition names an option that `table` lacks (a
///         programming error of the method's own file).
std::string applies_text(const OptionSpec& spec, const std::vector<OptionSpec>& table, bool markdown = false);

}  // namespace frictionlab
