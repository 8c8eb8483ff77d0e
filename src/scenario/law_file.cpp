#include "frictionlab/scenario/law_file.hpp"
#include "io/input_file.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "frictionlab/error.hpp"
#include "yaml_keys.hpp"

namespace frictionlab {
namespace {
// The MODEL.json schemas this frictionlab reads (docs/contract.md); it writes the last.
constexpr long long kModelSchemasRead[] = {1, 2};

// FrictionLaw::from_spec with its messages prefixed by `where`; an effect's parameter error
// (law.parameter, keyed by the bare parameter name) gets the file and the section's dotted key.
FrictionLaw build_law(const LawSpec& spec, const std::string& where) {
  return detail::with_context(where, [&] {
    try {
      return FrictionLaw::from_spec(spec);
    } catch (const InputError& e) {
      if (std::string(e.code()) != errc::law_parameter) throw;
      ErrorFields f = e.fields();
      const ErrorFields at = detail::key_fields(where, f.key);
      f.file = at.file;
      f.key = at.key;
      throw InputError(e.code(), e.what(), f);
    }
  });
}
}  // namespace

FrictionLaw law_from_yaml(const YAML::Node& node, const std::string& where) {
  if (!node || !node.IsMap())
    throw InputError(errc::scenario_value, where + ": expected a mapping with 'law' and its parameters", detail::key_fields(where));
  detail::check_unique_keys(node, where);
  LawSpec spec;
  for (const auto& kv : node) {
    // A list, mapping or empty key or name would make yaml-cpp throw its own bad conversion.
    if (!kv.first.IsScalar())
      throw InputError(errc::scenario_key_unknown,
                       where + ": line " + std::to_string(kv.first.Mark().line + 1) +
                           ": expected a parameter name as key, got a list, mapping or empty key",
                       detail::key_fields(where));
    const std::string key = kv.first.as<std::string>();
    const YAML::Node& value = kv.second;
    const std::string here = where + "." + key;
    if ((key == "law" || key == "shape") && !value.IsScalar()) {
      throw InputError(errc::scenario_value, here + ": expected a name", detail::key_fields(where, key));
    } else if (key == "law") {
      spec.name = value.as<std::string>();
    } else if (key == "shape") {
      spec.strings[key] = value.Scalar();
    } else if (value.IsSequence()) {
      std::vector<double> list;
      for (std::size_t i = 0; i < value.size(); ++i) {
        try {
          if (!value[i].IsScalar()) throw YAML::Exception(YAML::Mark::null_mark(), "");
          list.push_back(value[i].as<double>());
        } catch (const YAML::Exception&) {
          const std::string got = value[i].IsScalar() ? value[i].Scalar() : std::string("a list or mapping");
          ErrorFields f = detail::key_fields(where, key + "[" + std::to_string(i) + "]");
          f.value = got;
          throw InputError(errc::scenario_value, here + "[" + std::to_string(i) + "]: expected a number, got '" + got + "'", f);
        }
      }
      spec.arrays[key] = std::move(list);
    } else {
      try {
        if (!value.IsScalar()) throw YAML::Exception(YAML::Mark::null_mark(), "");
        spec.scalars[key] = value.as<double>();
      } catch (const YAML::Exception&) {
        const std::string got = value.IsScalar() ? value.Scalar() : std::string(value.IsNull() ? "nothing" : "a mapping");
        ErrorFields f = detail::key_fields(where, key);
        f.value = got;
        throw InputError(errc::scenario_value, here + ": expected a number, got '" + got + "'", f);
      }
    }
  }
  if (spec.name.empty())
    throw InputError(errc::scenario_key_missing, where + ": missing 'law' (one of the friction law names, e.g. stribeck)",
                     detail::key_fields(where, "law"));
  return build_law(spec, where);
}

FrictionLaw law_from_json(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) {
    throw InputError(errc::scenario_value, where + ": expected a JSON object describing a friction law", detail::key_fields(where));
  }
  LawSpec spec;
  if (j.contains("law") && j["law"].is_object()) return law_from_json(j["law"], where + ": law");  // MODEL.json
  const nlohmann::json* params = &j;
  if (j.contains("model") && j.contains("parameters")) {  // MODEL.json written by identify
    if (!j["model"].is_string()) throw InputError(errc::scenario_value, where + ": 'model' must be a law name", detail::key_fields(where, "model"));
    spec.name = j["model"].get<std::string>();
    params = &j["parameters"];
  } else if (j.contains("law") && j["law"].is_string()) {
    spec.name = j["law"].get<std::string>();
  } else {
    throw InputError(errc::scenario_key_missing, where + ": missing 'law' (or 'model' with 'parameters')", detail::key_fields(where, "law"));
  }
  for (const auto& [key, value] : params->items()) {
    if (key == "law" || key == "M" || key == "offset") continue;  // M and offset belong to the plant, not the law
    const std::string here = where + "." + key;
    if (key == "shape" && value.is_string()) {
      spec.strings[key] = value.get<std::string>();
    } else if (value.is_number()) {
      spec.scalars[key] = value.get<double>();
    } else if (value.is_object() && value.contains("value") && value["value"].is_number()) {
      spec.scalars[key] = value["value"].get<double>();
    } else if (value.is_array()) {
      std::vector<double> list;
      for (std::size_t i = 0; i < value.size(); ++i) {
        if (!value[i].is_number())
          throw InputError(errc::scenario_value, here + "[" + std::to_string(i) + "]: expected a number, got " + value[i].dump(),
                           detail::key_fields(where, key + "[" + std::to_string(i) + "]"));
        list.push_back(value[i].get<double>());
      }
      spec.arrays[key] = std::move(list);
    } else {
      throw InputError(errc::scenario_value, here + ": expected a number (or {\"value\": number}), got " + value.dump(),
                       detail::key_fields(where, key));
    }
  }
  return build_law(spec, where);
}

namespace {

// The JSON of `in`, with a key repeated within one object refused naming the file and the key
// (dotted from the top; "[]" for an array's element), as the scenario reader refuses it: the
// JSON standard leaves the meaning of a repeated key open, so no reader may guess.
nlohmann::json parse_unique_keys(std::istream& in, const std::string& path) {
  struct Frame {
    bool object = false;
    std::string where;  // dotted key of this object or array ("" at the top)
    std::set<std::string> keys;
    std::string key;  // the object's last key read
  };
  std::vector<Frame> stack;
  const auto child = [&]() -> std::string {
    if (stack.empty()) return "";
    const Frame& f = stack.back();
    const std::string step = f.object ? f.key : "[]";
    return f.where.empty() ? step : f.where + (f.object ? "." : "") + step;
  };
  using Event = nlohmann::json::parse_event_t;
  const nlohmann::json::parser_callback_t check = [&](int, Event event, nlohmann::json& parsed) {
    switch (event) {
      case Event::object_start: stack.push_back({true, child(), {}, {}}); break;
      case Event::array_start: stack.push_back({false, child(), {}, {}}); break;
      case Event::object_end:
      case Event::array_end:
        if (!stack.empty()) stack.pop_back();
        break;
      case Event::key: {
        Frame& f = stack.back();
        f.key = parsed.get<std::string>();
        if (!f.keys.insert(f.key).second) {
          const std::string key = f.where.empty() ? f.key : f.where + "." + f.key;
          throw InputError(errc::scenario_value,
                           path + ": " + key + ": the key is given twice; expected each key once in an object",
                           {.file = path, .key = key});
        }
        break;
      }
      case Event::value: break;
    }
    return true;
  };
  return nlohmann::json::parse(in, check);  // strict: the object must end the file
}

// A number where one belongs (null too when `nullable`), else refused naming the key.
void require_number(const nlohmann::json& v, const std::string& path, const std::string& key, bool nullable,
                    const std::string& what) {
  if (v.is_number() || (nullable && v.is_null())) return;
  throw InputError(errc::scenario_value, path + ": " + key + ": expected " + what + ", got " + v.dump(),
                   {.file = path, .key = key, .value = v.dump()});
}

// The fields of a MODEL.json whose type is fixed: status, axis, parameters, fit.
void check_model_fields(const nlohmann::json& j, const std::string& path) {
  if (!j.contains("status"))
    throw InputError(errc::scenario_key_missing,
                     path + ": missing 'status'; expected \"ok\" (a MODEL.json of frictionlab identify --json carries it)",
                     {.file = path, .key = "status"});
  if (j.contains("axis")) {
    const auto& a = j["axis"];
    if (!(a.is_string() && (a.get<std::string>() == "linear" || a.get<std::string>() == "rotary")))
      throw InputError(errc::scenario_value, path + ": axis: expected \"linear\" or \"rotary\", got " + a.dump(),
                       {.file = path, .key = "axis", .value = a.dump()});
  }
  if (j.contains("parameters")) {
    const auto& ps = j["parameters"];
    if (!ps.is_object())
      throw InputError(errc::scenario_value, path + ": parameters: expected an object of parameters, got " + ps.dump(),
                       {.file = path, .key = "parameters", .value = ps.dump()});
    for (const auto& [name, p] : ps.items()) {
      const std::string key = "parameters." + name;
      if (!p.is_object()) {
        require_number(p, path, key, false, "a number (the parameter's value) or {\"value\": number, \"std\": ...}");
        continue;
      }
      if (p.contains("value")) require_number(p["value"], path, key + ".value", true, "a number (the parameter's value)");
      for (const char* f : {"std", "std_ols"})
        if (p.contains(f)) require_number(p[f], path, key + "." + f, true, "a number or null (a standard deviation)");
      if (p.contains("unit") && !p["unit"].is_string())
        throw InputError(errc::scenario_value, path + ": " + key + ".unit: expected a unit name, got " + p["unit"].dump(),
                         {.file = path, .key = key + ".unit", .value = p["unit"].dump()});
    }
  }
  if (j.contains("fit")) {
    const auto& fit = j["fit"];
    if (!fit.is_object())
      throw InputError(errc::scenario_value, path + ": fit: expected an object, got " + fit.dump(),
                       {.file = path, .key = "fit", .value = fit.dump()});
    for (const char* f : {"relative_error_percent", "rmse", "samples"})
      if (fit.contains(f)) require_number(fit[f], path, std::string("fit.") + f, true, "a number");
  }
}

}  // namespace

nlohmann::json read_model_json(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(errc::scenario_format,
                     path + " is a directory; expected a JSON model file (MODEL.json of frictionlab identify --json)",
                     {.file = path});
  if (!std::filesystem::exists(path, ec))
    throw InputError(errc::scenario_format, path + ": cannot open the model file", {.file = path});
  // Read within the budget as every input file (io/input_file.hpp): a device (/dev/zero named
  // .json) is refused before a byte is read, a FIFO is read as a stream that ends or is refused.
  std::istringstream in(read_input_file(path, "model file", errc::scenario_format));
  nlohmann::json j;
  try {
    j = parse_unique_keys(in, path);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(errc::scenario_format, path + ": not valid JSON (" + e.what() + ")", {.file = path});
  }
  if (!j.is_object()) {
    throw InputError(errc::scenario_format, path + ": expected a JSON object (a friction law or MODEL.json)", {.file = path});
  }
  // A schema this version does not know (a newer frictionlab's MODEL.json) is refused rather than
  // read by guess: its fields may mean something else.
  const auto& known = kModelSchemasRead;
  if (j.contains("schema") &&
      !(j["schema"].is_number_integer() && std::find(std::begin(known), std::end(known), j["schema"].get<long long>()) != std::end(known))) {
    throw InputError(errc::scenario_value,
                     path + ": schema: " + j["schema"].dump() +
                         " is not a MODEL.json schema this frictionlab reads (1 or 2); a newer frictionlab wrote it, or "
                         "the file is not a MODEL.json",
                     {.file = path, .key = "schema", .value = j["schema"].dump()});
  }
  // A MODEL.json (a schema, a status, parameters, a method or a law object) is read strictly; a
  // plain law file ({"law": NAME, ...}) is the law's alone (law_from_json checks it).
  const bool model = j.contains("schema") || j.contains("status") || j.contains("parameters") || j.contains("method") ||
                     (j.contains("law") && j["law"].is_object());
  if (model) check_model_fields(j, path);
  if (j.contains("status")) {
    const auto& st = j["status"];
    if (!st.is_string()) {
      throw InputError(errc::scenario_value, path + ": status: expected \"ok\" or \"error\", got " + st.dump(),
                       {.file = path, .key = "status", .value = st.dump()});
    }
    if (st.get<std::string>() != "ok") {
      std::string why;
      if (j.contains("message") && j["message"].is_string()) why = j["message"].get<std::string>();
      throw InputError(errc::scenario_value,
                       path + ": the identification failed (status " + st.dump() + (why.empty() ? "" : ": " + why) +
                           "); it holds no model to use",
                       {.file = path, .key = "status", .value = st.get<std::string>()});
    }
  }
  // Schema 1 (the previous release, and a file without a schema) read in schema 2's layout: auto's
  // candidates move from the top-level "selection" to diagnostics.selection.
  if (model && (!j.contains("schema") || j["schema"] == 1)) {
    if (j.contains("selection")) {
      if (!j.contains("diagnostics") || !j["diagnostics"].is_object()) j["diagnostics"] = nlohmann::json::object();
      j["diagnostics"]["selection"] = j["selection"];
      j.erase("selection");
    }
    j["schema"] = 2;
  }
  return j;
}

FrictionLaw load_law(const std::string& path) {
  const bool is_json = path.size() >= 5 && path.substr(path.size() - 5) == ".json";
  if (is_json) return law_from_json(read_model_json(path), path);
  const std::string text = read_input_file(path, "friction law file", errc::scenario_format);
  YAML::Node node;
  try {
    node = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(errc::scenario_format, path + ": not valid YAML (" + e.what() + ")",
                     {.file = path, .row = static_cast<std::size_t>(e.mark.line + 1)});
  }
  detail::check_quotes_closed(node, text, path);
  detail::check_unique_keys(node, path);
  if (node.IsMap() && node["friction"]) return law_from_yaml(node["friction"], path + ": friction");
  return law_from_yaml(node, path);
}

nlohmann::json law_to_json(const FrictionLaw& law) {
  const LawSpec spec = law.to_spec();
  nlohmann::json j;
  j["law"] = spec.name;
  for (const auto& [k, v] : spec.scalars) j[k] = v;
  for (const auto& [k, v] : spec.arrays) j[k] = v;
  for (const auto& [k, v] : spec.strings) j[k] = v;
  return j;
}

std::optional<double> model_inertia(const nlohmann::json& j, const std::string& path) {
  if (!j.contains("parameters") || !j["parameters"].is_object() || !j["parameters"].contains("M")) return std::nullopt;
  const auto& p = j["parameters"]["M"];
  const auto& v = p.is_object() ? p.value("value", nlohmann::json()) : p;
  if (!v.is_number())
    throw InputError(errc::scenario_value,
                     path + ": parameters.M: expected the identified inertia, a number (kg or kg m^2), got " + v.dump(),
                     {.file = path, .key = "parameters.M", .value = v.dump()});
  return v.get<double>();
}

}  // namespace frictionlab
