#pragma once
// Splitting a run of many independent jobs (grid points of `analyze map`, files of a batch) over
// processes, and joining their outputs: the shard spec K/N, which jobs a shard runs, the part
// file each shard writes, and the merge that checks and joins the parts. Rows of named columns
// plus a key, nothing specific to one command.
//
// Selection: shard K of N runs the jobs i (0-based, in the run's global order) with
// i % N == K - 1 (round robin). Neighbouring jobs often cost alike (a grid's last axis varies
// fastest), so round robin spreads slow regions of a grid over all shards where contiguous blocks
// would give one shard all of them.
//
// Part file (JSON, one object):
//   {"frictionlab_part": 1, "command": "analyze map", "key": "<64 hex>", "shard": "2/4",
//    "total": 12, "columns": ["x", "class", ...], "rows_at": "/result/rows",
//    "envelope": {...}, "rows": [[index, cell, ...], ...]}
// and, for a table whose columns depend on its rows (see GrownColumns), "columns_at": "/columns"
// and "grown": {"begin": 8, "end": 14, "first": [0, 0, 0, 3, 3, 3]}.
// `key` identifies the run (the command's choice: a SHA-256 of everything that decides the
// rows: input files, grid, options; never the shard or the thread count); `total` is the number of
// jobs of the whole run; `envelope` is the whole run's JSON output without its rows, which go in at
// the JSON pointer `rows_at` (an array of objects, column -> cell). A cell is a number, a string
// or null (a number that is not finite), an integer or true/false. Merged output is written by the same functions as an
// unsharded run's, so the two are equal byte for byte.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Shard K of N (1 <= K <= N).
struct ShardSpec {
  std::size_t index = 1;  ///< K, 1-based
  std::size_t count = 1;  ///< N
  bool whole() const { return count == 1; }
  std::string text() const;  ///< "K/N"
};

/// Parses "K/N" (integers, 1 <= K <= N). \throws std::invalid_argument "OPTION 'TEXT': ..." naming
/// what is wrong (not K/N, K or N not a positive integer, K > N).
ShardSpec parse_shard(const std::string& text, const std::string& option = "--shard");

/// Whether job i (0-based) belongs to the shard: i % N == K - 1.
bool in_shard(std::size_t i, const ShardSpec& shard);

/// The jobs of the shard among `total`, in increasing order.
std::vector<std::size_t> shard_jobs(std::size_t total, const ShardSpec& shard);

/// One cell: a number (NaN and infinities are written as an empty CSV cell and JSON null), a text,
/// an integer (a count or index: JSON writes it without ".0") or a flag (true / false).
/// Construct from std::string, never from a string literal (it would become a flag).
using Cell = std::variant<double, std::string, std::int64_t, bool>;

/// Columns that the rows bring with them (an identification's parameters depend on the data and
/// the model: a shard whose files all failed has none): columns[begin, end) of a RowTable are the
/// union over its rows in order of first appearance by job index, and first[c - begin] is the job
/// index of the first row that has column c. A row without one of them holds NaN there. merge_parts
/// joins them over the parts in the same order, so the merged columns equal the unsharded run's
/// whichever jobs each shard got; the columns before `begin` and from `end` are fixed.
struct GrownColumns {
  std::size_t begin = 0;
  std::size_t end = 0;
  std::vector<std::size_t> first;  ///< size end - begin
};

/// Rows of named columns, each row with its job's global index.
struct RowTable {
  std::vector<std::string> columns;
  std::vector<std::size_t> index;       ///< global job index of each row
  std::vector<std::vector<Cell>> rows;  ///< rows[r].size() == columns.size()
  std::optional<GrownColumns> grown;    ///< set when some columns come from the rows
};

/// What a (sharded or whole) run writes: its rows and what identifies the run.
struct Part {
  std::string command;      ///< e.g. "analyze map"
  std::string key;          ///< identifies the run (see above)
  ShardSpec shard;          ///< which shard (1/1 for a whole run)
  std::size_t total = 0;    ///< jobs of the whole run
  std::string envelope;     ///< the whole run's JSON output without rows (a JSON object, as text)
  std::string rows_at;      ///< JSON pointer in `envelope` where the rows go, e.g. "/result/rows"
  std::string columns_at;   ///< JSON pointer in `envelope` where table_json writes the column names; "" = none
  RowTable table;
};

/// The part file's text (JSON, see above).
std::string part_to_json(const Part& part);

/// Reads a part file. \throws std::invalid_argument naming the file when it cannot be read, is not
/// JSON, or is not a frictionlab part (naming the missing or malformed field).
Part read_part(const std::string& path);

/// Joins parts into the whole run: checks that all have the same command, key, shard count,
/// total, columns (the fixed ones, for a table with GrownColumns, whose grown columns are joined),
/// envelope, rows_at and columns_at (else the part is foreign, named with the field that
/// differs), that every shard 1..N is there exactly once (naming the duplicated part and the
/// missing shard), and that the rows cover every job 0..total-1 once; returns one Part (shard 1/1)
/// with the rows sorted by job index. `names` label the parts in messages (file names).
/// \throws std::invalid_argument as above; also for an empty list.
Part merge_parts(const std::vector<Part>& parts, const std::vector<std::string>& names);

/// The table as CSV: a header row of the column names, then one line per row; numbers in their
/// shortest form that reads back exactly, a non-finite number as an empty cell, a text quoted when
/// it holds a comma, quote or line break.
std::string table_csv(const RowTable& table);

/// The envelope with the rows (objects column -> cell, in row order) put in at rows_at (and the
/// column names at columns_at, when set), indented
/// by `indent` (< 0: one line), with a final newline. \throws std::invalid_argument when the envelope is not a JSON
/// object or rows_at does not name a place in it.
std::string table_json(const Part& part, int indent = 2);

/// Appends a grown column (GrownColumns) to `table` if it has none of that name, first seen in the
/// row of job `job`: inserted at table.grown->end, with NaN in the rows already there.
/// \returns the column's place in table.columns. \throws std::logic_error when table.grown is unset.
std::size_t grow_column(RowTable& table, const std::string& name, std::size_t job);

/// Writes the whole run's output to `path` through write_file_atomic: CSV for a .csv file, the JSON
/// of table_json for .json. \throws std::invalid_argument naming the path for another extension
/// or an existing file without `overwrite`.
void write_table(const std::string& path, const Part& part, bool overwrite);

}  // namespace frictionlab
