#pragma once
// N independent rigid axes, each an inertia pushed by its own input force against its own
// friction: M_k a_k = u_k(t) + offset_k - F_k. The smallest plant with several contacts (a gantry's
// axes before any coupling); each axis's motion is that of a RigidAxis with the same law and input.

#include <optional>
#include <string>
#include <vector>

#include "frictionlab/models/friction_law.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/plants/plant.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// One axis of a MultiAxis.
struct NamedAxis {
  std::string name;  ///< column prefix ("x", "y", ...), non-empty, distinct
  AxisParams params;  ///< inertia M (kg or kg m^2, > 0) and constant force offset (N or N m)
  /// Its friction law; empty (default) = the law given to simulate().
  std::optional<FrictionLaw> law;
};

/// N rigid axes. States: x[2k] = position of axis k (m or rad), x[2k+1] = its velocity. Input k is
/// the applied force on axis k (N or N m). Signals of axis k: reference = drive = u_k.
class MultiAxis : public Plant {
 public:
  /// \throws std::invalid_argument when there is no axis, a name is empty or repeated, or an
  ///         axis's M or offset is out of range (the message names the axis).
  explicit MultiAxis(std::vector<NamedAxis> axes);
  std::string type() const override { return "multi-axis"; }
  int num_states() const override { return 2 * static_cast<int>(axes_.size()); }
  int num_inputs() const override { return static_cast<int>(axes_.size()); }
  int num_contacts() const override { return static_cast<int>(axes_.size()); }
  Contact contact(int i) const override;
  double inertia(int contact = 0) const override;
  void applied(double t, std::span<const double> x, Inputs u, std::span<double> force) const override;
  void derivatives(double t, std::span<const double> x, Inputs u, std::span<const double> friction,
                   std::span<double> dx) const override;
  bool jacobian(double t, std::span<const double> x, Inputs u, std::span<const double> friction,
                std::span<double> dfdx, std::span<double> dfdF) const override;
  void signals(double t, std::span<const double> x, Inputs u, std::span<PlantSignals> out) const override;
  const std::vector<NamedAxis>& axes() const { return axes_; }

 private:
  std::vector<NamedAxis> axes_;
};

}  // namespace frictionlab
