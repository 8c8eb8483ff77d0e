#pragma once
// A measured data set as read from a file: named columns of equal length, named scalars,
// and where it came from (file name and the sha256 of its bytes).

#include <Eigen/Core>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "frictionlab/error.hpp"
#include "frictionlab/signal/sampling.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Named columns of doubles (all of the same length), named scalars, and the source file.
/// Units are whatever the file holds; io/columns.hpp converts to SI (scale factors).
class Dataset {
 public:
  std::string file;    ///< source file name as given to the reader (empty if built in memory)
  std::string sha256;  ///< lowercase hex digest of the source file's bytes (empty if none)
  /// Named scalars (MAT 1x1 variables), e.g. "gtau" -> 35.15.
  std::map<std::string, double> scalars;
  /// For CSV data: the 1-based line number in the file of each sample (so messages can name the
  /// row even after invalid rows were dropped). Empty for MAT data (samples are then counted).
  std::vector<std::size_t> lines;
  /// For CSV data: false when the file has no header row (its columns are then named by the
  /// reader's `names`, the rest c1, c2, ... numbered from 1). True for MAT data.
  bool header_row = true;
  /// How the reader's user names the columns of a file without a header row, for messages
  /// (CsvOptions::names_option: "names", or "--names" on the command line).
  std::string names_option = "names";
  /// For MAT data: variables that are in the file but cannot be a column or a scalar, with what
  /// they are, e.g. "qm" -> "a 3x4 matrix", "info" -> "a struct (fields: date, rig)". Messages
  /// about a missing column say what such a variable is instead of "no column".
  std::map<std::string, std::string> unusable;
  /// Set when the columns were put on a uniform time grid (io/columns.hpp resample_dataset):
  /// the record's jitter, the grid and the samples in and out. Rows are then grid samples.
  std::optional<ResampleReport> resampling;
  /// What reading or resampling changed without refusing the data (merged time stamps, ...),
  /// one sentence each; commands pass them on as warnings.
  std::vector<std::string> warnings;
  /// Cells a reader could not take as finite numbers but left to the command that uses their
  /// column (CsvOptions::defer_invalid): the first such cell of each column, as the error that
  /// names its file, line and column. The column holds NaN there. select_column (io/columns.hpp)
  /// throws this error for such a column, so a bad cell in a column no command uses is harmless.
  std::map<std::string, InputError> invalid_cells;

  /// Adds a column (or replaces one of the same name). Shape: values of length rows() unless
  /// this is the first column. \throws std::invalid_argument naming the column, its length and
  /// the expected length.
  void add_column(const std::string& name, Eigen::VectorXd values);

  /// Number of samples (rows) of every column; 0 when there is none.
  Eigen::Index rows() const;
  /// Column names in file order.
  const std::vector<std::string>& column_names() const { return names_; }
  bool has_column(const std::string& name) const;
  bool has_scalar(const std::string& name) const { return scalars.count(name) != 0; }

  /// The column named `name`. \throws std::invalid_argument with missing_column_message.
  const Eigen::VectorXd& column(const std::string& name) const;
  /// Mutable access, same throws.
  Eigen::VectorXd& column(const std::string& name);

  /// "FILE: " or "" when there is no file; the prefix of every message about this data set.
  std::string where() const;
  /// Names sample k (0-based) in messages: "line 17" for CSV data, "sample 17" (1-based) else,
  /// "sample 17 of the resampled grid" after resampling.
  std::string row_label(Eigen::Index k) const;
  /// Comma-separated column names, then the scalar names after "scalars: " when any, then (CSV
  /// without a header row) that the file has no header row, then (MAT) the variables that are
  /// not columns and what they are.
  std::string describe_contents() const;
  /// Why `name` is not a column, for messages: "FILE: no column 'NAME' (ROLE); the file has
  /// columns: ..." (describe_contents), or, when `name` is a scalar or an unusable variable,
  /// "FILE: variable 'NAME' (ROLE) is a 3x4 matrix; expected a vector of N samples (1xN or Nx1)".
  /// `role` (e.g. "--time") may be empty.
  std::string missing_column_message(const std::string& name, const std::string& role = "") const;

 private:
  std::vector<std::string> names_;
  std::vector<Eigen::VectorXd> columns_;
};

}  // namespace frictionlab
