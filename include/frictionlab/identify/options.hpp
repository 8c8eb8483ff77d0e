#pragma once
// The options of an identification method, declared once in a table (name, type, unit, default,
// help, valid range) that the method's library file gives with its MethodInfo (identify/method.hpp).
// The command line makes its flags and their checks from the table (`--NAME`), the Python
// package its keywords (NAME with '-' as '_') and their checks, and `frictionlab help --markdown`
// the options reference; a result records the value each option had (options_json). A method
// turns the values into its options struct (e.g. make_sweep_options), taking every default from
// the table, whose defaults are those of the struct: one source for each.

#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// What an option's value is.
enum class OptionType {
  number,   ///< a real number (double), in [min, max]; `words` may name non-numeric values ("search")
  integer,  ///< a whole number (long long), in [min, max]
  text,     ///< a word; one of `words` when that is not empty
  flag,     ///< on or off (a CLI flag without a value; Python True/False)
  list,     ///< words: a comma-separated list on the command line (and Python), or repeated (`repeatable`)
  column,   ///< a data column: its name on the command line; an array of the data's length in Python
  file,     ///< a file: its path on the command line; in Python what the file holds (the help says what)
};

/// "number", "integer", "text", "flag", "list", "column", "file".
const char* to_string(OptionType type);

/// The value of a given option: flag bool, integer long long, number double, text/column/file
/// std::string, list std::vector<std::string>.
using OptionValue = std::variant<bool, long long, double, std::string, std::vector<std::string>>;

/// A condition on another option of the same table, under which an option applies to a run
/// (OptionSpec::applies_if): the report lists the defaults of the options that apply.
struct OptionCondition {
  std::string option;  ///< the other option's name ("iv", "terms")
  /// Empty: `option` is given, or is a flag that is on. Otherwise: its value (given, else its
  /// default) is one of these words (a text), or holds one of them (a list).
  std::vector<std::string> words;
  bool negated = false;  ///< the condition is that the above does not hold
};

/// `name` is given (a flag: on): "only with --iv".
inline OptionCondition when_given(std::string name) { return {std::move(name), {}, false}; }
/// `name` is not given (a flag: off): "not with --segment".
inline OptionCondition unless_given(std::string name) { return {std::move(name), {}, true}; }
/// `name`'s value is (a text) or holds (a list) one of `words`: "only when --terms holds stribeck".
inline OptionCondition when_value(std::string name, std::vector<std::string> words) {
  return {std::move(name), std::move(words), false};
}

/// The unit of an option's value when a condition on another option holds (OptionSpec::units):
/// idim's --kp is N/m with --controller pid and 1/s with --controller emps-pd.
struct OptionUnit {
  OptionCondition when;     ///< the other option's value that decides the unit (when_value)
  std::string unit;         ///< on a linear axis ("N/m")
  std::string rotary_unit;  ///< on a rotary axis ("N m/rad"); "" when the same as `unit`
};

/// One option of a method.
struct OptionSpec {
  std::string name;  ///< the command line's flag without "--" ("min-duration"): the contract
  OptionType type = OptionType::number;
  std::string unit;  ///< of the value on a linear axis ("m/s"), with rotary_unit; "" when none
  std::string rotary_unit;  ///< on a rotary axis ("rad/s"); "" when the same as `unit`
  /// Units that another option decides (the controller's type: N/m or 1/s), each with its
  /// condition; `unit` and `rotary_unit` are then left empty. A run's unit is the first case whose
  /// condition holds (OptionValues::unit); unit_on and unit_text name every case.
  std::vector<OptionUnit> units;
  /// The default; none when the default is computed from the data (the help says how) or there
  /// is none (an optional input, a required option).
  std::optional<OptionValue> default_value;
  std::string help;  ///< one or two sentences: what it does, its trade-off, the computed default
  /// Valid range of a number or integer (inclusive unless the *_open flag is set).
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false, max_open = false;
  /// text: the values allowed (empty: any); number: words accepted instead of a number.
  std::vector<std::string> words;
  /// number: the name of a scalar variable of the data file is accepted instead of a number (a MAT
  /// file's gain "Kp"); it is kept as text, and the method resolves it against the file
  /// (resolve_constant, io/columns.hpp) and checks the number it finds.
  bool scalar_name = false;
  bool required = false;
  bool repeatable = false;  ///< list: the flag may be given several times, one item each
  /// What is expected, in words, when the generated phrase (expected()) does not say it well:
  /// "a Stribeck velocity (m/s or rad/s) or 'search'".
  std::string expected_text;
  /// Why a word not among `words` is refused, when that says more than "expected ...": "cannot be
  /// fitted to a friction-velocity map" gives "SPELLED 'TEXT' cannot be fitted to a
  /// friction-velocity map; expected A, B or C".
  std::string refusal;
  /// Former Python keywords of this option, still accepted with a DeprecationWarning.
  std::vector<std::string> deprecated_keywords;
  /// When the option applies to a run: every condition holds (empty: always). An option that
  /// does not apply is not used by the run whatever its value (the method may refuse it when
  /// given); the report lists an option's default only where it applies.
  std::vector<OptionCondition> applies_if;
  /// For an option without a default that a run may take from elsewhere when it is not given
  /// (--controller from the --scenario's controller.type): the result's diagnostics text that
  /// records the value taken ("iv_controller_type"), from which OptionValues::unit decides the
  /// units that depend on this option. "" when none.
  std::string taken_text;

  /// The Python keyword: the name with '-' as '_', and "_" appended to a Python reserved word
  /// ("from" -> "from_").
  std::string keyword() const;
  /// The unit on an axis ("rotary": rotary_unit when set); with `units`, every case's unit on
  /// the axis ("N/m or 1/s"): the run decides which (OptionValues::unit).
  std::string unit_on(bool rotary) const;
  /// "m/s or rad/s", "s", "" (both axes' units in words, for help and the reference); with
  /// `units`, each case's with its condition's words: "N/m or N m/rad with pid, 1/s with emps-pd".
  std::string unit_text() const;
  /// The valid values in words: "a number > 0", "an integer >= 1", "one of position, velocity",
  /// "a number >= 0 or search".
  std::string expected() const;
  /// The range in words: ">= 0", "> 0 and <= 1", "" (any); with `finite`, "finite and > 0".
  std::string rule(bool finite = false) const;
};

/// Checks `value` against `spec` and returns it in the spec's type (an integer given for a
/// number becomes a double). `spelled` is the option as the caller names it ("--min-duration",
/// "sweep: min_duration").
/// \throws std::invalid_argument "SPELLED = VALUE must be RULE (UNIT)" for a number out of range
///         (or not finite), "SPELLED 'TEXT': expected EXPECTED (UNIT)" for a word not among the
///         allowed ones, "SPELLED: expected EXPECTED, got KIND" for a value of another type.
OptionValue check_option(const OptionSpec& spec, const OptionValue& value, const std::string& spelled);

/// The value of `spec` from the text of the command line (a number for number, "on"/"off" for a
/// flag, a comma-separated list for list), checked as check_option. Words listed for a number are
/// kept as text.
/// \throws std::invalid_argument naming `spelled`, the text and what was expected.
OptionValue parse_option(const OptionSpec& spec, const std::string& text, const std::string& spelled);

/// The value as text ("0.5", "true", "a,b"; a number in the shortest form that reads back the same).
std::string option_text(const OptionValue& value);

/// The options of one run of a method: those given (checked), over the table's defaults.
class OptionValues {
 public:
  OptionValues() = default;
  /// Values over `table` (which must outlive this object).
  explicit OptionValues(const std::vector<OptionSpec>& table) : table_(&table) {}

  /// Sets option `name` (checked by check_option, named `spelled`).
  /// \throws std::invalid_argument for a name the table lacks (listing the names) or a bad value.
  void set(const std::string& name, const OptionValue& value, const std::string& spelled);
  bool given(const std::string& name) const { return given_.count(name) > 0; }
  /// The given value, else the default, else nullopt. \throws std::invalid_argument for a name
  /// the table lacks (a programming error of the method's own file).
  std::optional<OptionValue> get(const std::string& name) const;
  /// get as a number (NaN when none), integer, flag (false when none), text ("" when none), list.
  double number(const std::string& name) const;
  long long integer(const std::string& name) const;
  bool flag(const std::string& name) const;
  std::string text(const std::string& name) const;
  std::vector<std::string> list(const std::string& name) const;
  /// Whether option `name` applies to this run: every condition of its applies_if holds for
  /// these values (given or not). \throws std::invalid_argument for a name the table lacks, in
  /// `name` or in one of its conditions (a programming error of the method's own file).
  bool applies(const std::string& name) const;
  /// The unit of option `name`'s value in this run, on a rotary or linear axis: the first of
  /// its `units` whose condition holds, else OptionSpec::unit_on. A condition on an option that
  /// is not given and has no default reads the value the run took from `texts` (the result's
  /// diagnostics texts, by the option's taken_text: the scenario's controller type); with none
  /// there, no case holds and the unit names every case ("N/m or 1/s").
  /// \throws std::invalid_argument for a name the table lacks.
  std::string unit(const std::string& name, bool rotary, const std::map<std::string, std::string>& texts = {}) const;

  const std::vector<OptionSpec>& table() const;
  const std::map<std::string, OptionValue>& given_values() const { return given_; }

 private:
  const OptionSpec& spec(const std::string& name) const;
  // Whether condition `c` holds for these values (`texts`: OptionValues::unit's).
  bool holds(const OptionCondition& c, const std::map<std::string, std::string>& texts) const;
  const std::vector<OptionSpec>* table_ = nullptr;
  std::map<std::string, OptionValue> given_;
};

/// JSON text (one object) of every option of `values`' table that shaped a result, in table
/// order: {"NAME": {"value": v, "unit": "s", "given": true|false}, ...}; value null when the
/// default is computed from the data (the result's diagnostics say what was used) or the option
/// is absent; a column or file holds its name. The unit is the run's (OptionValues::unit on the
/// axis `rotary` picks, with the result's diagnostics `texts`).
std::string options_json(const OptionValues& values, bool rotary, const std::map<std::string, std::string>& texts = {});

}  // namespace frictionlab
