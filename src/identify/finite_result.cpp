#include "frictionlab/identify/finite_result.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string_view>
#include <utility>

#include "frictionlab/error.hpp"
#include "frictionlab/format.hpp"

namespace frictionlab {
namespace {

bool separator(char c) {
  return std::isspace(static_cast<unsigned char>(c)) || std::string_view(",;=:()[]{}|<>\"").find(c) != std::string_view::npos;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// A word as printf and to_chars write a non-finite double: [+-](inf|infinity|nan|nan(chars)).
bool non_finite(std::string_view word) {
  std::string w = lower(word);
  if (!w.empty() && (w[0] == '-' || w[0] == '+')) w.erase(0, 1);
  if (w == "inf" || w == "infinity" || w == "nan") return true;
  return w.size() > 4 && w.compare(0, 4, "nan(") == 0 && w.back() == ')';
}

}  // namespace

std::string non_finite_word(std::string_view text) {
  std::size_t line = 1;
  for (std::size_t i = 0; i < text.size();) {
    if (separator(text[i])) {
      if (text[i] == '\n') ++line;
      ++i;
      continue;
    }
    std::size_t end = i;
    // nan(...) keeps its parentheses: printf may write the payload.
    while (end < text.size() && !separator(text[end])) ++end;
    if (end < text.size() && text[end] == '(' && lower(text.substr(i, end - i)).find("nan") != std::string::npos) {
      const std::size_t close = text.find(')', end);
      if (close != std::string_view::npos && text.substr(end, close - end).find('\n') == std::string_view::npos) end = close + 1;
    }
    const std::string_view word = text.substr(i, end - i);
    if (non_finite(word)) {
      std::string out = "'";  // appended piece by piece: GCC 12 warns (-Wrestrict) on "'" + std::string
      out.append(word);
      out += "' at line ";
      out += std::to_string(line);
      return out;
    }
    i = end;
  }
  return "";
}

std::string non_finite_figure(const Result& r) {
  if (!r.ok()) return "";
  auto bad = [](double x) { return !std::isfinite(x); };
  for (const Parameter& p : r.parameters) {
    if (bad(p.value)) return "parameter " + p.name + " = " + format_number(p.value);
    if (std::isinf(p.std)) return "std(" + p.name + ") = " + format_number(p.std);
  }
  if (r.fit.samples > 0) {
    if (bad(r.fit.rmse)) return "fit rmse = " + format_number(r.fit.rmse);
    if (bad(r.fit.relative_error_percent)) return "fit relative error = " + format_number(r.fit.relative_error_percent) + " %";
  }
  if (r.validation) {
    const ValidationFigures& v = *r.validation;
    if (v.samples > 0 && bad(v.rmse)) return "validation rmse = " + format_number(v.rmse);
    if (v.samples > 0 && v.signal_errors_percent.empty() && bad(v.relative_error_percent))
      return "validation relative error = " + format_number(v.relative_error_percent) + " %";
    for (const auto& [name, x] : v.signal_errors_percent)
      if (bad(x)) return "validation relative error of " + name + " = " + format_number(x) + " %";
  }
  if (std::isinf(r.diagnostics.condition_number)) return "condition number = " + format_number(r.diagnostics.condition_number);
  for (const auto& [name, x] : r.diagnostics.numbers)
    if (std::isinf(x)) return "diagnostics " + name + " = " + format_number(x);
  for (const auto& [group, items] : r.diagnostics.groups)
    for (const auto& [name, x] : items)
      if (std::isinf(x)) return "diagnostics " + group + "." + name + " = " + format_number(x);
  for (const auto& [list, rows] : r.diagnostics.lists)
    for (const auto& row : rows)
      for (const auto& [name, x] : row)
        if (std::isinf(x)) return "diagnostics " + list + "[]." + name + " = " + format_number(x);
  // The texts: a warning formatted from an intermediate figure that overflowed ("variance
  // inflation nan") is a figure that is not finite as much as a parameter is.
  const auto in_text = [](const std::string& where, std::string_view text) {
    const std::string word = non_finite_word(text);
    return word.empty() ? word : where + " word " + word;
  };
  std::string found = in_text("the message's", r.message);
  for (std::size_t i = 0; found.empty() && i < r.diagnostics.warnings.size(); ++i)
    found = in_text("warning " + std::to_string(i + 1) + "'s", r.diagnostics.warnings[i]);
  for (auto it = r.diagnostics.texts.begin(); found.empty() && it != r.diagnostics.texts.end(); ++it)
    found = in_text("diagnostics " + it->first + "'s", it->second);
  for (auto it = r.json_sections.begin(); found.empty() && it != r.json_sections.end(); ++it)
    found = in_text(it->first + "'s", it->second);
  if (found.empty() && r.validation)
    for (auto it = r.validation->json_sections.begin(); found.empty() && it != r.validation->json_sections.end(); ++it)
      found = in_text("validation " + it->first + "'s", it->second);
  if (found.empty()) found = in_text("the fit's quantity", r.fit.quantity + " " + r.fit.unit);
  return found;
}

Result finite_or_error(Result r) {
  // A NaN std means "not determined" (models/parameter.hpp): say so wherever it arises.
  if (r.ok())
    for (Parameter& p : r.parameters)
      if (std::isnan(p.std) && p.flag.empty()) {
        p.flag = "undetermined";
        if (std::find(r.diagnostics.undetermined.begin(), r.diagnostics.undetermined.end(), p.name) ==
            r.diagnostics.undetermined.end())
          r.diagnostics.undetermined.push_back(p.name);
        r.diagnostics.warnings.push_back("the std of " + p.name + " could not be formed in double precision (the data's "
                                         "scales are extreme): " + p.name + " is reported undetermined");
      }
  const std::string what = non_finite_figure(r);
  if (what.empty()) return r;
  r.status = ResultStatus::error;
  r.code = errc::output_not_finite;
  r.message = (r.data_file.empty() ? std::string() : r.data_file + ": ") + r.method + ": " + what +
              " is not a finite number (values or scales beyond what double precision holds); the data cannot "
              "give an answer";
  return r;
}

}  // namespace frictionlab
