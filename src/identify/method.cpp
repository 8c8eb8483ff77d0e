#include "frictionlab/identify/method.hpp"

#include <sstream>
#include <stdexcept>

#include "frictionlab/identify/option_applies.hpp"
#include "method_support.hpp"

namespace frictionlab {

const std::vector<MethodInfo>& identification_methods() {
  // Each method's own file describes it (summary, fitted signal, options); its name and place
  // come from its line of FRICTIONLAB_METHODS.
  static const std::vector<MethodInfo> methods = [] {
    std::vector<MethodInfo> all;
#define FRICTIONLAB_METHOD_INFO(method)        \
  all.push_back(detail::method##_method_info()); \
  all.back().name = #method;                     \
  all.back().id = MethodId::FRICTIONLAB_METHOD_ENUM(method);
    FRICTIONLAB_METHODS(FRICTIONLAB_METHOD_INFO)
#undef FRICTIONLAB_METHOD_INFO
    return all;
  }();
  return methods;
}

const MethodInfo& method_info(std::string_view name) {
  std::string names;
  for (const auto& m : identification_methods()) {
    if (m.name == name) return m;
    names += (names.empty() ? "" : ", ") + m.name;
  }
  throw std::invalid_argument("identification method '" + std::string(name) + "' is not known; expected one of " +
                              names);
}

const MethodInfo& method_info(MethodId id) { return identification_methods().at(static_cast<std::size_t>(id)); }

const OptionSpec* MethodInfo::option(const std::string& option_name) const {
  for (const auto& o : options)
    if (o.name == option_name) return &o;
  return nullptr;
}

Result new_result(const MethodInfo& method, const std::string& model, Axis axis) {
  Result r;
  r.method = method.name;
  r.model = model;
  r.axis = axis;
  r.fit.quantity = method.fit_signal;
  if (method.fit_quantity) r.fit.unit = std::string(unit(*method.fit_quantity, axis));
  return r;
}

std::pair<std::string, std::string> fit_signal_and_unit(const Result& r) {
  if (!r.fit.quantity.empty() || !r.fit.unit.empty()) return {r.fit.quantity, r.fit.unit};
  for (const auto& m : identification_methods())
    if (m.name == r.method && m.fit_quantity) return {m.fit_signal, std::string(unit(*m.fit_quantity, r.axis))};
  return {};
}

namespace {
// A table cell: '|' escaped, no line breaks.
std::string cell(std::string s) {
  for (std::size_t at = s.find('|'); at != std::string::npos; at = s.find('|', at + 2)) s.replace(at, 1, "\\|");
  for (char& c : s)
    if (c == '\n') c = ' ';
  return s;
}
}  // namespace

std::string options_markdown() {
  std::ostringstream md;
  md << "# Options of the identification methods\n\n"
     << "Generated from the option tables of the library (`frictionlab help --markdown`); do not edit by hand.\n"
     << "Each option is a flag of `frictionlab identify METHOD` (validate: `frictionlab validate`) and a keyword\n"
     << "of the Python function. Units: linear axis, then rotary axis.\n";
  for (const auto& m : identification_methods()) {
    md << "\n## " << m.name << "\n\n" << m.summary << ".\n\n";
    if (m.options.empty()) {
      md << "No options of its own.\n";
      continue;
    }
    md << "| flag | Python | type | unit | default | valid values | description |\n"
       << "|---|---|---|---|---|---|---|\n";
    for (const auto& o : m.options) {
      std::string def = o.required ? "required" : "computed";
      if (!o.required && o.default_value) def = std::string("`").append(option_text(*o.default_value)).append("`");
      md << "| `--" << o.name << "` | `" << o.keyword() << "` | " << to_string(o.type) << (o.repeatable ? ", repeatable" : "")
         << " | " << cell(o.unit_text()) << " | " << cell(def) << " | " << cell(o.expected()) << " | " << cell(o.help);
      const std::string applies = applies_text(o, m.options, AppliesStyle::markdown);
      if (!applies.empty()) md << " (" << cell(applies) << ")";
      if (!o.deprecated_keywords.empty()) {
        md << " (Python, deprecated:";
        for (const auto& k : o.deprecated_keywords) md << " `" << k << "`";
        md << ")";
      }
      md << " |\n";
    }
  }
  return md.str();
}

}  // namespace frictionlab
