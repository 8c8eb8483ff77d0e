#pragma once
// The result every identification method returns: parameters with standard deviations and
// units, fit figures, optional validation figures on a second data set, diagnostics, and a
// status with a message. Its JSON form is the MODEL.json of the command line (docs/contract.md).

#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "frictionlab/models/friction_law.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// How well the identified model reproduces the data it was identified on.
struct FitFigures {
  double relative_error_percent = std::numeric_limits<double>::quiet_NaN();  ///< 100 ||y - y_hat|| / ||y||
  double rmse = std::numeric_limits<double>::quiet_NaN();                    ///< sqrt(mean((y - y_hat)^2)), unit of y
  std::size_t samples = 0;                                                   ///< samples in the fit
  /// The fitted signal in words ("drive force", "energy lost per half cycle", "position"), set by
  /// the method (identify/method.hpp); empty when there is no single one.
  std::string quantity;
  std::string unit;  ///< rmse's unit on the result's axis ("N", "N m", "J", "m"); empty with quantity
};

/// The same figures on a second data set (cross-test), with that file's name and digest.
struct ValidationFigures {
  std::string file;
  std::string sha256;
  double relative_error_percent = std::numeric_limits<double>::quiet_NaN();
  double rmse = std::numeric_limits<double>::quiet_NaN();
  std::size_t samples = 0;
  /// Per-signal relative errors (%), e.g. "position", "velocity", "acceleration", "force" of
  /// `frictionlab validate`. When not empty, JSON "relative_error_percent" is this object
  /// instead of the single number above.
  std::map<std::string, double> signal_errors_percent;
  /// Signals behind the cross-test figure, in SI units (not written to JSON): idim's cross_test
  /// gives "time", "force" (measured) and "force_model" (predicted), of one length.
  std::map<std::string, std::vector<double>> series;
  /// Further figures as JSON text by key, each written under its key inside JSON "validation"
  /// (validate on an xy-table: "contour", the circular-test figures of measured and simulated).
  std::map<std::string, std::string> json_sections;
};

/// Correlation of the parameter estimates: matrix[i][j] = cov_ij / sqrt(cov_ii cov_jj) of the
/// parameters `names` (unit diagonal, symmetric). Entries involving a parameter without a std
/// (undetermined, at a bound) are NaN off the diagonal (null in JSON). Empty when not computed.
struct ParameterCorrelation {
  std::vector<std::string> names;
  std::vector<std::vector<double>> matrix;  ///< names.size() x names.size()
};

/// Numerical health of an identification.
struct Diagnostics {
  double condition_number = std::numeric_limits<double>::quiet_NaN();  ///< of the regressor matrix (NaN if none)
  std::vector<std::string> warnings;                                   ///< human-readable, one sentence each
  std::map<std::string, double> numbers;                               ///< free-form figures ("dt", "residual_std", ...)
  /// Named groups of figures, e.g. groups["readoff"] = {{"Fs", 0.1}, {"Fc", 0.08}} (a JSON object each).
  std::map<std::string, std::map<std::string, double>> groups;
  /// Named lists of records, e.g. lists["points"] = one {"velocity": v, "force": f} per segment
  /// (a JSON array of objects each).
  std::map<std::string, std::vector<std::map<std::string, double>>> lists;
  /// Named words, e.g. texts["regressors_from"] = "position" (a JSON string each).
  std::map<std::string, std::string> texts;
  /// Parameters the data cannot determine, and parameters that ended at a bound (std NaN each).
  std::vector<std::string> undetermined, at_bound;
  ParameterCorrelation correlation;
};

enum class ResultStatus { ok, error };

/// Outcome of an identification method.
struct Result {
  ResultStatus status = ResultStatus::ok;
  std::string message;      ///< why status is error (names file, parameter, expectation); empty when ok
  /// The error code (frictionlab/error.hpp) of a status error that has one: "output.not_finite"
  /// when the figures are not finite numbers (finite_or_error, identify/finite_result.hpp);
  /// empty when ok and for data that gives no answer (no motion, too few segments).
  std::string code;
  std::string method;       ///< "idim", "sweep", ...
  std::string model;        ///< friction law name, e.g. "coulomb-viscous"
  std::string data_file;    ///< identification data file
  std::string data_sha256;  ///< its sha256
  /// The axis the units are on (set by the method from its options; never guessed from units).
  Axis axis = Axis::linear;
  std::vector<Parameter> parameters;
  FitFigures fit;
  std::optional<ValidationFigures> validation;
  Diagnostics diagnostics;
  /// The identified friction law in its file form, ready for simulate and validate (absent when
  /// the estimates do not make a valid law, e.g. a negative Coulomb level; a warning says why).
  std::optional<LawSpec> law;
  /// Signals behind the result's figures, by name, in SI units (not written to JSON): e.g. idim
  /// "time", "force", "force_model", "velocity", "friction" (force less inertia and offset),
  /// "friction_model" (the friction terms), "law_velocity" and "law_force" (the friction terms
  /// over a velocity grid); sweep "velocity", "force", "force_std"; decay "time",
  /// "position", "peak_time", "peak_position". Series that share a prefix share a length.
  std::map<std::string, std::vector<double>> series;
  /// Figures that are not parameters, as JSON text by key, each written under its key at the top
  /// level of to_json: `frictionlab analyze`'s "result" (the envelope or stick-slip figures); a key
  /// "diagnostics.NAME" is written as NAME under "diagnostics" (auto's "diagnostics.selection").
  std::map<std::string, std::string> json_sections;

  bool ok() const { return status == ResultStatus::ok; }
  /// The parameter named `name`, or nullptr.
  const Parameter* find(const std::string& name) const;
  /// Value of the parameter `name`. \throws std::invalid_argument listing the parameters.
  double value(const std::string& name) const;
};

/// JSON text of a result (MODEL.json schema 2, docs/contract.md):
/// {"schema":2,"status":"ok"|"error","message":...,"method":...,"model":...,
///  "data":{"file":...,"sha256":...},"axis":"linear"|"rotary","parameters":{"Fc":{"value":v,"std":s,"unit":"N"},...},
///  "fit":{"relative_error_percent":e,"rmse":r,"samples":n,"quantity":...,"unit":...} (the last two when set),"validation":{...} (only when set),
///  "diagnostics":{"condition_number":c,"warnings":[...],"undetermined":[...],"at_bound":[...],
///  "correlation":{"names":[...],"matrix":[[...]]} (only when computed), ...numbers, ...groups,
///  ...lists, ...texts}}. Non-finite numbers are null. A status error with a `code` also has
///  "error":{"code":...,"message":...} (the error JSON's form, docs/contract.md).
/// Then each of json_sections under its key (under diagnostics for "diagnostics.NAME"). `indent` < 0 gives one line. (Returns text so
/// nlohmann_json stays a private dependency.)
/// \throws std::invalid_argument naming the key when a json_sections text is not valid JSON.
std::string to_json(const Result& result, int indent = 2);

}  // namespace frictionlab
