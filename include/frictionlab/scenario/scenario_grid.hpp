#pragma once
// A scenario file with some of its numbers replaced: the scenarios of a map's grid points
// (`frictionlab analyze map SCENARIO.yaml --vary plant.k=1:4:4`). Keys are dotted paths into the
// file's YAML (plant.k, controller.Kp, friction.Fs, plant.axes.x.mass, input.value; a number
// selects a list entry). A key names a number the file gives, or a field the file leaves at its
// default (plant.c of a spring-base), which the scenario reader then checks like any other.

#include <memory>
#include <string>
#include <vector>

#include "frictionlab/scenario/scenario.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The scenario file, read once, and the keys varied in it.
class ScenarioGrid {
 public:
  /// Reads the file and checks each key: every part but the last must name a mapping (or list)
  /// in the file, the last a number or an absent field that the reader accepts (tried with the
  /// file's own value, or 1 when absent).
  /// \throws std::invalid_argument "--vary KEY: ..." naming the key, the part that is missing and
  ///         what the file has there (the keys of that mapping), a key that names a mapping or a
  ///         text, or a field the reader refuses (its message); and what load_scenario throws.
  ScenarioGrid(const std::string& path, std::vector<std::string> keys, const ScenarioOptions& options = {});
  ~ScenarioGrid();
  ScenarioGrid(ScenarioGrid&&) noexcept;
  ScenarioGrid& operator=(ScenarioGrid&&) noexcept;

  /// The scenario with keys[i] set to values[i] (one value per key).
  /// \throws std::invalid_argument "FILE with KEY=VALUE, ...: MESSAGE" when the reader refuses the
  ///         values (a stiffness <= 0, Fs < Fc, ...).
  Scenario at(const std::vector<double>& values) const;

  const std::string& path() const;
  const std::vector<std::string>& keys() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace frictionlab
