#pragma once
// A model file as simulation, compensation and export read it: a MODEL.json (the result of
// `frictionlab identify --json`) or a law file, with the identified inertia when the file has one.

#include <optional>
#include <string>

#include "frictionlab/models/friction_law.hpp"
#include "frictionlab/models/parameter.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// A model file's law and, when the file has one (the MODEL.json of `identify idim` or `decay`),
/// the identified inertia M (kg or kg m^2): the disturbance observer's default.
struct ModelFile {
  FrictionLaw law;
  std::optional<double> inertia;
  /// The axis MODEL.json names ("axis": "linear" or "rotary"); nullopt when it names none (a law file).
  std::optional<Axis> axis = std::nullopt;
  /// The identified constant force offset parameters.offset (N or N m); nullopt when it has none.
  std::optional<double> offset = std::nullopt;
};

/// Reads MODEL.json (read_model_json, law_from_json: the strict model reader) or a law file
/// (.yaml/.yml through load_law; scenario/law_file.hpp). \throws std::invalid_argument naming the
/// file (and key) when it cannot be read or parsed, or its law, inertia, axis ("linear" or
/// "rotary") or offset (a number) is not valid.
ModelFile read_model_file(const std::string& path);

}  // namespace frictionlab
