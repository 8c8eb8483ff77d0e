#pragma once
// CSV reader for logs as rigs write them: a header row of column names or none, one row of
// numbers per sample, the delimiter detected, comment lines, CRLF, a UTF-8 BOM, quoted cells.

#include <string>
#include <vector>

#include "frictionlab/io/dataset.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Whether a CSV file must start with a header row.
enum class CsvHeader {
  /// The first row must be a header row of names (a first row of numbers is an error).
  required,
  /// A first row whose cells all parse as numbers (NaN, inf, empty cells allowed; at least one
  /// number) is data: the file has no header row and its columns are named by `names`, the
  /// rest c1, c2, ... (1-based, by position). Any other first row is the header row.
  detect,
};

/// Options of read_csv.
struct CsvOptions {
  /// Field separator; '\0' (default) detects it from the first row that is not a comment: a tab
  /// if it has one outside quotes, else ';', else ',', else runs of blanks. ' ' means runs of
  /// blanks (spaces and tabs; leading and trailing blanks ignored).
  char delimiter = '\0';
  /// Drop rows with an empty, NaN or infinite cell instead of rejecting the file. Default false.
  /// Rows with text that is not a number or with the wrong number of cells are always errors.
  bool drop_invalid = false;
  /// Lines starting with this character (after blanks) are skipped. Default '#'; '\0' for none.
  char comment = '#';
  /// Header row required (default, for callers that name columns) or detected (what the command
  /// line and Python do).
  CsvHeader header = CsvHeader::required;
  /// Names of the columns, in file order. For a file without a header row they name the first
  /// names.size() columns (the others keep c<k>); with a header row they replace the header's
  /// names the same way (the header row is still not data). Empty (default): no renaming.
  /// More names than columns, an empty name or a name used twice is an error.
  std::vector<std::string> names;
  /// How the user gives `names`, for messages ("--names" on the command line, "names" in
  /// Python). Default "names".
  std::string names_option = "names";
  /// How the user sets drop_invalid, for messages ("--drop-invalid" on the command line).
  /// Default "drop_invalid".
  std::string drop_invalid_option = "drop_invalid";
  /// Leave a cell that is not a finite number (empty, NaN, inf, out of range, text) to the
  /// command: the column holds NaN there and Dataset::invalid_cells records the first such cell
  /// of each column with the error that would have refused the file; using that column then
  /// refuses it (io/columns.hpp select_column). Default false: the file is refused at once.
  /// drop_invalid takes precedence for empty, NaN and infinite cells.
  bool defer_invalid = false;
};

/// Reads a CSV file into a Dataset of columns; sets file, sha256, header_row and the line number
/// of each sample. Header names have surrounding blanks and quotes removed; cells may be quoted
/// ("1.5", "a;b"; "" inside quotes is a quote; a quoted cell does not span lines). Blank lines
/// are skipped, CRLF line ends and a UTF-8 byte order mark are accepted. Numbers are parsed with
/// the C locale ("1.5e-3"); a number too small for a double (1e-400) reads as 0 or a subnormal,
/// one too large (1e400) is an error.
/// \throws std::invalid_argument "FILE: line L, column C 'NAME': expected a number, got 'TEXT'"
///         for a cell that is not a number, and naming file, line and column for an empty, NaN or
///         out-of-range cell (the first two unless drop_invalid), a wrong number of cells, an
///         unterminated quote, a first row mixing numbers and text (detect), a first row of
///         numbers (required), an empty or duplicate name (naming names_option when it came from
///         `names`), more names than columns, no data rows, or a file that cannot be read. With
///         defer_invalid, bad cells are recorded in Dataset::invalid_cells instead.
Dataset read_csv(const std::string& path, const CsvOptions& options = {});

}  // namespace frictionlab
