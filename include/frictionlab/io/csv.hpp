#pragma once
// CSV reader: a header row of column names, then one row of numbers per sample.

#include <string>

#include "frictionlab/io/dataset.hpp"

namespace frictionlab {

/// Options of read_csv.
struct CsvOptions {
  /// Field separator. Default ','.
  char delimiter = ',';
  /// Drop rows with an empty, NaN or infinite cell instead of rejecting the file. Default false.
  /// Rows with text that is not a number or with the wrong number of cells are always errors.
  bool drop_invalid = false;
  /// Lines starting with this character (after blanks) are skipped. Default '#'; '\0' for none.
  char comment = '#';
};

/// Reads a CSV file with a header row (names, surrounding blanks and quotes removed) into a
/// Dataset of columns; sets file, sha256 and the line number of each sample. Blank lines are
/// skipped. Numbers are parsed with the C locale ("1.5e-3").
/// \throws std::invalid_argument "FILE: line L, column 'NAME': expected a number, got 'TEXT'" for
///         non-numeric, empty or NaN cells (the last two unless drop_invalid), a wrong number of
///         cells, an empty or duplicate header name, no data rows, or a file that cannot be read.
Dataset read_csv(const std::string& path, const CsvOptions& options = {});

}  // namespace frictionlab
