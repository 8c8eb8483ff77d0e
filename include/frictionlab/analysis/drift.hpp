#pragma once
// Fleet view: how identified parameters of one axis drift over many logs taken over time, and a
// simple condition-monitoring rule that flags a change larger than its combined uncertainty.
// The log's date comes from the file's name (log_date_from_name) or from a POSIX time stamp
// (log_date_from_posix: a column or scalar of the file).

#include <optional>
#include <string>
#include <vector>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The date (and time) a log was taken.
struct LogDate {
  /// ISO 8601 in UTC: "YYYY-MM-DD" when only the day is known, else "YYYY-MM-DDTHH:MM:SS".
  std::string iso;
  /// The same instant as POSIX time (s since 1970-01-01T00:00:00 UTC; midnight when only the day is known).
  double posix_seconds = 0.0;
};

/// The date in a file name: the last date in its base name (the folders are not read), in one of
/// the forms (separators between the date and the time: 'T', '_', '-' or ' '):
///   YYYY-MM-DD, YYYY_MM_DD, YYYYMMDD                                     (a day)
///   YYYY-MM-DD{T|_|-| }HH:MM[:SS], YYYY-MM-DD_HH-MM[-SS], YYYY-MM-DD_HHMM[SS],
///   YYYYMMDD{T|_|-}HHMM[SS]                                              (a day and a time)
/// e.g. "axis3_2026-11-02.csv", "log-20261102T0815.mat", "axis3_2026-11-02_08-15-30.csv".
/// Digits that do not form a valid calendar date (month 13, day 31 of a 30-day month, hour 24)
/// are not a date. Years 1970 to 2999.
/// \returns the date, or nullopt when the name holds none.
std::optional<LogDate> log_date_from_name(const std::string& path);

/// The date of POSIX time `seconds` (s since 1970-01-01 UTC; a data logger's time stamp).
/// \throws std::invalid_argument when `seconds` is not finite or outside 1970 to 2999.
LogDate log_date_from_posix(double seconds);

/// One identified parameter of one log.
struct DriftSample {
  std::string file;     ///< the log's file (names the row)
  LogDate date;         ///< when the log was taken
  std::string parameter;  ///< "Fc", "Fv", ...
  double value = 0.0;   ///< the estimate, in `unit`
  double std = 0.0;     ///< its standard deviation, in `unit` (NaN when unknown)
  std::string unit;     ///< "N", "N m s/rad", ...
};

/// One row of a drift table: a parameter of one log next to the previous log of that parameter.
struct DriftRow {
  DriftSample sample;
  /// value - previous log's value of the same parameter (unit); NaN for its first log.
  double change = 0.0;
  /// sqrt(std^2 + previous std^2) (unit); NaN for the first log or when either std is unknown.
  double combined_std = 0.0;
  /// |change| > threshold * combined_std. False when combined_std is NaN (nothing to judge by).
  bool flagged = false;
};

/// The drift table of `samples` (any order): grouped by parameter in order of first appearance,
/// each group in date order (logs of the same date keep their given order), each row compared
/// with the previous log of its parameter.
/// The rule (condition monitoring): a change between consecutive logs larger than `threshold`
/// times its combined standard deviation is flagged. With independent normal errors and no real
/// change, |change| > 1 combined std happens in about 32 % of the pairs, > 2 in 4.6 %, > 3 in
/// 0.27 %: threshold 1 (default) flags every change the estimates can see at all; a fleet with
/// many logs will want 2 or 3 to keep false alarms rare.
/// \throws std::invalid_argument when `threshold` is not finite and > 0 (naming it), or a sample's
///         value is not finite (naming its file and parameter).
std::vector<DriftRow> drift_table(const std::vector<DriftSample>& samples, double threshold = 1.0);

}  // namespace frictionlab
