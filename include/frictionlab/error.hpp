#pragma once
// Errors with a stable code. Bad input (a data file, a scenario, an option, an output path) is
// an InputError: a std::invalid_argument (the CLI exits 2, Python raises ValueError) that also
// carries a code from the table below and the fields that locate the fault (file, row, column,
// key, option, value). A failure that is not the caller's (an I/O error while writing, a broken
// invariant) is an InternalError: a std::runtime_error (exit 1, Python RuntimeError) with a code.
//
// Codes are part of the interface: the CLI's error JSON ("error": {"code": ...}) and Python's
// frictionlab.Error.code carry them, and scripts may branch on them. A code is never renamed or
// reused for another meaning; new codes may be added. Messages are for people and may change.
//
// | code                   | meaning                                                              | fields |
// |------------------------|----------------------------------------------------------------------|--------|
// | input.invalid          | bad input not yet given a code of its own (any std::invalid_argument  | -      |
// |                        | that is not an InputError is reported with this code)                 |        |
// | internal               | an internal failure without a code of its own (any other exception)  | -      |
// | data.file_unreadable   | a data file cannot be opened or read (missing, not a regular file,   | file   |
// |                        | a read error)                                                         |        |
// | data.file_type         | a data file's extension is neither .csv nor .mat                      | file, value |
// | data.format            | the file is not a valid CSV or MAT file: an unclosed quote, a header | file, row, column |
// |                        | that is missing, mixed or empty, a row with the wrong cell count, an |        |
// |                        | empty file, no data rows, a damaged or unsupported MAT file          |        |
// | data.column_duplicate  | two columns (or --names entries) with one name                        | file, row, column |
// | data.column_missing    | a column or variable that is not in the file (or is not a numeric    | file, column, option |
// |                        | vector)                                                               |        |
// | data.column_length     | a column whose length differs from the others                        | file, column |
// | data.not_a_number      | a cell that is text where a number belongs                           | file, row, column, value |
// | data.not_finite        | a NaN, inf, empty cell or a number beyond the range of a double      | file, row, column, value |
// | data.time              | a time column that is not increasing or not regular enough           | file, row, column |
// | data.no_answer         | data that cannot give an answer: no motion or excitation, too few    | file   |
// |                        | segments or samples, rank-deficient regressors (a result whose status |        |
// |                        | is error and that has no other code)                                  |        |
// | option.invalid         | an option value that cannot be parsed (NAME=FACTOR, a number or a    | option, value |
// |                        | scalar's name, a list of names)                                       |        |
// | option.out_of_range    | an option value outside its valid range (units in the message)       | option, value |
// | option.conflict        | options that cannot be given together                                | option |
// | scenario.key_unknown   | a key that the scenario or MODEL.json does not know                   | file, key |
// | scenario.key_missing   | a required key that is absent                                        | file, key |
// | scenario.key_duplicate | a key given twice in one mapping (YAML)                              | file, row, key |
// | scenario.value         | a key whose value is of the wrong type or out of its range           | file, key, value |
// | scenario.format        | a scenario or MODEL.json that cannot be parsed (YAML or JSON syntax, | file |
// |                        | unreadable file)                                                      |        |
// | law.parameter          | a friction law's load, temperature or ripple parameter out of its    | key, value |
// |                        | range (key: the law file's parameter name; value: the value, or the  |        |
// |                        | temperature at which a coefficient would turn negative)              |        |
// | output.exists          | an output file that exists, without --overwrite                       | file, option |
// | output.is_input        | an output that is one of the run's inputs (never replaced, even with | file, option, other_file, other_option |
// |                        | --overwrite)                                                          |        |
// | output.duplicate       | two outputs of one run that are the same file                         | file, option, other_file, other_option |
// | output.not_writable    | an output that cannot be written: a directory, a missing or          | file, option |
// |                        | unwritable directory, a block device or socket, a link without       |        |
// |                        | --overwrite                                                          |        |
// | output.write_failed    | (InternalError) writing an output failed: disk full, I/O error       | file |
// | output.not_finite      | a result or output refused because a number of it is not finite (a  | file, column, key, value |
// |                        | figure or a simulated column that overflows double precision, a C    |        |
// |                        | header's constant beyond double's or float's range): the input gave  |        |
// |                        | numbers beyond what double precision holds; nothing is written       |        |
// | budget.memory          | the run would need more memory than the memory budget (budget.hpp)   | file, key, option, value |
// | budget.work            | the run would do more work (samples, solver steps, runs, YAML nodes, | file, key, option, value |
// |                        | bytes read) than the work budget (budget.hpp)                         |        |
//
// Field meanings: `file` the file the fault is in (for output.* the output path); `row` the
// 1-based line of a CSV file, or the 1-based sample when the data has no lines; `column` a
// column or variable name; `key` a dotted scenario or MODEL.json key (plant.M); `option` a
// command-line option or Python keyword (--json, --time); `value` the offending text; for
// output.is_input and output.duplicate, `other_file` and `other_option` name the input (or
// other output) the output is the same file as.

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Stable error codes (see the table above).
namespace errc {
inline constexpr const char* input_invalid = "input.invalid";
inline constexpr const char* internal = "internal";
inline constexpr const char* data_file_unreadable = "data.file_unreadable";
inline constexpr const char* data_file_type = "data.file_type";
inline constexpr const char* data_format = "data.format";
inline constexpr const char* data_column_duplicate = "data.column_duplicate";
inline constexpr const char* data_column_missing = "data.column_missing";
inline constexpr const char* data_column_length = "data.column_length";
inline constexpr const char* data_not_a_number = "data.not_a_number";
inline constexpr const char* data_not_finite = "data.not_finite";
inline constexpr const char* data_time = "data.time";
inline constexpr const char* data_no_answer = "data.no_answer";
inline constexpr const char* option_invalid = "option.invalid";
inline constexpr const char* option_out_of_range = "option.out_of_range";
inline constexpr const char* option_conflict = "option.conflict";
inline constexpr const char* scenario_key_unknown = "scenario.key_unknown";
inline constexpr const char* scenario_key_missing = "scenario.key_missing";
inline constexpr const char* scenario_key_duplicate = "scenario.key_duplicate";
inline constexpr const char* scenario_value = "scenario.value";
inline constexpr const char* scenario_format = "scenario.format";
inline constexpr const char* law_parameter = "law.parameter";
inline constexpr const char* output_exists = "output.exists";
inline constexpr const char* output_is_input = "output.is_input";
inline constexpr const char* output_duplicate = "output.duplicate";
inline constexpr const char* output_not_writable = "output.not_writable";
inline constexpr const char* output_write_failed = "output.write_failed";
inline constexpr const char* output_not_finite = "output.not_finite";
inline constexpr const char* budget_memory = "budget.memory";
inline constexpr const char* budget_work = "budget.work";
}  // namespace errc

/// Where an error lies. Empty strings and an empty row mean "does not apply".
struct ErrorFields {
  std::string file{};                 ///< the file the fault is in (output.*: the output path)
  std::optional<std::size_t> row{};   ///< 1-based line of a CSV file (or sample number)
  std::string column{};               ///< column or variable name
  std::string key{};                  ///< dotted scenario / MODEL.json key, e.g. "plant.M"
  std::string option{};               ///< command-line option or Python keyword, e.g. "--json"
  std::string value{};                ///< the offending value, as text
  std::string other_file{};           ///< output.is_input / output.duplicate: the other file
  std::string other_option{};         ///< ... and its option or role ("scenario", "data:", "--json")

  /// The fields that apply, as (name, text) pairs in the order above (row as a decimal number).
  std::vector<std::pair<std::string, std::string>> items() const;
};

/// Bad input: a std::invalid_argument with a code and fields. what() is the message.
class InputError : public std::invalid_argument {
 public:
  InputError(std::string code, const std::string& message, ErrorFields fields = {});
  const std::string& code() const noexcept { return code_; }
  const ErrorFields& fields() const noexcept { return fields_; }

 private:
  std::string code_;
  ErrorFields fields_;
};

/// An internal failure (not the caller's input): a std::runtime_error with a code and fields.
class InternalError : public std::runtime_error {
 public:
  InternalError(std::string code, const std::string& message, ErrorFields fields = {});
  const std::string& code() const noexcept { return code_; }
  const ErrorFields& fields() const noexcept { return fields_; }

 private:
  std::string code_;
  ErrorFields fields_;
};

/// The code of any exception: an InputError's or InternalError's own, "input.invalid" for any
/// other std::invalid_argument, "internal" for anything else.
std::string error_code(const std::exception& e) noexcept;

/// The fields of an InputError or InternalError, empty for any other exception.
ErrorFields error_fields(const std::exception& e) noexcept;

/// Rethrows `e` (a std::invalid_argument) as an InputError with `prefix` before its message and
/// `option` set (keeping an InputError's code and other fields; others get input.invalid).
[[noreturn]] void rethrow_with_option(const std::invalid_argument& e, const std::string& prefix,
                                      const std::string& option);

}  // namespace frictionlab
