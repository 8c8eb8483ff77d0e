// A plant closed by a controller: see include/frictionlab/simulate/closed_loop.hpp.
#include "frictionlab/simulate/closed_loop.hpp"

#include <algorithm>
#include <type_traits>

#include "frictionlab/plants/backlash_axis.hpp"
#include "frictionlab/simulate/emps_pd_loop.hpp"

namespace frictionlab {

ClosedLoop::ClosedLoop(std::shared_ptr<const Plant> inner, PidParams c, std::shared_ptr<const Compensator> compensator)
    : inner_(std::move(inner)), pid_(c, "controller"), compensator_(std::move(compensator)) {
  require_loop_plant(inner_.get(), "controller");
  n_inner_ = inner_->num_states();
  n_pid_ = pid_.num_states();
  n_comp_ = compensator_ ? compensator_->num_states() : 0;
}

std::span<const double> ClosedLoop::own_states(std::span<const double> x) const {
  return x.subspan(static_cast<std::size_t>(n_inner_ + n_pid_), static_cast<std::size_t>(n_comp_));
}

std::shared_ptr<const ClosedLoop> ClosedLoop::with_conditions(CompensationConditions c) const {
  auto out = std::make_shared<ClosedLoop>(*this);
  out->conditions_ = std::move(c);
  return out;
}

std::shared_ptr<const ClosedLoop> ClosedLoop::measuring(MeasuredBody body) const {
  auto out = std::make_shared<ClosedLoop>(*this);
  out->measured_body_ = body;
  out->pos_ = 0;
  if (body != MeasuredBody::contact) {
    const auto* b = dynamic_cast<const BacklashAxis*>(inner_.get());
    if (b == nullptr)
      throw std::invalid_argument(std::string("controller.measure: ") + (body == MeasuredBody::motor ? "motor" : "load") +
                                  " needs a plant with a motor and a load (an axis with backlash); the " + inner_->type() +
                                  " has one body, which the loop measures");
    out->pos_ = static_cast<std::size_t>(body == MeasuredBody::motor ? b->motor_state() : b->load_state());
  }
  return out;
}

CompensatorInput ClosedLoop::measured(double t, std::span<const double> x, const InputValue& r) const {
  CompensatorInput in;
  in.t = t;
  in.position = x[pos_];
  in.velocity = x[pos_ + 1];
  conditions_.fill(in, t, x.first(static_cast<std::size_t>(n_inner_)));
  if (pid_.params().loop == ControlLoop::position) {
    in.reference = r.value;
    in.reference_rate = r.rate;
    in.reference_accel = r.accel;
  } else {  // r is a velocity: no position reference, so no position error
    in.reference = x[pos_];
    in.reference_rate = r.value;
    in.reference_accel = r.rate;
  }
  return in;
}

PidInput ClosedLoop::pid_input(std::span<const double> x, const InputValue& r) const {
  return {x[pos_], x[pos_ + 1], r.value, r.rate, r.accel};
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
  for (std::size_t i = 0; i < static_cast<std::size_t>(n_pid_); ++i) x[n + i] = 0.0;
  if (compensator_)
    compensator_->initial_states(measured(0.0, x, u[0]),
                                 x.subspan(n + static_cast<std::size_t>(n_pid_), static_cast<std::size_t>(n_comp_)));
}

void ClosedLoop::fixed_step_update(double t, double dt, std::span<const double> before, Inputs u_before,
                                   std::span<double> x, Inputs u) const {
  if (!compensator_ || pid_.sampled()) return;
  const std::size_t n = static_cast<std::size_t>(n_inner_);
  const double t0 = t - dt;
  // The force the drive held over the step: the inner plant's drive at the output of the step's start.
  const InputValue held{control(t0, before, u_before[0])};
  CompensatorInput in = measured(t, x, u[0]);
  in.drive = signals_of(*inner_, t0, before.first(n), held).drive;
  const auto z = x.subspan(n + static_cast<std::size_t>(n_pid_), static_cast<std::size_t>(n_comp_));
  const auto z0 = own_states(before);
  std::copy(z0.begin(), z0.end(), z.begin());  // from the step's start, not the engine's Euler value
  compensator_->update(in, z, dt);
}

double ClosedLoop::compensation(double t, std::span<const double> x, const InputValue& r) const {
  return compensator_ ? compensator_->output(measured(t, x, r), own_states(x)) : 0.0;
}

double ClosedLoop::control(std::span<const double> x, const InputValue& r, double compensation) const {
  return pid_.output(pid_input(x, r), x[static_cast<std::size_t>(n_inner_)], compensation);
}

double ClosedLoop::control(double t, std::span<const double> x, const InputValue& r) const {
  if (pid_.sampled()) return Pid::held(x.subspan(static_cast<std::size_t>(n_inner_), 3));
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
  if (pid_.sampled()) {
    const InputValue u{control(t, x, r)};
    derivatives_of(*inner_, t, inner_x, u, friction, dx.first(n));
    for (std::size_t i = n; i < x.size(); ++i) dx[i] = 0.0;  // discrete: change only at samples
    return;
  }
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
  dx[n] = pid_.error(pid_input(x, r));
}

PlantSignals ClosedLoop::signals(double t, std::span<const double> x, const InputValue& r) const {
  const InputValue u{control(t, x, r)};
  PlantSignals s = signals_of(*inner_, t, x.first(static_cast<std::size_t>(n_inner_)), u);
  s.reference = r.value;
  return s;
}

void ClosedLoop::sample(double t, std::span<double> x, const InputValue& r) const {
  if (!pid_.sampled()) return;
  const std::size_t n = static_cast<std::size_t>(n_inner_);
  const auto s = x.subspan(n, static_cast<std::size_t>(n_pid_));
  double c = 0.0;
  if (compensator_) {
    // The engine samples at t = j Ts from t = 0: the first sample closes no step.
    const double h = t < 0.5 * pid_.params().Ts ? 0.0 : pid_.params().Ts;
    CompensatorInput in = measured(t, x, r);
    in.drive = signals_of(*inner_, t, x.first(n), InputValue{Pid::held(s)}).drive;  // held over the step just ended
    c = compensator_->update(in, x.subspan(n + static_cast<std::size_t>(n_pid_), static_cast<std::size_t>(n_comp_)), h);
  }
  pid_.sample(pid_input(x, r), s, c);
}

int ClosedLoop::num_events() const {
  return inner_->num_events() + (compensator_ && !pid_.sampled() ? compensator_->num_events() : 0);
}

bool ClosedLoop::guard_event(int k) const { return k < inner_->num_events() && inner_->guard_event(k); }

void ClosedLoop::events(double t, std::span<const double> x, Inputs u, std::span<const double> friction,
                        std::span<double> g) const {
  const auto ni = static_cast<std::size_t>(inner_->num_events());
  if (ni > 0) {
    const InputValue c{control(t, x, u[0])};
    inner_->events(t, x.first(static_cast<std::size_t>(n_inner_)), Inputs(&c, 1), friction, g.first(ni));
  }
  if (compensator_ && !pid_.sampled()) compensator_->events(measured(t, x, u[0]), own_states(x), g.subspan(ni));
}

void ClosedLoop::events(double t, std::span<const double> x, Inputs u, std::span<double> g) const {
  const double no_friction = 0.0;
  events(t, x, u, std::span<const double>(&no_friction, 1), g);
}

void ClosedLoop::on_event(double t, std::span<double> x, Inputs u, int k) const {
  const int ni = inner_->num_events();
  if (k < ni) {
    const InputValue c{control(t, x, u[0])};
    inner_->on_event(t, x.first(static_cast<std::size_t>(n_inner_)), Inputs(&c, 1), k);
    return;
  }
  if (compensator_ && !pid_.sampled())
    compensator_->on_event(measured(t, x, u[0]), x.subspan(static_cast<std::size_t>(n_inner_ + n_pid_),
                                                           static_cast<std::size_t>(n_comp_)),
                           k - ni);
}

std::shared_ptr<const Plant> close_loop(std::shared_ptr<const Plant> plant, const Controller& controller,
                                        std::shared_ptr<const Compensator> compensator) {
  return std::visit(
      [&](const auto& c) -> std::shared_ptr<const Plant> {
        using C = std::decay_t<decltype(c)>;
        if constexpr (std::is_same_v<C, PidParams>)
          return std::make_shared<const ClosedLoop>(std::move(plant), c, std::move(compensator));
        else
          return std::make_shared<const EmpsPdLoop>(std::move(plant), c, std::move(compensator));
      },
      controller);
}

}  // namespace frictionlab
