#pragma once
// Reads a data file, choosing the reader by the file's extension or by the format the caller names.

#include <string>

#include "frictionlab/io/csv.hpp"
#include "frictionlab/io/dataset.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Which reader load_dataset uses.
enum class DataFormat {
  by_extension,  ///< .csv, .tsv, .txt (any case): a text table (read_csv); .mat: read_mat; others refused
  csv,           ///< a text table whatever the name (a robot's .log, a .dat file): read_csv
  mat,           ///< a MAT file whatever the name: read_mat
};

/// "csv" or "mat" (a text table or a MAT file); "" or "auto" is by_extension. `option` names the
/// option or keyword in the message ("--format", "format").
/// \throws InputError (code option.invalid) for any other text.
DataFormat parse_data_format(const std::string& text, const std::string& option);

/// The file read by `format`: read_csv(path, csv_options) or read_mat(path).
/// \throws InputError (code data.file_type) for an extension by_extension does not know, naming
///         the file, the extensions it knows and the formats that can be given instead; and
///         whatever the chosen reader throws.
Dataset load_dataset(const std::string& path, const CsvOptions& csv_options = {},
                     DataFormat format = DataFormat::by_extension);

}  // namespace frictionlab
