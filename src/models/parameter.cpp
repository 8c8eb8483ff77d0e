#include "frictionlab/models/parameter.hpp"

namespace frictionlab {

std::string_view unit(Quantity q, Axis axis) {
  const bool rot = axis == Axis::rotary;
  switch (q) {
    case Quantity::force: return rot ? "N m" : "N";
    case Quantity::viscous: return rot ? "N m s/rad" : "N s/m";
    case Quantity::velocity: return rot ? "rad/s" : "m/s";
    case Quantity::displacement: return rot ? "rad" : "m";
    case Quantity::stiffness: return rot ? "N m/rad" : "N/m";
    case Quantity::inertia: return rot ? "kg m^2" : "kg";
    case Quantity::acceleration: return rot ? "rad/s^2" : "m/s^2";
    case Quantity::time: return "s";
    case Quantity::rate: return "1/s";
    case Quantity::force_rate: return rot ? "N m/s" : "N/s";
    case Quantity::dimensionless: return "";
    case Quantity::energy: return "J";
    case Quantity::viscous_per_kelvin: return rot ? "N m s/rad/K" : "N s/m/K";
  }
  return "";
}

Axis parse_axis(std::string_view text) {
  if (text == "linear") return Axis::linear;
  if (text == "rotary") return Axis::rotary;
  throw std::invalid_argument("axis: '" + std::string(text) + "' is not valid; expected linear or rotary");
}

}  // namespace frictionlab
