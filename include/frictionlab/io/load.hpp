#pragma once
// Reads a data file, choosing the reader by the file's extension.

#include <string>

#include "frictionlab/io/csv.hpp"
#include "frictionlab/io/dataset.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// `.csv` (any case) -> read_csv(path, csv_options), `.mat` -> read_mat(path).
/// \throws std::invalid_argument naming the file and the accepted extensions for any other
///         extension, and whatever the chosen reader throws.
Dataset load_dataset(const std::string& path, const CsvOptions& csv_options = {});

}  // namespace frictionlab
