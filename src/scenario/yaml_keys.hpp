#pragma once
// Checks of parsed YAML shared by the scenario and law readers (private to src/io).

#include <yaml-cpp/yaml.h>

#include <map>
#include <set>
#include <stdexcept>
#include <string>

#include "frictionlab/budget.hpp"
#include "frictionlab/error.hpp"

namespace frictionlab::detail {

// The file and dotted key of a message prefix "FILE: section.key" (a prefix without ": " is a
// file name alone), plus `key`: the fields of an InputError about a scenario or law file.
inline ErrorFields key_fields(const std::string& where, const std::string& key = "") {
  ErrorFields f;
  const auto sep = where.find(": ");
  f.file = sep == std::string::npos ? where : where.substr(0, sep);
  const std::string section = sep == std::string::npos ? std::string() : where.substr(sep + 2);
  f.key = section.empty() ? key : key.empty() ? section : section + "." + key;
  return f;
}

// Wraps a constructor's own message ("axis: M = 0 must be > 0") with the file and key path
// `where`, keeping the code of an InputError; any other refusal is scenario.value (a value the
// model refused).
template <class F>
auto with_context(const std::string& where, F&& make) {
  try {
    return make();
  } catch (const std::invalid_argument& e) {
    ErrorFields f = error_fields(e);
    const ErrorFields at = key_fields(where);
    if (f.file.empty()) f.file = at.file;
    if (f.key.empty()) f.key = at.key;
    const std::string code = dynamic_cast<const InputError*>(&e) ? error_code(e) : std::string(errc::scenario_value);
    throw InputError(code, where + ": " + e.what(), f);
  }
}

/// The most nodes a scenario or law document may expand to, aliases expanded (times the budget
/// factor, frictionlab/budget.hpp), and the deepest nesting: a 1 kB alias bomb (each level a list
/// of nine aliases of the one before) expands to 9^8 nodes, and every reader walks the expansion.
inline constexpr double kMaxYamlNodes = 1e6;
inline constexpr int kMaxYamlDepth = 100;

/// Refuses a mapping that gives a key twice (`k: 2.0` then `k: 3.0`), anywhere in the document:
/// yaml-cpp keeps both pairs and a lookup silently finds one of them, so the user's intent is
/// unknown. Also refuses keys that are not plain scalars (a list or mapping as a key), and a
/// document that expands (aliases repeated) to more than kMaxYamlNodes nodes or nests deeper than
/// kMaxYamlDepth levels, before any reader walks it.
/// \throws std::invalid_argument "WHERE: line L: key 'k' given twice (first on line F)";
///         InputError(budget.work) for the expansion and the depth.
inline void check_unique_keys(const YAML::Node& node, const std::string& where, double& nodes, int depth) {
  if (!node || !node.IsDefined()) return;
  const std::string file = where.substr(0, where.find(": "));
  if (++nodes > kMaxYamlNodes * budget_factor()) {
    throw InputError(errc::budget_work,
                     where + ": the document expands to more than " + std::to_string(static_cast<long long>(kMaxYamlNodes * budget_factor())) +
                         " nodes with its aliases (&name / *name) expanded; expected a scenario without repeated aliases "
                         "(raise the limit with --budget FACTOR)",
                     {.file = file});
  }
  if (depth > kMaxYamlDepth) {
    throw InputError(errc::budget_work,
                     where + ": line " + std::to_string(node.Mark().line + 1) + ": nested more than " +
                         std::to_string(kMaxYamlDepth) + " levels deep; expected a scenario's few levels",
                     {.file = file});
  }
  if (node.IsSequence()) {
    for (const auto& item : node) check_unique_keys(item, where, nodes, depth + 1);
    return;
  }
  if (!node.IsMap()) return;
  std::map<std::string, int> seen;  // key -> 1-based line of its first occurrence
  for (const auto& kv : node) {
    const int line = kv.first.Mark().line + 1;
    if (!kv.first.IsScalar())
      throw InputError(errc::scenario_key_unknown, where + ": line " + std::to_string(line) + ": a key must be a name, not a list or mapping",
                       {.file = file, .row = static_cast<std::size_t>(line)});
    const std::string key = kv.first.Scalar();
    const auto [it, fresh] = seen.emplace(key, line);
    if (!fresh)
      throw InputError(errc::scenario_key_duplicate,
                       where + ": line " + std::to_string(line) + ": key '" + key + "' given twice (first on line " +
                           std::to_string(it->second) + "); give each key once",
                       {.file = file, .row = static_cast<std::size_t>(line), .key = key});
    check_unique_keys(kv.second, where, nodes, depth + 1);
  }
}

inline void check_unique_keys(const YAML::Node& node, const std::string& where) {
  double nodes = 0;
  check_unique_keys(node, where, nodes, 0);
}

/// Refuses a quoted value whose closing quote is missing. yaml-cpp reads an unterminated quote
/// to the end of the file as one value (the rest of the file swallowed, then "missing 'plant'"):
/// every quoted scalar of the parsed `node` is scanned again in `text` from its opening quote, by
/// YAML's own rules (\ escapes in "...", '' in '...'), and one that reaches the end of the text
/// is an InputError scenario.format "FILE: line L, column C: unterminated quote: ...".
inline void check_quotes_closed(const YAML::Node& node, const std::string& text, const std::string& file,
                                std::set<int>& seen) {
  if (!node.IsDefined()) return;
  // Each node of the text once: an alias is the node it names, so a small file of aliases (an
  // alias bomb) is walked in the time of its text, not of its expansion.
  if (!node.Mark().is_null() && !seen.insert(node.Mark().pos).second) return;
  if (node.IsScalar()) {
    if (node.Tag() != "!") return;  // a plain scalar: no quotes
    const YAML::Mark m = node.Mark();
    if (m.is_null() || m.pos < 0 || static_cast<std::size_t>(m.pos) >= text.size()) return;
    const std::size_t open = static_cast<std::size_t>(m.pos);
    const char q = text[open];
    if (q != '"' && q != '\'') return;
    for (std::size_t i = open + 1; i < text.size(); ++i) {
      if (q == '"' && text[i] == '\\') {
        ++i;
        continue;
      }
      if (text[i] != q) continue;
      if (q == '\'' && i + 1 < text.size() && text[i + 1] == '\'') {
        ++i;
        continue;
      }
      return;  // closed
    }
    throw InputError(errc::scenario_format,
                     file + ": line " + std::to_string(m.line + 1) + ", column " + std::to_string(m.column + 1) +
                         ": unterminated quote: the value opened by " + (q == '"' ? "\"" : "'") +
                         " here has no closing " + (q == '"' ? "\"" : "'") + " before the end of the file",
                     {.file = file, .row = static_cast<std::size_t>(m.line + 1)});
  }
  if (node.IsSequence() || node.IsMap())
    for (const auto& item : node) {
      if (node.IsMap()) {
        check_quotes_closed(item.first, text, file, seen);
        check_quotes_closed(item.second, text, file, seen);
      } else {
        check_quotes_closed(item, text, file, seen);
      }
    }
}

inline void check_quotes_closed(const YAML::Node& node, const std::string& text, const std::string& file) {
  std::set<int> seen;
  check_quotes_closed(node, text, file, seen);
}

/// "WHERE: line L, column C: MESSAGE" for an exception yaml-cpp raised while a node was read
/// (a value of the wrong kind where the reader asked for one).
inline InputError yaml_error(const std::string& where, const YAML::Exception& e) {
  const std::string file = where.substr(0, where.find(": "));
  if (e.mark.is_null()) return InputError(errc::scenario_value, where + ": " + e.msg, {.file = file});
  return InputError(errc::scenario_value,
                    where + ": line " + std::to_string(e.mark.line + 1) + ", column " + std::to_string(e.mark.column + 1) +
                        ": " + e.msg,
                    {.file = file, .row = static_cast<std::size_t>(e.mark.line + 1)});
}

}  // namespace frictionlab::detail
