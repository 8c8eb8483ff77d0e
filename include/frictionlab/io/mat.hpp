#pragma once
// MATLAB MAT-file reader (v5, and v7.3/HDF5 when matio was built with HDF5), through matio.

#include <string>

#include "frictionlab/io/dataset.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Reads every real numeric variable of a MAT file: vectors (1xN or Nx1) become columns, 1x1
/// values become scalars; any numeric class (double, single, integers) is converted to double.
/// Every other variable (matrix, char, struct, cell, complex, logical, sparse, or a vector
/// shorter than the longest) is recorded in Dataset::unusable with what it is ("a 3x4 matrix",
/// "a 1x1 struct (fields: a, b)"), so that asking for it as a column says so. In a v5 file,
/// each compressed variable's zlib stream is inflated to its end first and its checksum
/// verified. Sets file and sha256.
/// \throws std::invalid_argument naming the file when it does not exist, is not a MAT file, is
///         corrupt or truncated (naming the variable whose compressed data is damaged), or holds
///         no numeric vector (listing the variables and what they are). Never crashes on a bad
///         file that matio reports as bad.
Dataset read_mat(const std::string& path);

}  // namespace frictionlab
