#pragma once
// Derived columns: a signal given as arithmetic of a data set's columns, e.g. the friction a
// torque-sensing joint measures, `TorqueCur1 - Torque1` (motor torque from current minus the
// link torque sensor), or `gtau * vir` with a MAT file's scalar.
//
// The grammar is small and safe (nothing is executed, no names but the data set's):
//   expression := term (("+" | "-") term)*
//   term       := factor (("*" | "/") factor)*
//   factor     := ("+" | "-") factor | NUMBER | NAME | `QUOTED NAME` | "(" expression ")"
// NAME is a column or a scalar of the data set made of letters, digits, '_' and '.', not starting
// with a digit; a name holding anything else (spaces, operators) is written between backquotes,
// `Torque cur [A]`. A text that is exactly a column's name is that column, operators or not.

#include <Eigen/Core>
#include <string>

#include "frictionlab/io/dataset.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// True when `text` is not a column of `data` but reads as an expression: it holds an operator
/// (+ - * /), a parenthesis or a backquote. A plain unknown name is not an expression (its
/// message stays "no column").
bool is_column_expression(const Dataset& data, const std::string& text);

/// Evaluates `expression` sample by sample over the columns of `data` (units: whatever the
/// columns hold after scaling; the result has the columns' length). Every column it uses must be
/// finite. `role` names it in messages ("--force").
/// \throws InputError (std::invalid_argument):
///   - option.invalid for a syntax error, naming the role, the expression and the character;
///   - data.column_missing for a name that is neither a column nor a scalar, listing the file's
///     columns (Dataset::describe_contents);
///   - data.not_finite naming the row and the column of a non-finite input sample, or the row
///     where the result is not finite (a division by zero).
Eigen::VectorXd evaluate_column_expression(const Dataset& data, const std::string& expression, const std::string& role = "");

/// The signal `name_or_expression` of `data`: the column of that name (checked finite, as
/// finite_column of io/columns.hpp), or else the value of the expression
/// (evaluate_column_expression). The one way commands read a column a user names.
/// \throws as finite_column or evaluate_column_expression.
Eigen::VectorXd finite_signal(const Dataset& data, const std::string& name_or_expression, const std::string& role = "");

}  // namespace frictionlab
