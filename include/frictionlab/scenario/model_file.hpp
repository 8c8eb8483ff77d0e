#pragma once
// A model file as simulation, compensation and export read it: a MODEL.json (the result of
// `frictionlab identify --json`) or a law file, with the identified inertia when the file has one.

#include <optional>
#include <string>

#include "frictionlab/models/friction_law.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// A model file's law and, when the file has one (the MODEL.json of `identify idim` or `decay`),
/// the identified inertia M (kg or kg m^2): the disturbance observer's default.
struct ModelFile {
  FrictionLaw law;
  std::optional<double> inertia;
};

/// Reads MODEL.json (read_model_json, law_from_json: the strict model reader) or a law file
/// (.yaml/.yml through load_law; scenario/law_file.hpp). \throws std::invalid_argument naming the
/// file when it cannot be read or parsed, or its law or inertia is not valid.
ModelFile read_model_file(const std::string& path);

}  // namespace frictionlab
