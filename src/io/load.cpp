#include "frictionlab/io/load.hpp"
#include "frictionlab/error.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

#include "frictionlab/io/mat.hpp"

namespace frictionlab {

DataFormat parse_data_format(const std::string& text, const std::string& option) {
  if (text.empty() || text == "auto") return DataFormat::by_extension;
  if (text == "csv") return DataFormat::csv;
  if (text == "mat") return DataFormat::mat;
  throw InputError(errc::option_invalid,
                   option + " '" + text + "': expected csv (a text table: comma, semicolon, tab or blank separated) "
                                          "or mat (a MATLAB file), or auto (by the file's extension)",
                   {.option = option, .value = text});
}

Dataset load_dataset(const std::string& path, const CsvOptions& csv_options, DataFormat format) {
  if (format == DataFormat::csv) return read_csv(path, csv_options);
  if (format == DataFormat::mat) return read_mat(path);
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  // The text extensions whose files are tables by convention; the reader finds the separator.
  if (ext == ".csv" || ext == ".tsv" || ext == ".txt") return read_csv(path, csv_options);
  if (ext == ".mat") return read_mat(path);
  throw InputError(errc::data_file_type,
                   path + ": unknown data file type '" + ext +
                       "'; expected a .csv, .tsv or .txt file (a text table, with or without a header row) or a "
                       ".mat file; for a file of another name give its format (--format csv or --format mat; "
                       "Python: format=\"csv\")",
                   {.file = path, .value = ext});
}

}  // namespace frictionlab
