#include "frictionlab/io/load.hpp"
#include "frictionlab/error.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

#include "frictionlab/io/mat.hpp"

namespace frictionlab {

Dataset load_dataset(const std::string& path, const CsvOptions& csv_options) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".csv") return read_csv(path, csv_options);
  if (ext == ".mat") return read_mat(path);
  throw InputError(errc::data_file_type,
                   path + ": unknown data file type '" + ext +
                       "'; expected a .csv file (with or without a header row) or a .mat file",
                   {.file = path, .value = ext});
}

}  // namespace frictionlab
