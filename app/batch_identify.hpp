#pragma once
// Batch identification: `frictionlab identify METHOD DATA...` with several files or a folder
// identifies each file alone and writes one row per file to a table (CSV or JSON, the format of
// python frictionlab.batch.Table), with --jobs threads; with --date-from, the log's date per
// row, the fleet's drift table (--drift) and figure (--plot).
//
// The work is a list of jobs (batch_jobs): each file with its global index, its place in the
// expanded DATA list. A row keeps that index, so a subset of the jobs (a shard of a Slurm array)
// gives rows that a merge puts back in order.

#include <CLI/CLI.hpp>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "output.hpp"
#include "frictionlab/analysis/drift.hpp"
#include "frictionlab/identify/result.hpp"
#include "fleet/shard.hpp"

namespace frictionlab::cli {

/// The batch options of an identify method subcommand.
struct BatchOptions {
  std::string table;        ///< --table FILE|-: the rows, CSV (JSON when FILE ends in .json); "" = none
  int jobs = 1;             ///< --jobs N: files identified at once (threads), >= 1
  std::string date_from;    ///< --date-from name|column:NAME; "" = no dates
  std::string drift;        ///< --drift FILE: the drift table (CSV, or JSON by .json), needs dates
  double drift_threshold = 1.0;  ///< --drift-threshold K: flag |change| > K combined std
  std::string shard;        ///< --shard K/N: only these files, a part file to --table PART.json; "" = all
  CLI::Option* table_opt = nullptr;  ///< set by add_batch_options
  const CLI::App* command = nullptr;  ///< the method subcommand (set by add_batch_options): its options key a part
  /// The method's name (set with the subcommand): the `method` of the rows of files that failed
  /// before the method ran (a file that cannot be read).
  std::string method;
};

/// Adds --table, --jobs, --shard, --date-from, --drift and --drift-threshold to `cmd` (group "Batch").
void add_batch_options(CLI::App* cmd, BatchOptions& o);

/// One file of a batch and its global index (0-based place in the expanded DATA list).
struct BatchJob {
  std::size_t index = 0;
  std::string file;
};

/// The jobs of DATA arguments, in order: a folder gives its .csv and .mat files (sorted by name,
/// subfolders not read), anything else is one file (a missing one is kept: its row says so).
/// \throws std::invalid_argument for a folder without data files, or no DATA.
std::vector<BatchJob> batch_jobs(const std::vector<std::string>& data);

/// True when the DATA arguments and options ask for a batch: more than one DATA, a folder,
/// --table, --shard or --drift given. One file without them is the single-file command, unchanged.
bool is_batch(const std::vector<std::string>& data, const BatchOptions& o);

/// One row: the job, the log's date (empty without --date-from) and the result (a Result with
/// status error and the message for a file that failed, however it failed).
struct BatchRow {
  BatchJob job;
  LogDate date;
  Result result;
};

/// Identifies every job with `identify(file)` on `threads` threads (handed out one at a time).
/// An exception of one file (bad file, column, option) becomes its row's error; the others go on.
/// `date_from`: "" (none), "name" (log_date_from_name) or "column:NAME" (POSIX time in the
/// first sample of column NAME, or scalar NAME, read by `date_of_column`).
/// \returns the rows in job order.
std::vector<BatchRow> run_batch(const std::vector<BatchJob>& jobs, int threads,
                                const std::function<Result(const std::string& file)>& identify,
                                const std::string& date_from,
                                const std::function<double(const std::string& file, const std::string& column)>& date_of_column);

/// The table: columns index, file, [date,] status, message, method, model, axis, then each
/// parameter P as P, P_std, P_unit (grown columns of fleet/shard.hpp: in order of first appearance by
/// job index), then relative_error_percent, rmse, rmse_unit, samples, sha256; one row per BatchRow
/// (index and samples as integers, NaN where a row has no value, e.g. a failed file's parameters).
RowTable batch_table(const std::vector<BatchRow>& rows, bool with_date);

/// The key of a batch's part files: SHA-256 (hex) of what decides the rows: the method, the
/// subcommand's options given (o.command; not the output and batch options, the threads or the
/// shard), --date-from and every job's file name with its size in bytes (null when missing), in
/// order. The files' contents are not read (each shard would read the whole fleet); each row's
/// sha256 column names the bytes it read.
std::string batch_key(const std::vector<BatchJob>& jobs, const BatchOptions& o);

/// The drift table (analysis/drift.hpp) of a batch table (batch_table's columns, with date): the
/// parameters (grown columns P with P_std and P_unit) of its ok rows, by the date column (ISO, to
/// the second). An unsharded batch and `frictionlab merge` of its parts both take the drift from
/// the table, so the two agree.
/// \throws std::invalid_argument when the table has no date column (identify ran without
///         --date-from), a date cannot be read (naming the row's file), or as drift_table.
std::vector<DriftRow> table_drift(const RowTable& table, double threshold);

/// Writes the drift table to `drift_file` (CSV, or JSON when it ends in .json; "" = none) and the
/// drift figure to `plot` (one panel per parameter, value +- std against days since the first log,
/// flagged logs marked; "" = none, and none when `drift` is empty) through write_file_atomic and
/// write_figure. `threshold` labels the flagged marks. \throws std::invalid_argument as they do.
void write_drift(const std::vector<DriftRow>& drift, const std::string& drift_file, const std::string& plot,
                 double threshold, bool overwrite);

/// Runs a batch for a parsed method subcommand: checks the outputs first (--table, --drift,
/// --plot; --json and --report are one file's outputs and are refused with a batch), identifies
/// every job, writes the table (stdout when --table is not given), the drift table and figure,
/// and prints "N files: K ok, F failed" on stderr, one line per failure. With --shard K/N: the
/// shard's jobs only, written as a part file (fleet/shard.hpp, command "identify", key batch_key) to
/// --table PART.json; --drift and --plot are refused (the drift needs every file).
/// `inputs`: the run's other input files (the method's own, e.g. --static); every job's file is
/// an input too (check_run_files of output.hpp).
/// \returns 0 when at least one file gave a result (or the shard has no files), 2 when every
/// file failed (the table or part is still written).
int run_identify_batch(const std::vector<std::string>& data, const BatchOptions& o, const std::string& json,
                       const std::string& report, const std::string& plot, bool overwrite,
                       const std::function<Result(const std::string& file)>& identify,
                       const std::function<double(const std::string& file, const std::string& column)>& date_of_column,
                       const std::vector<RunFile>& inputs = {});

}  // namespace frictionlab::cli
