// The PID controller: see include/frictionlab/control/pid.hpp.
#include "frictionlab/control/pid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "frictionlab/models/parameter.hpp"

namespace frictionlab {

void PidParams::validate(std::string_view who, const PidUnits& units) const {
  auto gain = [&](double value, const char* name, const char* unit) {
    detail::require(std::isfinite(value) && value >= 0, who, name, value, std::string(">= 0 (") + unit + ")");
  };
  gain(Kp, "Kp", units.Kp);
  gain(Ki, "Ki", units.Ki);
  gain(Kd, "Kd", units.Kd);
  if (loop == ControlLoop::velocity)
    detail::require(Kd == 0.0, who, "Kd", Kd, "0 in a velocity loop (it would need the acceleration)");
  detail::require(std::isfinite(limit) && limit >= 0, who, "limit", limit,
                  std::string(">= 0 (") + units.limit + "; 0 = no saturation)");
  gain(Kvff, "Kvff", units.Kvff);
  gain(Kaff, "Kaff", units.Kaff);
  detail::require(std::isfinite(compensation_gain) && compensation_gain > 0, who, "compensation_gain",
                  compensation_gain, "> 0 (plant input unit per N or N m of compensation)");
  validate_timing(who);
}

void PidParams::validate_timing(std::string_view who) const {
  detail::require(std::isfinite(Ts) && Ts >= 0, who, "Ts", Ts, ">= 0 (s; 0 = continuous controller)");
  detail::require(delay == 0 || delay == 1, who, "delay", delay, "0 or 1 (samples)");
  if (delay == 1 && Ts == 0)
    throw std::invalid_argument(std::string(who) + ": delay = 1 needs a sampled controller (Ts > 0 s)");
}

Pid::Pid(PidParams p, std::string_view who, const PidUnits& units) : p_(p) { p_.validate(who, units); }

double Pid::error(const PidInput& in) const {
  return p_.loop == ControlLoop::position ? in.reference - in.position : in.reference - in.velocity;
}

double Pid::unsaturated(const PidInput& in, double integral, double compensation) const {
  double out;
  if (p_.loop == ControlLoop::position) {
    out = p_.Kp * (in.reference - in.position) + p_.Ki * integral - p_.Kd * in.velocity +
          p_.Kvff * in.reference_rate + p_.Kaff * in.reference_accel;
  } else {
    out = p_.Kp * (in.reference - in.velocity) + p_.Ki * integral + p_.Kvff * in.reference +
          p_.Kaff * in.reference_rate;
  }
  return out + p_.compensation_gain * compensation;  // before the saturation: the limit holds with it
}

double Pid::saturate(double out) const { return p_.limit > 0 ? std::clamp(out, -p_.limit, p_.limit) : out; }

double Pid::saturation_slope(double out) const { return p_.limit > 0 && std::abs(out) > p_.limit ? 0.0 : 1.0; }

double Pid::sample(const PidInput& in, std::span<double> s, double compensation) const {
  constexpr std::size_t kIntegral = 0, kApplied = 1, kComputed = 2;
  s[kIntegral] += p_.Ts * error(in);
  const double v = output(in, s[kIntegral], compensation);
  // delay 1: the output computed at the previous sample goes to the drive now.
  s[kApplied] = p_.delay == 1 ? s[kComputed] : v;
  s[kComputed] = v;
  return v;
}

}  // namespace frictionlab
