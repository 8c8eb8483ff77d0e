// Model files: see include/frictionlab/scenario/model_file.hpp.
#include "frictionlab/scenario/model_file.hpp"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "frictionlab/scenario/law_file.hpp"

namespace frictionlab {

ModelFile read_model_file(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".yaml" || ext == ".yml") return {load_law(path), std::nullopt};
  const nlohmann::json j = read_model_json(path);
  ModelFile m{law_from_json(j, path), std::nullopt};
  m.inertia = model_inertia(j, path);
  return m;
}

}  // namespace frictionlab
