// EMPS discrete PD loop: see include/frictionlab/plants/emps_pd.hpp.
#include "frictionlab/plants/emps_pd.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace frictionlab {
namespace {

void require(bool ok, const char* name, double value, const char* rule) {
  if (!ok) {
    std::ostringstream s;
    s.precision(10);
    s << "controller (emps-pd): " << name << " = " << value << " must be " << rule;
    throw std::invalid_argument(s.str());
  }
}

// Offsets of the discrete states after the inner plant's.
constexpr std::size_t kApplied = 0, kComputed = 1, kPrevQ = 2, kPrevQf = 3, kPrimed = 4, kPrevR = 5;

}  // namespace

EmpsPdLoop::EmpsPdLoop(std::shared_ptr<const Plant> inner, EmpsPdParams p, std::shared_ptr<const Compensator> compensator)
    : inner_(std::move(inner)), p_(std::move(p)), compensator_(std::move(compensator)) {
  require_loop_plant(inner_.get(), "controller (emps-pd)");
  require(std::isfinite(p_.kp) && p_.kp >= 0, "kp", p_.kp, ">= 0 (1/s)");
  require(std::isfinite(p_.kv) && p_.kv >= 0, "kv", p_.kv, ">= 0 (V/(m/s))");
  require(std::isfinite(p_.gtau) && p_.gtau > 0, "gtau", p_.gtau, "> 0 (N/V)");
  require(std::isfinite(p_.limit) && p_.limit > 0, "limit", p_.limit, "> 0 (V)");
  require(std::isfinite(p_.dt) && p_.dt > 0, "dt", p_.dt, "> 0 (s)");
  require(p_.delay == 0 || p_.delay == 1, "delay", p_.delay, "0 or 1 (samples)");
  p_.pulses.validate("controller (emps-pd): pulses");
  n_inner_ = inner_->num_states();
  n_comp_ = compensator_ ? compensator_->num_states() : 0;
}

void EmpsPdLoop::initial_extras(std::span<double> x, Inputs u) const {
  const std::size_t n = static_cast<std::size_t>(n_inner_);
  const InputValue no_output{};
  inner_->initial_extras(x.first(n), Inputs(&no_output, 1));
  for (std::size_t i = n; i < n + kDiscrete; ++i) x[i] = 0.0;  // primed = 0: the first sample starts the memory
  if (compensator_) {
    CompensatorInput in;
    in.position = x[0];
    in.velocity = x[1];
    in.reference = u[0].value;
    compensator_->initial_states(in, x.subspan(n + kDiscrete, static_cast<std::size_t>(n_comp_)));
  }
}

double EmpsPdLoop::applied(double t, std::span<const double> x, const InputValue&) const {
  const std::size_t n = static_cast<std::size_t>(n_inner_);
  return applied_of(*inner_, t, x.first(n), InputValue{p_.gtau * x[n + kApplied], 0.0});
}

void EmpsPdLoop::derivatives(double t, std::span<const double> x, const InputValue&, double friction,
                             std::span<double> dx) const {
  const std::size_t n = static_cast<std::size_t>(n_inner_);
  derivatives_of(*inner_, t, x.first(n), InputValue{p_.gtau * x[n + kApplied], 0.0}, friction, dx.first(n));
  for (std::size_t i = n; i < x.size(); ++i) dx[i] = 0.0;  // discrete and compensator states change only at samples
}

PlantSignals EmpsPdLoop::signals(double t, std::span<const double> x, const InputValue& r) const {
  const std::size_t n = static_cast<std::size_t>(n_inner_);
  PlantSignals s = signals_of(*inner_, t, x.first(n), InputValue{p_.gtau * x[n + kApplied], 0.0});
  s.voltage = x[n + kComputed];
  s.drive = p_.gtau * x[n + kComputed];
  s.reference = r.value;
  return s;
}

void EmpsPdLoop::sample(double t, std::span<double> x, const InputValue& r) const {
  const std::size_t n = static_cast<std::size_t>(n_inner_);
  const double q = x[0];
  const bool first = x[n + kPrimed] == 0.0;
  if (first) {  // first sample: the memory starts at rest at the current position and reference
    x[n + kPrevQ] = q;
    x[n + kPrevQf] = q;
    x[n + kPrevR] = r.value;
    x[n + kPrimed] = 1.0;
  }
  const double qf = 0.5 * q + 0.5 * x[n + kPrevQ];
  const double qd_m = (qf - x[n + kPrevQf]) / p_.dt;
  double compensation = 0.0;  // V
  if (compensator_) {
    CompensatorInput in;
    in.t = t;
    in.position = q;
    in.velocity = qd_m;
    in.reference = r.value;
    in.reference_rate = (r.value - x[n + kPrevR]) / p_.dt;
    in.reference_accel = r.accel;
    in.drive = p_.gtau * x[n + kApplied];  // the force held over the period just ended
    const auto z = x.subspan(n + kDiscrete, static_cast<std::size_t>(n_comp_));
    compensation = compensator_->update(in, z, first ? 0.0 : p_.dt) / p_.gtau;
  }
  const double v = std::clamp(p_.kp * p_.kv * (r.value - q) - p_.kv * qd_m + compensation, -p_.limit, p_.limit) +
                   p_.pulses.at(t).value;
  // delay 1: the output computed at the previous sample goes to the drive now.
  x[n + kApplied] = p_.delay == 1 ? x[n + kComputed] : v;
  x[n + kComputed] = v;
  x[n + kPrevQ] = q;
  x[n + kPrevQf] = qf;
  x[n + kPrevR] = r.value;
}

}  // namespace frictionlab
