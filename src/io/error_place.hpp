#pragma once
// Where an error about a column happened, for InputError's fields: shared by the column readers
// (columns.cpp) and derived columns (column_expression.cpp), so both name rows and options alike.

#include <Eigen/Core>
#include <cstddef>
#include <string>

#include "frictionlab/io/dataset.hpp"

namespace frictionlab::detail {

/// The 1-based line of sample k in the file, or its sample number when the data has no lines
/// (MAT data) or was resampled.
inline std::size_t row_number(const Dataset& data, Eigen::Index k) {
  if (!data.resampling && k >= 0 && static_cast<std::size_t>(k) < data.lines.size()) return data.lines[static_cast<std::size_t>(k)];
  return static_cast<std::size_t>(k + 1);
}

/// A role that is an option ("--time") is reported as the error's option field; "" otherwise.
inline std::string option_of(const std::string& role) { return role.rfind("-", 0) == 0 ? role : std::string(); }

}  // namespace frictionlab::detail
