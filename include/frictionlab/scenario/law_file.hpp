#pragma once
// Friction laws in files: the YAML form of scenario files and the JSON form of model files.
//
// YAML (scenario `friction:` block, or a file of its own):
//   law: stribeck            # one of FrictionLaw::names()
//   Fc: 1.0                  # parameters by name, SI units
//   Fs: 1.5
//   vs: 0.001
//   Fv: 0.4
// Lists for table (velocity, force) and gms (k, alpha); `shape: tanh|atan` for smooth.
//
// JSON: the same object, or the result of `frictionlab identify --json` (MODEL.json): its "law"
// object when present, else its "model" (the law name) with "parameters" mapping names to
// {"value": v, "std": s, "unit": u}.

#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "frictionlab/models/friction_law.hpp"

namespace YAML {
class Node;
}

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Reads a law from a YAML mapping. `where` names the place for messages (file and key path,
/// e.g. "scenario.yaml: friction"). Throws std::invalid_argument naming `where` and the key
/// when `law` is missing, a value is not a number or list of numbers, or the law rejects it.
FrictionLaw law_from_yaml(const YAML::Node& node, const std::string& where);

/// Reads a law from a JSON object (plain form or MODEL.json). Throws std::invalid_argument
/// naming `where` and the key on a missing law name or a non-numeric value.
FrictionLaw law_from_json(const nlohmann::json& j, const std::string& where);

/// Reads a law from a `.yaml`/`.yml` or `.json` file (a .json file through read_model_json).
/// Throws std::invalid_argument naming the file when it cannot be read or parsed, and, for YAML,
/// on a key given twice in one mapping (naming the key and its line).
FrictionLaw load_law(const std::string& path);

/// Reads a JSON law file or the MODEL.json of `frictionlab identify --json`, strictly
/// (docs/contract.md, "Reading a MODEL.json"): the whole file must be one JSON object (text after
/// it is refused, with its line and column); a key given twice in one object is refused naming
/// it; a MODEL.json (a file with a schema, status, method, parameters or a law object) must name
/// schema 1 or 2 (none reads as 1) and carry a "status"; a model whose status is not "ok" is
/// refused with its message (an identification that gave no answer has no law to use); its "axis"
/// must be "linear" or "rotary", its parameters' value, std, std_ols and its fit's figures numbers
/// (or null), each refusal naming the key. A schema-1 file is returned in schema 2's layout
/// ("schema": 2; a top-level "selection" moved to diagnostics.selection). The one reader of model
/// files (identify lugre --static, validate, simulate's model:, export, plan, Python's load_law).
/// \throws std::invalid_argument (InputError) naming the file and, for a field, the key.
nlohmann::json read_model_json(const std::string& path);

/// The identified inertia parameters.M of a MODEL.json (kg or kg m^2), as `identify --json` writes
/// it ({"value": v, ...}) or as a plain number; nullopt when the model has none.
/// \throws std::invalid_argument "PATH: parameters.M: expected the identified inertia, ..." when it
///         is not a number.
std::optional<double> model_inertia(const nlohmann::json& model, const std::string& path);

/// The plain JSON form {"law": name, parameters..., lists...} of a law.
nlohmann::json law_to_json(const FrictionLaw& law);

}  // namespace frictionlab
