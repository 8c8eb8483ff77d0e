#pragma once
// Numbers or an error, never both (docs/guarantees.md): the one check that the writers of numbers
// run before they write with exit status 0: the result of identify, validate and analyze (its
// JSON, its text summary and its report: emit() in output.hpp), each row of a batch, simulate's
// CSV and summary, plan's profile, JSON and text. (Tables of map and merge write a figure that is
// not defined for a row as an empty cell, as documented in fleet/shard.hpp.) The computations
// check their own figures where they can say why (a simulation's column at a time, an envelope
// whose sums overflow); this check is what no command gets past.

#include <string>
#include <string_view>

#include "frictionlab/identify/finite_result.hpp"

namespace frictionlab::cli {

/// The first word of `text` that is a number that is not finite (inf, nan, ...), as "'WORD' at
/// line N" (frictionlab::non_finite_word, identify/finite_result.hpp).
using frictionlab::non_finite_word;

/// `r` with status error, code output.not_finite and a message naming the figure (frictionlab::finite_or_error,
/// identify/finite_result.hpp) or the word of `text` (the text the command would print) when it
/// is ok and either is not finite; `r` as it is otherwise.
Result finite_or_error(Result r, std::string_view text);

/// Throws InputError (output.not_finite, file `output`: the input gave numbers beyond double
/// precision) naming the output, the word and its line when non_finite_word(text) finds one: for
/// the writers of tables and text that are not a Result. `output` names the file ("-" or empty:
/// standard output).
void require_finite_output(std::string_view text, const std::string& output);

}  // namespace frictionlab::cli
