#pragma once
// MATLAB MAT-file reader (v5, and v7.3/HDF5 when matio was built with HDF5), through matio.

#include <string>

#include "frictionlab/io/dataset.hpp"

namespace frictionlab {

/// Reads every real numeric variable of a MAT file: vectors (1xN or Nx1) become columns, 1x1
/// values become scalars; any numeric class (double, single, integers) is converted to double.
/// Complex, sparse, logical, char, cell, struct and matrix variables are skipped (their names are
/// listed in the scalar-free message if no column remains). Vectors of a length different from
/// the longest vector are skipped too. Sets file and sha256.
/// \throws std::invalid_argument naming the file when it does not exist, is not a MAT file, is
///         corrupt or truncated, or holds no numeric vector. Never crashes on a bad file that
///         matio reports as bad.
Dataset read_mat(const std::string& path);

}  // namespace frictionlab
