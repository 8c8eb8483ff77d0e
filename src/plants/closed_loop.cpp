#include "frictionlab/plants/closed_loop.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "frictionlab/models/parameter.hpp"

namespace frictionlab {
namespace {

void require(bool ok, const char* name, double value, const char* rule) {
  detail::require(ok, "controller", name, value, rule);
}

}  // namespace

ClosedLoop::ClosedLoop(std::shared_ptr<const Plant> inner, ControllerParams c,
                       std::shared_ptr<const Compensator> compensator)
    : inner_(std::move(inner)), c_(c), compensator_(std::move(compensator)) {
  require_loop_plant(inner_.get(), "controller");
  require(std::isfinite(c.Kp) && c.Kp >= 0, "Kp", c.Kp, ">= 0");
  require(std::isfinite(c.Ki) && c.Ki >= 0, "Ki", c.Ki, ">= 0");
  require(std::isfinite(c.Kd) && c.Kd >= 0, "Kd", c.Kd, ">= 0");
  if (c.loop == ControlLoop::velocity)
    require(c.Kd == 0.0, "Kd", c.Kd, "0 in a velocity loop (it would need the acceleration)");
  require(std::isfinite(c.limit) && c.limit >= 0, "limit", c.limit, ">= 0 (0 = no saturation)");
  require(std::isfinite(c.Kvff) && c.Kvff >= 0, "Kvff", c.Kvff, ">= 0 (output unit per m/s or rad/s)");
  require(std::isfinite(c.Kaff) && c.Kaff >= 0, "Kaff", c.Kaff, ">= 0 (output unit per m/s^2 or rad/s^2)");
  require(std::isfinite(c.compensation_gain) && c.compensation_gain > 0, "compensation_gain", c.compensation_gain,
          "> 0 (plant input unit per N or N m of compensation)");
  n_inner_ = inner_->num_states();
  n_comp_ = compensator_ ? compensator_->num_states() : 0;
}

std::span<const double> ClosedLoop::own_states(std::span<const double> x) const {
  return x.subspan(static_cast<std::size_t>(n_inner_ + 1), static_cast<std::size_t>(n_comp_));
}

CompensatorInput ClosedLoop::measured(double t, std::span<const double> x, const InputValue& r) const {
  CompensatorInput in;
  in.t = t;
  in.position = x[0];
  in.velocity = x[1];
  if (c_.loop == ControlLoop::position) {
    in.reference = r.value;
    in.reference_rate = r.rate;
    in.reference_accel = r.accel;
  } else {  // r is a velocity: no position reference, so no position error
    in.reference = x[0];
    in.reference_rate = r.value;
    in.reference_accel = r.rate;
  }
  return in;
}

void ClosedLoop::initial_extras(std::span<double> x) const {
  const InputValue zero_reference{};
  initial_extras(x, Inputs(&zero_reference, 1));
}

void ClosedLoop::initial_extras(std::span<double> x, Inputs u) const {
  const std::size_t n = static_cast<std::size_t>(n_inner_);
  // The inner plant's input is the controller output, which needs these very states: it starts
  // from a zero input.
  const InputValue no_output{};
  inner_->initial_extras(x.first(n), Inputs(&no_output, 1));
  x[n] = 0.0;
  if (compensator_)
    compensator_->initial_states(measured(0.0, x, u[0]), x.subspan(n + 1, static_cast<std::size_t>(n_comp_)));
}

void ClosedLoop::fixed_step_update(double t, double dt, std::span<const double> before, Inputs u_before,
                                   std::span<double> x, Inputs u) const {
  if (!compensator_) return;
  const std::size_t n = static_cast<std::size_t>(n_inner_);
  const double t0 = t - dt;
  // The force the drive held over the step: the inner plant's drive at the output of the step's start.
  const InputValue held{control(t0, before, u_before[0])};
  CompensatorInput in = measured(t, x, u[0]);
  in.drive = signals_of(*inner_, t0, before.first(n), held).drive;
  const auto z = x.subspan(n + 1, static_cast<std::size_t>(n_comp_));
  const auto z0 = own_states(before);
  std::copy(z0.begin(), z0.end(), z.begin());  // from the step's start, not the engine's Euler value
  compensator_->update(in, z, dt);
}

double ClosedLoop::compensation(double t, std::span<const double> x, const InputValue& r) const {
  return compensator_ ? compensator_->output(measured(t, x, r), own_states(x)) : 0.0;
}

double ClosedLoop::control(std::span<const double> x, const InputValue& r, double compensation) const {
  const double integral = x[static_cast<std::size_t>(n_inner_)];
  double out;
  if (c_.loop == ControlLoop::position) {
    out = c_.Kp * (r.value - x[0]) + c_.Ki * integral - c_.Kd * x[1] + c_.Kvff * r.rate + c_.Kaff * r.accel;
  } else {
    out = c_.Kp * (r.value - x[1]) + c_.Ki * integral + c_.Kvff * r.value + c_.Kaff * r.rate;
  }
  out += c_.compensation_gain * compensation;  // before the saturation: the limit holds with it
  if (c_.limit > 0) out = std::clamp(out, -c_.limit, c_.limit);
  return out;
}

double ClosedLoop::control(double t, std::span<const double> x, const InputValue& r) const {
  return control(x, r, compensation(t, x, r));
}

double ClosedLoop::applied(double t, std::span<const double> x, const InputValue& r) const {
  const InputValue u{control(t, x, r)};
  return applied_of(*inner_, t, x.first(static_cast<std::size_t>(n_inner_)), u);
}

void ClosedLoop::derivatives(double t, std::span<const double> x, const InputValue& r, double friction,
                             std::span<double> dx) const {
  const std::size_t n = static_cast<std::size_t>(n_inner_);
  const auto inner_x = x.first(n);
  if (!compensator_) {
    const InputValue u{control(x, r, 0.0)};
    derivatives_of(*inner_, t, inner_x, u, friction, dx.first(n));
  } else {
    CompensatorInput in = measured(t, x, r);
    const auto z = own_states(x);
    const InputValue u{control(x, r, compensator_->output(in, z))};
    derivatives_of(*inner_, t, inner_x, u, friction, dx.first(n));
    in.drive = signals_of(*inner_, t, inner_x, u).drive;  // the force applied, the compensation in it
    compensator_->derivatives(in, z, dx.subspan(n + 1, static_cast<std::size_t>(n_comp_)));
  }
  dx[n] = c_.loop == ControlLoop::position ? r.value - x[0] : r.value - x[1];
}

PlantSignals ClosedLoop::signals(double t, std::span<const double> x, const InputValue& r) const {
  const InputValue u{control(t, x, r)};
  PlantSignals s = signals_of(*inner_, t, x.first(static_cast<std::size_t>(n_inner_)), u);
  s.reference = r.value;
  return s;
}

void ClosedLoop::events(double t, std::span<const double> x, Inputs u, std::span<double> g) const {
  if (compensator_) compensator_->events(measured(t, x, u[0]), own_states(x), g);
}

void ClosedLoop::on_event(double t, std::span<double> x, Inputs u, int k) const {
  if (compensator_)
    compensator_->on_event(measured(t, x, u[0]), x.subspan(static_cast<std::size_t>(n_inner_ + 1),
                                                           static_cast<std::size_t>(n_comp_)),
                           k);
}

}  // namespace frictionlab
