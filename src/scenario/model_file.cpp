// Model files: see include/frictionlab/scenario/model_file.hpp.
#include "frictionlab/scenario/model_file.hpp"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "frictionlab/error.hpp"
#include "frictionlab/scenario/law_file.hpp"

namespace frictionlab {
namespace {

std::optional<Axis> model_axis(const nlohmann::json& j, const std::string& path) {
  if (!j.contains("axis")) return std::nullopt;
  const auto& a = j["axis"];
  if (a.is_string() && (a.get<std::string>() == "linear" || a.get<std::string>() == "rotary"))
    return parse_axis(a.get<std::string>());
  throw InputError(errc::scenario_value, path + ": axis: expected \"linear\" or \"rotary\", got " + a.dump(),
                   {.file = path, .key = "axis", .value = a.dump()});
}

std::optional<double> model_offset(const nlohmann::json& j, const std::string& path) {
  if (!j.contains("parameters") || !j["parameters"].is_object() || !j["parameters"].contains("offset")) return std::nullopt;
  const auto& p = j["parameters"]["offset"];
  const auto& v = p.is_object() ? p.value("value", nlohmann::json()) : p;
  if (!v.is_number())
    throw InputError(errc::scenario_value,
                     path + ": parameters.offset: expected the identified offset, a number (N or N m), got " + v.dump(),
                     {.file = path, .key = "parameters.offset", .value = v.dump()});
  return v.get<double>();
}

}  // namespace

ModelFile read_model_file(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".yaml" || ext == ".yml") return {load_law(path), std::nullopt};
  const nlohmann::json j = read_model_json(path);
  ModelFile m{law_from_json(j, path), std::nullopt};
  m.inertia = model_inertia(j, path);
  m.axis = model_axis(j, path);
  m.offset = model_offset(j, path);
  return m;
}

}  // namespace frictionlab
