// Two-axis table: see include/frictionlab/simulate/xy_table.hpp.
#include "frictionlab/simulate/xy_table.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "frictionlab/models/parameter.hpp"

namespace frictionlab {
namespace {

constexpr const char* kNames[2] = {"x", "y"};
// Offsets in an axis's own block (after the four contact states).
constexpr std::size_t kIntegral = 0, kApplied = 1, kComputed = 2;

std::string who(int i) { return std::string("xy-table: axis ") + kNames[i]; }

void require(bool ok, int i, const char* name, double value, const char* rule) {
  detail::require(ok, who(i), name, value, rule);
}

void check_timing(const XyTiming& timing) {
  PidParams t;
  t.Ts = timing.Ts;
  t.delay = timing.delay;
  t.validate_timing("xy-table");
}

// The axis's checks beyond its PID's (Pid checks the gains): its body, and a gain set that fits
// the table (a position loop on a force-driven carriage, the timing the table's).
void check_axis(const XyAxis& a, int i) {
  require(std::isfinite(a.mass) && a.mass >= 0, i, "mass", a.mass, ">= 0 (kg)");
  require(std::isfinite(a.inertia) && a.inertia >= 0, i, "inertia", a.inertia, ">= 0 (kg m^2)");
  require(std::isfinite(a.lead) && a.lead >= 0, i, "lead", a.lead, ">= 0 (m/rev)");
  require(std::isfinite(a.offset), i, "offset", a.offset, "finite (N)");
  require(a.inertia == 0 || a.lead > 0, i, "lead", a.lead, "> 0 (m/rev) when an inertia is given");
  const double M = a.equivalent_mass();
  require(std::isfinite(M) && M > 0, i, "equivalent mass", M, "> 0 (kg): give mass, or inertia and lead");
  const PidParams& c = a.gains;
  if (c.loop != ControlLoop::position)
    throw std::invalid_argument(who(i) + ": the axis runs a position loop; a velocity loop is not supported");
  require(c.compensation_gain == 1.0, i, "compensation_gain", c.compensation_gain,
          "1 (the drive takes a force: the compensator's N go straight to the command)");
  require(c.Ts == 0.0, i, "Ts", c.Ts, "0 (the table's timing, XyTiming, sets the axes' sample period)");
  require(c.delay == 0, i, "delay", c.delay, "0 (the table's timing, XyTiming, sets the axes' delay)");
}

// Axis i's PID, after the table's and the axis's checks, with the table's timing.
Pid axis_pid(const XyAxis& a, int i, const XyTiming& timing) {
  if (i == 0) check_timing(timing);
  check_axis(a, i);
  PidParams p = a.gains;
  p.Ts = timing.Ts;
  p.delay = timing.delay;
  return Pid(p, who(i), PidUnits::force_on_linear_axis());
}

}  // namespace

double XyAxis::equivalent_mass() const {
  if (inertia == 0.0) return mass;
  const double ratio = 2.0 * std::numbers::pi / lead;  // rad of screw per m of travel
  return mass + inertia * ratio * ratio;
}

XyTable::XyTable(XyAxis x, XyAxis y, XyTiming timing)
    : axes_{std::move(x), std::move(y)},
      pids_{axis_pid(axes_[0], 0, timing), axis_pid(axes_[1], 1, timing)},
      timing_(timing) {
  for (int i = 0; i < 2; ++i) {
    mass_[i] = axes_[i].equivalent_mass();
    const int nc = axes_[i].compensator ? axes_[i].compensator->num_states() : 0;
    own_[i] = static_cast<int>(comp_offset()) + nc;
    events_[i] = axes_[i].compensator && !sampled() ? axes_[i].compensator->num_events() : 0;
  }
}

const XyAxis& XyTable::axis(int i) const {
  if (i != 0 && i != 1) throw std::out_of_range("xy-table has axes 0 (x) and 1 (y), not " + std::to_string(i));
  return axes_[i];
}

Contact XyTable::contact(int i) const {
  const XyAxis& a = axis(i);
  return {kNames[i], 2 * i, 2 * i + 1, a.law ? &*a.law : nullptr};
}

double XyTable::inertia(int contact) const {
  (void)axis(contact);
  return mass_[contact];
}

CompensatorInput XyTable::measured(int i, double t, std::span<const double> x, const InputValue& r) const {
  CompensatorInput in;
  in.t = t;
  in.position = x[static_cast<std::size_t>(2 * i)];
  in.velocity = x[static_cast<std::size_t>(2 * i + 1)];
  in.reference = r.value;
  in.reference_rate = r.rate;
  in.reference_accel = r.accel;
  return in;
}

PidInput XyTable::pid_input(int i, std::span<const double> x, const InputValue& r) const {
  return {x[static_cast<std::size_t>(2 * i)], x[static_cast<std::size_t>(2 * i + 1)], r.value, r.rate, r.accel};
}

double XyTable::command(int i, double t, std::span<const double> x, const InputValue& r) const {
  (void)axis(i);
  if (sampled()) return x[block(i) + kApplied];
  const Compensator* comp = axes_[i].compensator.get();
  const double c = comp ? comp->output(measured(i, t, x, r), x.subspan(block(i) + comp_offset(), comp->num_states())) : 0.0;
  return pids_[i].output(pid_input(i, x, r), integral(i, x), c);
}

void XyTable::initial_extras(std::span<double> x) const {
  for (int i = 0; i < 2; ++i) {
    const std::size_t b = block(i);
    for (std::size_t j = 0; j < comp_offset(); ++j) x[b + j] = 0.0;
    if (const Compensator* comp = axes_[i].compensator.get()) {
      CompensatorInput at_rest;
      at_rest.position = x[static_cast<std::size_t>(2 * i)];
      at_rest.velocity = x[static_cast<std::size_t>(2 * i + 1)];
      comp->initial_states(at_rest, x.subspan(b + comp_offset(), static_cast<std::size_t>(comp->num_states())));
    }
  }
}

void XyTable::applied(double t, std::span<const double> x, Inputs u, std::span<double> force) const {
  for (int i = 0; i < 2; ++i)
    force[static_cast<std::size_t>(i)] = command(i, t, x, u[static_cast<std::size_t>(i)]) + axes_[i].offset;
}

void XyTable::derivatives(double t, std::span<const double> x, Inputs u, std::span<const double> friction,
                          std::span<double> dx) const {
  for (int i = 0; i < 2; ++i) {
    const std::size_t p = static_cast<std::size_t>(2 * i), b = block(i);
    const InputValue& r = u[static_cast<std::size_t>(i)];
    const Compensator* comp = axes_[i].compensator.get();
    const std::size_t nz = comp ? static_cast<std::size_t>(comp->num_states()) : 0;
    double drive;
    if (sampled()) {
      drive = x[b + kApplied];
      dx[b + kIntegral] = dx[b + kApplied] = dx[b + kComputed] = 0.0;  // discrete: change only at samples
      for (std::size_t j = 0; j < nz; ++j) dx[b + comp_offset() + j] = 0.0;
    } else if (!comp) {
      drive = pids_[i].output(pid_input(i, x, r), integral(i, x), 0.0);
      dx[b + kIntegral] = pids_[i].error(pid_input(i, x, r));
    } else {
      CompensatorInput in = measured(i, t, x, r);
      const auto z = x.subspan(b + comp_offset(), nz);
      drive = pids_[i].output(pid_input(i, x, r), integral(i, x), comp->output(in, z));
      in.drive = drive;  // the force applied, the compensation in it
      comp->derivatives(in, z, dx.subspan(b + comp_offset(), nz));
      dx[b + kIntegral] = pids_[i].error(pid_input(i, x, r));
    }
    dx[p] = x[p + 1];
    dx[p + 1] = (drive + axes_[i].offset - friction[static_cast<std::size_t>(i)]) / mass_[i];
  }
}

bool XyTable::jacobian(double t, std::span<const double> x, Inputs u, std::span<const double>, std::span<double> dfdx,
                       std::span<double> dfdF) const {
  const auto n = static_cast<std::size_t>(num_states());
  constexpr std::size_t nc = 2;
  // The compensators' partials first, with respect to w = (position, velocity, drive, z...): one
  // without an analytic form leaves the whole Jacobian to difference quotients, nothing written.
  // Sampled, they are not needed (the compensator's states are discrete, its output is in the
  // held command). Scratch on the stack for up to kStack states each, else on the heap.
  constexpr std::size_t kStack = 8, kW = 3 + kStack;
  std::array<double, 2 * kW> dout_stack{};
  std::array<double, 2 * kStack * kW> dderiv_stack{};
  std::vector<double> heap[2];
  std::span<double> dout[2], dderiv[2];
  double comp_out[2] = {0.0, 0.0};
  for (int i = 0; i < 2; ++i) {
    const Compensator* comp = axes_[i].compensator.get();
    if (!comp || sampled()) continue;
    const auto nz = static_cast<std::size_t>(comp->num_states()), w = 3 + nz;
    if (nz <= kStack) {
      dout[i] = std::span<double>(dout_stack).subspan(static_cast<std::size_t>(i) * kW, w);
      dderiv[i] = std::span<double>(dderiv_stack).subspan(static_cast<std::size_t>(i) * kStack * kW, nz * w);
    } else {  // no compensator of the library has more than one state
      heap[i].assign(w * (nz + 1), 0.0);
      dout[i] = std::span<double>(heap[i]).first(w);
      dderiv[i] = std::span<double>(heap[i]).subspan(w, nz * w);
    }
    const CompensatorInput in = measured(i, t, x, u[static_cast<std::size_t>(i)]);
    const auto z = x.subspan(block(i) + comp_offset(), nz);
    if (!comp->jacobian(in, z, dout[i], dderiv[i])) return false;
    comp_out[i] = comp->output(in, z);
  }

  std::fill(dfdx.begin(), dfdx.begin() + static_cast<std::ptrdiff_t>(n * n), 0.0);
  std::fill(dfdF.begin(), dfdF.begin() + static_cast<std::ptrdiff_t>(n * nc), 0.0);
  auto at = [&](std::size_t row, std::size_t col) -> double& { return dfdx[row * n + col]; };
  for (int i = 0; i < 2; ++i) {
    const std::size_t p = static_cast<std::size_t>(2 * i), v = p + 1, b = block(i);
    const double M = mass_[i];
    at(p, v) = 1.0;                                     // d position / dt = velocity
    dfdF[v * nc + static_cast<std::size_t>(i)] = -1.0 / M;  // M dv/dt = drive - F
    if (sampled()) {
      at(v, b + kApplied) = 1.0 / M;  // the held command; every discrete state has derivative 0
      continue;
    }
    // Continuous: drive = sat(raw), raw = Kp (r - p) + Ki I - Kd v + feedforward + c(p, v, z).
    const PidParams& g = pids_[i].params();
    const Compensator* comp = axes_[i].compensator.get();
    const std::size_t nz = comp ? static_cast<std::size_t>(comp->num_states()) : 0, w = 3 + nz, zc = b + comp_offset();
    const double raw = pids_[i].unsaturated(pid_input(i, x, u[static_cast<std::size_t>(i)]), integral(i, x), comp_out[i]);
    // Slope of the saturation: 1 inside (clamp is the identity at |raw| = limit too), 0 beyond.
    const double s = pids_[i].saturation_slope(raw);
    // d drive / d(p, v, I, z_j): the compensator's output enters raw (it never reads the drive).
    const double dp = s * (-g.Kp + (comp ? dout[i][0] : 0.0));
    const double dv = s * (-g.Kd + (comp ? dout[i][1] : 0.0));
    const double dI = s * g.Ki;
    at(v, p) = dp / M;
    at(v, v) = dv / M;
    at(v, b + kIntegral) = dI / M;
    for (std::size_t j = 0; j < nz; ++j) at(v, zc + j) = s * dout[i][3 + j] / M;
    at(b + kIntegral, p) = -1.0;  // d I / dt = r - p
    // The compensator's state equations: through p, v and the drive (which depends on p, v, I, z).
    for (std::size_t k = 0; k < nz; ++k) {
      const std::span<const double> row = dderiv[i].subspan(k * w, w);
      const double dd = row[2];  // d (dz_k/dt) / d drive
      at(zc + k, p) = row[0] + dd * dp;
      at(zc + k, v) = row[1] + dd * dv;
      at(zc + k, b + kIntegral) = dd * dI;
      for (std::size_t j = 0; j < nz; ++j) at(zc + k, zc + j) = row[3 + j] + dd * s * dout[i][3 + j];
    }
  }
  return true;
}

void XyTable::signals(double t, std::span<const double> x, Inputs u, std::span<PlantSignals> out) const {
  for (int i = 0; i < 2; ++i) {
    const InputValue& r = u[static_cast<std::size_t>(i)];
    const double drive = command(i, t, x, r);
    out[static_cast<std::size_t>(i)] = PlantSignals{0.0, 0.0, r.value, drive};
  }
}

void XyTable::sample(double t, std::span<double> x, Inputs u) const {
  if (!sampled()) return;
  // The engine samples at t = j Ts from t = 0: the first sample closes no step.
  const double h = t < 0.5 * timing_.Ts ? 0.0 : timing_.Ts;
  for (int i = 0; i < 2; ++i) {
    const std::size_t b = block(i);
    const InputValue& r = u[static_cast<std::size_t>(i)];
    double c = 0.0;
    if (const Compensator* comp = axes_[i].compensator.get()) {
      CompensatorInput in = measured(i, t, x, r);
      in.drive = x[b + kApplied];  // the force held over the step just ended
      c = comp->update(in, x.subspan(b + comp_offset(), static_cast<std::size_t>(comp->num_states())), h);
    }
    pids_[i].sample(pid_input(i, x, r), x.subspan(b, 3), c);
  }
}

void XyTable::events(double t, std::span<const double> x, Inputs u, std::span<double> g) const {
  std::size_t k = 0;
  for (int i = 0; i < 2; ++i) {
    if (events_[i] == 0) continue;
    const Compensator& comp = *axes_[i].compensator;
    comp.events(measured(i, t, x, u[static_cast<std::size_t>(i)]),
                x.subspan(block(i) + comp_offset(), static_cast<std::size_t>(comp.num_states())),
                g.subspan(k, static_cast<std::size_t>(events_[i])));
    k += static_cast<std::size_t>(events_[i]);
  }
}

void XyTable::on_event(double t, std::span<double> x, Inputs u, int k) const {
  const int i = k < events_[0] ? 0 : 1;
  const int local = i == 0 ? k : k - events_[0];
  if (local < 0 || local >= events_[i]) return;
  const Compensator& comp = *axes_[i].compensator;
  comp.on_event(measured(i, t, x, u[static_cast<std::size_t>(i)]),
                x.subspan(block(i) + comp_offset(), static_cast<std::size_t>(comp.num_states())), local);
}

}  // namespace frictionlab
