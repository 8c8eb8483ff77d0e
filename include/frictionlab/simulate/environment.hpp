#pragma once
// The conditions a friction contact works in during a run: the load it transmits and its
// temperature, for laws that carry load or temperature effects (models/law_effects.hpp).
//
// Temperature as a state: a first-order thermal model of the contact heated by the power its
// friction dissipates,
//   C dT/dt = P_friction - (T - T_ambient) / R,   tau = R C,
// with P_friction = F_law v, the velocity law's force times the velocity (the position ripple is
// conservative and does not heat). While a contact is stuck P_friction = 0 and T relaxes to
// T_ambient. The engine integrates T with the plant's states (a state of its own per contact).

#include <cmath>
#include <functional>
#include <optional>
#include <span>
#include <string>

#include "frictionlab/core/input.hpp"
#include "frictionlab/models/parameter.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Where a contact's load F_load (N or N m) comes from; none of the two = 0.
struct LoadSource {
  /// The load over time: any input shape (constant, steps, ramps, sine, a data column). Its
  /// corners are corners of the run (the engine stops there, as at the plant's input's).
  std::optional<InputSignal> signal;
  /// Or a function of time t (s) and the plant's state x (Plant::num_states() entries; a stuck
  /// contact at its frozen position), e.g. a joint's gravity load m g cos(q). It must be
  /// continuous in t and x (a jump would be stepped over) and safe to call from several threads.
  std::function<double(double t, std::span<const double> x)> of_state;

  bool given() const { return signal.has_value() || static_cast<bool>(of_state); }
  /// The load at (t, x) (N or N m).
  double at(double t, std::span<const double> x) const {
    if (signal) return signal->at(t).value;
    if (of_state) return of_state(t, x);
    return 0.0;
  }
};

/// The first-order thermal model of a contact (temperatures in degC or K, one scale throughout).
struct ThermalModel {
  double T_ambient = 20.0;          ///< ambient temperature (degC or K). Default 20.
  std::optional<double> T0;         ///< temperature at t = 0 (degC or K); none = T_ambient
  double tau = 600.0;               ///< thermal time constant R C (s), > 0. Default 600.
  double R = 1.0;                   ///< thermal resistance to ambient (K/W), > 0. Default 1.

  /// \throws std::invalid_argument naming the parameter (T_ambient, T0, tau, R) and its rule.
  void validate() const {
    detail::require(std::isfinite(T_ambient), "thermal", "T_ambient", T_ambient, "finite (degC or K)");
    if (T0) detail::require(std::isfinite(*T0), "thermal", "T0", *T0, "finite (degC or K)");
    detail::require(std::isfinite(tau) && tau > 0, "thermal", "tau", tau, "> 0 (s)");
    detail::require(std::isfinite(R) && R > 0, "thermal", "R", R, "> 0 (K/W)");
  }
  /// dT/dt (K/s) at temperature T with dissipated power P (W): (P R - (T - T_ambient)) / tau.
  double rate(double T, double P) const { return (P * R - (T - T_ambient)) / tau; }
};

/// One contact's conditions. The temperature comes in one of three forms, which exclude each
/// other: a fixed `temperature`, a `temperature_log` over time, or a `thermal` model.
struct ContactEnvironment {
  LoadSource load;
  std::optional<double> temperature;   ///< a fixed temperature (degC or K)
  /// or a temperature over time (degC or K): an input, e.g. a log's temperature column (a data
  /// input), replayed as the run goes; its corners are corners of the run
  std::optional<InputSignal> temperature_log;
  std::optional<ThermalModel> thermal; ///< or the temperature as a state of the run

  bool empty() const { return !load.given() && !temperature && !temperature_log && !thermal; }
  /// The temperature (degC or K) at time t of a fixed value or a log; none without either.
  std::optional<double> temperature_at(double t) const {
    if (temperature_log) return temperature_log->at(t).value;
    return temperature;
  }
  /// \throws std::invalid_argument when two temperature forms are given, a fixed temperature is
  ///         not finite, or the thermal model or an input breaks its rules (naming the parameter).
  void validate() const {
    if ((temperature ? 1 : 0) + (temperature_log ? 1 : 0) + (thermal ? 1 : 0) > 1)
      throw std::invalid_argument("environment: give one of a fixed temperature, a temperature over time or a thermal model");
    if (temperature) detail::require(std::isfinite(*temperature), "environment", "temperature", *temperature, "finite (degC or K)");
    if (temperature_log) temperature_log->validate("temperature");
    if (thermal) thermal->validate();
    if (load.signal) load.signal->validate("load");
  }
};

}  // namespace frictionlab
