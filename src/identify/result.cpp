#include "frictionlab/io/json_text.hpp"
#include "frictionlab/identify/result.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "frictionlab/error.hpp"
#include "frictionlab/version.hpp"
#include <stdexcept>
#include <string_view>

namespace frictionlab {
namespace {

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

const Parameter* Result::find(const std::string& name) const {
  for (const auto& p : parameters)
    if (p.name == name) return &p;
  return nullptr;
}

double Result::value(const std::string& name) const {
  if (const auto* p = find(name)) return p->value;
  std::string names;
  for (const auto& p : parameters) names += (names.empty() ? "" : ", ") + p.name;
  throw std::invalid_argument("result of " + method + ": no parameter '" + name +
                              "'; parameters: " + (names.empty() ? "(none)" : names));
}

std::string to_json(const Result& r, int indent) {
  nlohmann::json j;
  j["schema"] = 2;  // MODEL.json schema 2 (docs/contract.md); read_model_json reads 1 and 2
  j["frictionlab"] = {{"version", kVersion}};  // the program that made the result (reproducibility)
  j["status"] = r.ok() ? "ok" : "error";
  j["message"] = r.message;
  // Every error result carries a stable code: its own, or data.no_answer (no motion, too few
  // segments, rank-deficient regressors: what the data could not give).
  if (!r.ok()) j["error"] = {{"code", r.code.empty() ? errc::data_no_answer : r.code}, {"message", r.message}};
  j["method"] = r.method;
  j["model"] = r.model;
  j["data"] = {{"file", r.data_file}, {"sha256", r.data_sha256}};
  j["axis"] = r.axis == Axis::rotary ? "rotary" : "linear";
  nlohmann::json params = nlohmann::json::object();
  for (const auto& p : r.parameters) {
    params[p.name] = {{"value", number(p.value)}, {"std", number(p.std)}, {"unit", p.unit}};
    if (p.std_ols) params[p.name]["std_ols"] = number(*p.std_ols);
  }
  j["parameters"] = params;
  j["fit"] = {{"relative_error_percent", number(r.fit.relative_error_percent)},
              {"rmse", number(r.fit.rmse)},
              {"samples", r.fit.samples}};
  if (!r.fit.quantity.empty()) j["fit"]["quantity"] = r.fit.quantity;
  if (!r.fit.unit.empty()) j["fit"]["unit"] = r.fit.unit;
  if (r.validation) {
    const auto& v = *r.validation;
    j["validation"] = {{"file", v.file},
                       {"sha256", v.sha256},
                       {"relative_error_percent", number(v.relative_error_percent)},
                       {"rmse", number(v.rmse)},
                       {"samples", v.samples}};
    if (!v.signal_errors_percent.empty()) {
      nlohmann::json e = nlohmann::json::object();
      for (const auto& [name, value] : v.signal_errors_percent) e[name] = number(value);
      j["validation"]["relative_error_percent"] = e;
    }
    for (const auto& [key, text] : v.json_sections) {
      try {
        j["validation"][key] = nlohmann::json::parse(text);
      } catch (const nlohmann::json::parse_error& e) {
        throw std::invalid_argument("to_json: validation." + key + " is not valid JSON: " + e.what());
      }
    }
  }
  nlohmann::json d = nlohmann::json::object();
  for (const auto& [key, value] : r.diagnostics.numbers) d[key] = number(value);
  for (const auto& [key, group] : r.diagnostics.groups) {
    nlohmann::json g = nlohmann::json::object();
    for (const auto& [name, value] : group) g[name] = number(value);
    d[key] = g;
  }
  for (const auto& [key, list] : r.diagnostics.lists) {
    nlohmann::json arr = nlohmann::json::array();
    for (const auto& record : list) {
      nlohmann::json o = nlohmann::json::object();
      for (const auto& [name, value] : record) o[name] = number(value);
      arr.push_back(o);
    }
    d[key] = arr;
  }
  for (const auto& [key, word] : r.diagnostics.texts) d[key] = word;
  d["condition_number"] = number(r.diagnostics.condition_number);
  d["undetermined"] = r.diagnostics.undetermined;
  d["at_bound"] = r.diagnostics.at_bound;
  if (!r.diagnostics.correlation.names.empty()) {
    nlohmann::json m = nlohmann::json::array();
    for (const auto& row : r.diagnostics.correlation.matrix) {
      nlohmann::json jr = nlohmann::json::array();
      for (double x : row) jr.push_back(number(x));
      m.push_back(jr);
    }
    d["correlation"] = {{"names", r.diagnostics.correlation.names}, {"matrix", m}};
  }
  d["warnings"] = r.diagnostics.warnings;
  j["diagnostics"] = d;
  if (r.law) {
    nlohmann::json law = {{"law", r.law->name}};
    for (const auto& [k, v] : r.law->scalars) law[k] = number(v);
    for (const auto& [k, v] : r.law->arrays) law[k] = v;
    for (const auto& [k, v] : r.law->strings) law[k] = v;
    j["law"] = law;
  }
  // A section keyed "diagnostics.NAME" goes under diagnostics (schema 2: auto's "selection").
  for (const auto& [key, text] : r.json_sections) {
    try {
      constexpr std::string_view kUnder = "diagnostics.";
      if (key.rfind(kUnder, 0) == 0) j["diagnostics"][key.substr(kUnder.size())] = nlohmann::json::parse(text);
      else j[key] = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
      throw std::invalid_argument("result of " + r.method + ": section '" + key + "' is not valid JSON: " + e.what());
    }
  }
  return json_text(j, indent);
}

}  // namespace frictionlab
