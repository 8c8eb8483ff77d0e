// EMPS discrete PD loop: see include/frictionlab/simulate/emps_pd_loop.hpp.
#include "frictionlab/simulate/emps_pd_loop.hpp"

#include <stdexcept>

namespace frictionlab {

EmpsPdLoop::EmpsPdLoop(std::shared_ptr<const Plant> inner, EmpsPdParams p, std::shared_ptr<const Compensator> compensator)
    : inner_(std::move(inner)),
      pd_((require_loop_plant(inner_.get(), "controller (emps-pd)"), std::move(p))),
      compensator_(std::move(compensator)) {
  n_inner_ = inner_->num_states();
  n_comp_ = compensator_ ? compensator_->num_states() : 0;
  if (inner_->num_events() > 0)  // a backlash's impacts: this loop does not forward plant events
    throw std::invalid_argument("controller (emps-pd): cannot close this loop around an axis with backlash; use a pid controller");
}

std::shared_ptr<const EmpsPdLoop> EmpsPdLoop::with_conditions(CompensationConditions c) const {
  auto out = std::make_shared<EmpsPdLoop>(*this);
  out->conditions_ = std::move(c);
  return out;
}

// What the compensator sees at time t of the inner plant's states x (position q = x[0]): the
// position and the contact's conditions; the caller adds the velocity and the reference.
CompensatorInput EmpsPdLoop::measured(double t, std::span<const double> x) const {
  CompensatorInput in;
  in.t = t;
  in.position = x[0];
  conditions_.fill(in, t, x);
  return in;
}

void EmpsPdLoop::initial_extras(std::span<double> x, Inputs u) const {
  const std::size_t n = static_cast<std::size_t>(n_inner_);
  const InputValue no_output{};
  inner_->initial_extras(x.first(n), Inputs(&no_output, 1));
  for (std::size_t i = n; i < n + kDiscrete; ++i) x[i] = 0.0;  // primed = 0: the first sample starts the memory
  if (compensator_) {
    CompensatorInput in = measured(0.0, x.first(n));
    in.velocity = x[1];
    in.reference = u[0].value;
    compensator_->initial_states(in, x.subspan(n + kDiscrete, static_cast<std::size_t>(n_comp_)));
  }
}

double EmpsPdLoop::applied(double t, std::span<const double> x, const InputValue&) const {
  const std::size_t n = static_cast<std::size_t>(n_inner_);
  const double v = EmpsPd::held(x.subspan(n, kDiscrete));
  return applied_of(*inner_, t, x.first(n), InputValue{pd_.params().gtau * v, 0.0});
}

void EmpsPdLoop::derivatives(double t, std::span<const double> x, const InputValue&, double friction,
                             std::span<double> dx) const {
  const std::size_t n = static_cast<std::size_t>(n_inner_);
  const double v = EmpsPd::held(x.subspan(n, kDiscrete));
  derivatives_of(*inner_, t, x.first(n), InputValue{pd_.params().gtau * v, 0.0}, friction, dx.first(n));
  for (std::size_t i = n; i < x.size(); ++i) dx[i] = 0.0;  // discrete and compensator states change only at samples
}

PlantSignals EmpsPdLoop::signals(double t, std::span<const double> x, const InputValue& r) const {
  const std::size_t n = static_cast<std::size_t>(n_inner_);
  const double gtau = pd_.params().gtau;
  const auto s = x.subspan(n, kDiscrete);
  PlantSignals out = signals_of(*inner_, t, x.first(n), InputValue{gtau * EmpsPd::held(s), 0.0});
  out.voltage = EmpsPd::computed(s);
  out.drive = gtau * EmpsPd::computed(s);
  out.reference = r.value;
  return out;
}

void EmpsPdLoop::sample(double t, std::span<double> x, const InputValue& r) const {
  const std::size_t n = static_cast<std::size_t>(n_inner_);
  const EmpsPdParams& p = pd_.params();
  const double q = x[0];
  const auto s = x.subspan(n, kDiscrete);
  const EmpsPdMeasurement m = pd_.measure(s, q, r.value);
  double compensation = 0.0;  // V
  if (compensator_) {
    CompensatorInput in = measured(t, x.first(n));
    in.velocity = m.velocity;
    in.reference = r.value;
    in.reference_rate = m.reference_rate;
    in.reference_accel = r.accel;
    in.drive = p.gtau * EmpsPd::held(s);  // the force held over the period just ended
    const auto z = x.subspan(n + kDiscrete, static_cast<std::size_t>(n_comp_));
    compensation = compensator_->update(in, z, m.first ? 0.0 : p.dt) / p.gtau;
  }
  pd_.sample(s, t, q, r.value, m, compensation);
}

}  // namespace frictionlab
