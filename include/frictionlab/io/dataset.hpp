#pragma once
// A measured data set as read from a file: named columns of equal length, named scalars,
// and where it came from (file name and the sha256 of its bytes).

#include <Eigen/Core>
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace frictionlab {

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

  /// The column named `name`. \throws std::invalid_argument naming the file and the column
  /// and listing the columns the file has (and its scalars).
  const Eigen::VectorXd& column(const std::string& name) const;
  /// Mutable access, same throws.
  Eigen::VectorXd& column(const std::string& name);

  /// "FILE: " or "" when there is no file; the prefix of every message about this data set.
  std::string where() const;
  /// Names sample k (0-based) in messages: "line 17" for CSV data, "sample 17" (1-based) else.
  std::string row_label(Eigen::Index k) const;
  /// Comma-separated column names, and the scalar names after "scalars: " when any.
  std::string describe_contents() const;

 private:
  std::vector<std::string> names_;
  std::vector<Eigen::VectorXd> columns_;
};

}  // namespace frictionlab
