#pragma once
// Numbers or an error, never both (docs/guarantees.md): an identification whose status is ok has
// a finite number for every figure it reports. Values or scales beyond what double precision holds
// (a force offset of 1e167, whose squares overflow the fit's sums; forces of 1e-162, whose squares
// underflow) can make a fit's covariance or its residual figures overflow while its estimates stay
// finite; such a result is an error that names the figure, not an ok result with inf in it.
//
// What may be NaN in an ok result, as "not determined" or "not defined" (JSON null, text "n/a"):
// a parameter's std (undetermined or at a bound), the condition number (no regressor matrix), a
// diagnostics number or group entry (the autocorrelation of a zero residual). inf is never one.

#include <string>
#include <string_view>

#include "frictionlab/identify/result.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The first word of `text` that is a number that is not finite as printf or std::to_chars
/// writes it (inf, infinity, nan, each with a sign or not, in any case, nan(...) too), as
/// "'WORD' at line N": a word stands between the start or end of the text, whitespace and the
/// separators , ; = : ( ) [ ] { } | < > " (so a file name such as inf.csv, or "information", is
/// not one). Empty when there is none. Never throws (but std::bad_alloc).
std::string non_finite_word(std::string_view text);

/// The first figure of an ok result that is not a finite number where one belongs, in words
/// ("parameter Fc = inf", "std(M) = inf", "fit rmse = nan", "diagnostics adequacy.residual_std =
/// inf"): the parameters' values and std, the fit and validation figures (when they count
/// samples), diagnostics numbers, groups and lists (inf only, see above); then the texts, where a
/// figure formatted from an intermediate result (a warning's "variance inflation nan") would say
/// nan or inf (non_finite_word): the message, every warning ("warning 2's word 'nan' at line 1"), the
/// diagnostics' texts and the JSON sections. Empty when there is none, or when the status is
/// error. Never throws.
std::string non_finite_figure(const Result& r);

/// `r` with status error, code "output.not_finite" (frictionlab/error.hpp) and a message naming
/// the figure or the text ("FILE: METHOD: std(M) = inf is not a finite number (values or scales beyond what
/// double precision holds); the data cannot give an answer") when it is ok and
/// non_finite_figure(r) finds one; `r` as it is otherwise. Every identification of the library
/// returns through it (identify_idim, identify_sweep, identify_breakaway, identify_decay,
/// identify_lugre); Python raises frictionlab.Error with that code instead of returning such a
/// result. On an ok result, a NaN std that no method explained (its parameter neither undetermined
/// nor at a bound: a variance that could not be formed in double precision) is made one: the
/// parameter is flagged and listed undetermined, with a warning that names it.
Result finite_or_error(Result r);

}  // namespace frictionlab
