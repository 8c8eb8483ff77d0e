#include "frictionlab/analysis/plan/design.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "frictionlab/budget.hpp"
#include "frictionlab/error.hpp"
#include "frictionlab/format.hpp"
#include "frictionlab/analysis/plan/predict.hpp"

namespace frictionlab {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;

// Design constants, each with why.
constexpr double kDefaultBreakawayMargin = 1.4;  // the lecture: 0.15 A peak over the 0.1064 A breakaway
constexpr double kDefaultLugreMargin = 2.0;      // Canudas de Wit's sliding sine: 2 Fs
constexpr double kSettleTau = 5.0;               // time constants to steady state (e^-5 < 1 %)
constexpr double kHoldPrecision = 1e-3;          // the hold's mean speed and force to 0.1 % through the noise
constexpr double kSweepPrecision = 2e-3;         // a sweep point's mean force to 0.2 % of Fc through the noise
constexpr double kSettleBand = 0.02;             // a step has settled within 2 % of its set point
constexpr double kSettleFactor = 1.5;            // settle time = 1.5 x the simulated 2 % time
constexpr double kMinSegment = 1.0;              // s: identify sweep keeps steady segments >= 0.5 s (its default)
constexpr double kSpeedUse = 0.95;               // fraction of a speed limit a plan goes to
constexpr double kForceUse = 0.9;                // fraction of a force limit a steady level uses
constexpr double kBelowVs = 0.8, kAboveVs = 1.25;  // sweep speeds kept off vs itself, where the law bends

std::string u(Quantity q, Axis a) { return std::string(unit(q, a)); }

std::string num(double x) { return format_number(x, 4); }

void add(ExperimentProfile& p, std::string name, double value, std::string unit_text, std::string what) {
  p.figures.push_back({std::move(name), value, std::move(unit_text), std::move(what)});
}

// Largest drive force the limits allow (N or N m), and the words naming the limit that sets it.
struct ForceLimit {
  double value = kInf;
  std::string name;  // "--limits current = 0.2 A (2.8e-3 N m)"
};

ForceLimit force_limit(const PlanRig& rig, const PlanLimits& l) {
  ForceLimit f;
  const std::string fu = u(Quantity::force, rig.axis);
  if (std::isfinite(l.current)) {
    if (!(rig.torque_constant > 0))
      throw std::invalid_argument("--limits current = " + num(l.current) + " A: the scenario's plant (" +
                                  rig.scenario.plant->type() + ") has no motor current; use force=");
    f.value = l.current * rig.torque_constant;
    f.name = "--limits current = " + num(l.current) + " A (Kt i = " + num(f.value) + " " + fu + ")";
  }
  if (l.force < f.value) {
    f.value = l.force;
    f.name = "--limits force = " + num(l.force) + " " + fu;
  }
  return f;
}

// Force (N or N m) of one std of the measured drive signal.
double force_noise(const PlanRig& rig, const SensorNoise& n) {
  return rig.torque_constant > 0 ? rig.torque_constant * n.current : n.force;
}

double need(const PlanRig& rig, const char* name, const char* method) {
  const double v = rig.prior(name);
  if (!std::isfinite(v))
    throw std::invalid_argument(rig.prior_file + ": the prior law '" + rig.law.name() + "' has no " + name + "; a " +
                                method + " plan needs it");
  return v;
}

void require_drive(const PlanRig& rig, PlanMethod m, std::initializer_list<PlanDrive> ok, const char* what) {
  for (auto d : ok)
    if (rig.drive == d) return;
  const std::string name = plan_method_name(m);
  throw std::invalid_argument(rig.scenario_file + ": " + (name[0] == 'i' ? "an " : "a ") + name + " plan needs " + what +
                              "; the scenario's plant is driven by " + plan_drive_name(rig.drive));
}

// ---- breakaway: trapezoid of current or force ----
ExperimentProfile design_breakaway(const PlanRig& rig, const PlanLimits& lim, const SensorNoise& noise,
                                   const PlanDesignOptions& o, double fs) {
  require_drive(rig, PlanMethod::breakaway, {PlanDrive::current, PlanDrive::force},
                "an open-loop drive (dc-motor with drive: current, or an axis driven by force)");
  ExperimentProfile p;
  const Axis ax = rig.axis;
  const std::string fu = u(Quantity::force, ax), vu = u(Quantity::velocity, ax), cu = rig.command_unit;
  const double Fs = need(rig, "Fs", "breakaway"), Fc = need(rig, "Fc", "breakaway");
  const double Fv = rig.damping;
  if (!(Fv > 0))
    throw std::invalid_argument(rig.prior_file + ": the prior's Fv = 0: a breakaway plan needs viscous damping to reach "
                                "a steady speed in the hold (give the prior a viscous coefficient Fv > 0)");
  const double tau = rig.time_constant();
  const double margin = o.margin > 0 ? o.margin : kDefaultBreakawayMargin;
  const ForceLimit fl = force_limit(rig, lim);
  const double k = rig.force_per_command;
  double peak = margin * Fs;
  if (peak > fl.value) {
    if (fl.value < o.min_margin * Fs)
      throw std::invalid_argument(fl.name + " is below " + num(o.min_margin) + " Fs = " + num(o.min_margin * Fs / k) + " " +
                                  cu + " (prior Fs = " + num(Fs) + " " + fu +
                                  "): the axis would not break away with margin");
    peak = fl.value;
    p.warnings.push_back(fl.name + " lowers the peak to " + num(peak / Fs) + " Fs (margin " + num(margin) + " asked)");
  }
  double w = (peak - Fc) / Fv;
  if (w > kSpeedUse * lim.speed) {
    const double lowered = Fc + Fv * kSpeedUse * lim.speed;
    if (lowered < o.min_margin * Fs)
      throw std::invalid_argument("--limits speed = " + num(lim.speed) + " " + vu + " is reached below " +
                                  num(o.min_margin) + " Fs: the steady speed at the peak must exceed (" +
                                  num(o.min_margin) + " Fs - Fc) / Fv = " + num((o.min_margin * Fs - Fc) / Fv) + " " + vu);
    peak = lowered;
    w = kSpeedUse * lim.speed;
    p.warnings.push_back("--limits speed = " + num(lim.speed) + " " + vu + " lowers the peak to " + num(peak / Fs) + " Fs");
  }
  const double rate = o.lag_fraction * Fc / tau;  // N/s: lag bias rate * tau = lag_fraction Fc
  const double sF = force_noise(rig, noise);
  const double n_avg = std::max(std::pow(noise.velocity / (kHoldPrecision * w), 2), std::pow(sF / (kHoldPrecision * peak), 2));
  const double settle = kSettleTau * tau;
  const double hold = settle + std::max(settle, n_avg / fs);
  const double pre = 1.0, tail = kSettleTau * tau + 1.0;
  const double ramp = peak / rate;
  p.signal.shape = InputShape::trapezoid;
  p.signal.time = pre;
  p.signal.level = peak / k;
  p.signal.rate = rate / k;
  p.signal.hold = hold;
  p.duration = pre + 2 * ramp + hold + tail;
  add(p, "ramp_rate", rate / k, cu + "/s", "rate of the ramps up and down");
  add(p, "peak", peak / k, cu, "level of the hold");
  add(p, "hold", hold, "s", "duration of the hold");
  add(p, "ramp_time", ramp, "s", "duration of each ramp");
  add(p, "margin", peak / Fs, "", "peak over the prior's breakaway level Fs");
  add(p, "time_constant", tau, "s", "mechanical time constant M / Fv of the prior");
  add(p, "hold_speed", w, vu, "steady speed in the hold on the prior");
  add(p, "lag_bias", rate * tau, fu, "bias of the stop read-off from the ramp's lag, rate x time constant");
  add(p, "expected_breakaway_time", pre + Fs / rate, "s", "when the prior breaks away");
  p.windows.push_back({"ramp-up", pre, pre + ramp, peak / k});
  p.windows.push_back({"hold", pre + ramp, pre + ramp + hold, peak / k});
  p.windows.push_back({"ramp-down", pre + ramp + hold, pre + 2 * ramp + hold, 0.0});
  return p;
}

// Time (s) after `begin` from which |v - level| stays within the band until `end`; end - begin when never.
double settling_time(const Trajectory& tr, double begin, double end, double level) {
  const double band = kSettleBand * std::abs(level);
  double last = begin;
  for (std::size_t i = 0; i < tr.rows(); ++i) {
    if (tr.time[i] < begin || tr.time[i] >= end) continue;
    if (std::abs(tr.velocity[i] - level) > band) last = tr.time[i];
  }
  return last - begin;
}

InputSignal staircase(const std::vector<double>& times, const std::vector<double>& values) {
  InputSignal s;
  s.shape = InputShape::table;
  s.hold_steps = true;
  s.times = times;
  s.values = values;
  return s;
}

// ---- sweep: staircase of velocity set points ----
ExperimentProfile design_sweep(const PlanRig& rig, const PlanLimits& lim, const SensorNoise& noise,
                               const PlanDesignOptions& o, double fs) {
  require_drive(rig, PlanMethod::sweep, {PlanDrive::velocity_loop}, "a velocity loop (controller: {loop: velocity, ...})");
  ExperimentProfile p;
  const Axis ax = rig.axis;
  const std::string fu = u(Quantity::force, ax), vu = u(Quantity::velocity, ax);
  const double Fc = need(rig, "Fc", "sweep");
  const double Fs = std::max(Fc, std::isfinite(rig.prior("Fs")) ? rig.prior("Fs") : Fc);
  const double Fv = std::isfinite(rig.prior("Fv")) ? rig.prior("Fv") : 0.0;
  const double vs = rig.prior("vs");
  const ForceLimit fl = force_limit(rig, lim);
  double top = 0;
  if (std::isfinite(lim.speed)) {
    top = kSpeedUse * lim.speed;
  } else if (Fv > 0) {
    top = 3 * Fs / Fv;  // the viscous part 3 times the static level: Fv well determined
  } else {
    top = std::isfinite(vs) ? 100 * vs : 1.0;
    p.warnings.push_back("the prior has no viscous term and no --limits speed is given: top speed " + num(top) + " " + vu);
  }
  if (std::isfinite(fl.value) && Fc + Fv * top > kForceUse * fl.value) {
    if (kForceUse * fl.value <= Fs)
      throw std::invalid_argument(fl.name + " is below the prior's friction Fs = " + num(Fs) + " " + fu + " / " +
                                  num(kForceUse) + ": no constant speed can be held");
    top = (kForceUse * fl.value - Fc) / Fv;
    p.warnings.push_back(fl.name + " lowers the top speed to " + num(top) + " " + vu);
  }
  double bottom = std::isfinite(vs) ? vs / 5 : top / 300;
  if (lim.min_speed > bottom) bottom = lim.min_speed;
  if (!(bottom < top / 2))
    throw std::invalid_argument("--limits min_speed = " + num(lim.min_speed) + " " + vu + " leaves no range of speeds below the top speed " +
                                num(top) + " " + vu + " (the sweep needs bottom < top / 2)");
  const int n = o.speeds;
  auto logspace = [](double a, double b, int count, std::vector<double>& out) {
    for (int i = 0; i < count; ++i) out.push_back(count == 1 ? a : a * std::pow(b / a, double(i) / (count - 1)));
  };
  std::vector<double> speeds;
  if (std::isfinite(vs) && bottom < kBelowVs * vs && kAboveVs * vs < top) {
    // At least 4 speeds below vs (the static fit wants 3 per direction below its vs), the rest
    // above it: the Stribeck dip and the viscous slope both get points.
    const double share = std::log(kBelowVs * vs / bottom) / std::log(top / bottom);
    const int low = std::clamp(static_cast<int>(std::lround(share * n)), 4, n / 2);
    logspace(bottom, kBelowVs * vs, low, speeds);
    logspace(kAboveVs * vs, top, n - low, speeds);
  } else {
    logspace(bottom, top, n, speeds);
  }
  if (std::isfinite(vs)) {
    const auto below = std::count_if(speeds.begin(), speeds.end(), [&](double v) { return v < vs; });
    if (below < 3) {
      p.undetermined = {"vs", "delta"};
      p.warnings.push_back("only " + std::to_string(below) + " of the " + std::to_string(n) +
                           " speeds per direction lie below the prior's vs = " + num(vs) + " " + vu +
                           " (3 are needed): vs and delta cannot be determined; lower --limits min_speed");
    }
  }
  // Settling of the loop on the prior: steps from rest to the bottom speed, to the top speed and to
  // minus the bottom speed, lengthened until each settles.
  double step = 2.0, settle = 0;
  for (int attempt = 0; attempt < 3; ++attempt, step *= 4) {
    ExperimentProfile probe;
    probe.signal = staircase({0, step, 2 * step, 3 * step}, {bottom, top, -bottom, -bottom});
    probe.duration = 3 * step;
    probe.sample_rate = fs;
    const Trajectory tr = simulate_profile(probe, rig, rig.law);
    const double s1 = settling_time(tr, 0, step, bottom), s2 = settling_time(tr, step, 2 * step, top),
                 s3 = settling_time(tr, 2 * step, 3 * step, -bottom);
    settle = std::max({s1, s2, s3});
    if (settle < 0.5 * step) break;
    if (attempt == 2)
      p.warnings.push_back("the loop does not settle within " + num(step) + " s on the prior (stick-slip or hunting at " +
                           num(bottom) + " " + vu + "?): the sweep points may be biased");
  }
  settle = std::max(kSettleFactor * settle, 10.0 / fs);
  const double sF = force_noise(rig, noise);
  double avg = std::max(settle, std::pow(sF / (kSweepPrecision * Fc), 2) / fs);
  if (settle + avg < kMinSegment) avg = kMinSegment - settle;
  const double seg = settle + avg;
  std::vector<double> times{0.0}, values{0.0};
  double t = seg;  // rest first
  for (int dir : {1, -1})
    for (double v : speeds) {
      times.push_back(t);
      values.push_back(dir * v);
      p.windows.push_back({"speed", t + settle, t + seg, dir * v});
      t += seg;
    }
  times.push_back(t);
  values.push_back(0.0);
  p.signal = staircase(times, values);
  p.duration = t + seg;
  add(p, "speeds", n, "", "set points per direction, log-spaced below and above vs");
  add(p, "bottom_speed", bottom, vu, "slowest set point");
  add(p, "top_speed", top, vu, "fastest set point");
  add(p, "settle", settle, "s", "settling time per set point (1.5 x the loop's 2 % time on the prior)");
  add(p, "averaging", avg, "s", "averaging time per set point after settling");
  add(p, "segment", seg, "s", "duration of each set point");
  if (std::isfinite(vs)) add(p, "prior_vs", vs, vu, "the prior's Stribeck velocity");
  return p;
}

// ---- idim: trapezoidal velocity moves of the position reference ----

// Top speed v, acceleration a and distance d of idim's moves, within the limits; `Fc` the Coulomb
// level the moves must overcome (the prior's, raised by the largest load of a load-steps plan).
struct MoveLevels {
  double v = 0, a = 0, d = 0;
};

MoveLevels move_levels(const PlanRig& rig, const PlanLimits& lim, ExperimentProfile& p, double Fc) {
  const Axis ax = rig.axis;
  const std::string fu = u(Quantity::force, ax), vu = u(Quantity::velocity, ax), xu = u(Quantity::displacement, ax);
  const double Fv = std::isfinite(rig.prior("Fv")) ? rig.prior("Fv") : 0.0;
  const double M = rig.inertia;
  double v = 0;
  if (std::isfinite(lim.speed)) v = 0.9 * lim.speed;
  else if (Fv > 0) v = 2 * Fc / Fv;  // the viscous force twice the Coulomb level at the top speed
  else {
    v = 1.0;
    p.warnings.push_back("the prior has no viscous term and no --limits speed is given: top speed 1 " + vu);
  }
  double a = 2 * (Fc + Fv * v) / M;  // inertia force twice the friction: M as well excited as Fc, Fv
  const ForceLimit fl = force_limit(rig, lim);
  if (std::isfinite(fl.value)) {
    const double budget = 0.8 * fl.value;
    if (budget <= 1.5 * Fc)
      throw std::invalid_argument(fl.name + " leaves no force to accelerate: 0.8 of it must exceed 1.5 Fc = " +
                                  num(1.5 * Fc) + " " + fu);
    if (Fc + Fv * v + M * a > budget) {
      if (Fc + 2 * Fv * v > budget) v = (budget - Fc) / (2 * Fv);
      a = (budget - Fc - Fv * v) / M;
      p.warnings.push_back(fl.name + " lowers the top speed to " + num(v) + " " + vu + " and the acceleration to " + num(a));
    }
  }
  double d = std::isfinite(lim.travel) ? 0.9 * lim.travel : v * v / a + v * 1.0;
  if (d < v * v / a) {
    v = std::sqrt(d * a);
    p.warnings.push_back("--limits travel = " + num(lim.travel) + " " + xu + " makes the fastest move triangular: top speed " +
                         num(v) + " " + vu);
  }
  return {v, a, d};
}

// Piecewise position reference: moves out (from 0) and back (from d), trapezoidal in velocity.
struct Move {
  double t0, x0, dist, vmax;
};

double move_duration(double dist, double vm, double a) {
  return std::abs(dist) < vm * vm / a ? 2 * std::sqrt(std::abs(dist) / a) : std::abs(dist) / vm + vm / a;
}

// Appends a move out and one back at each speed in `speeds`, from time t, each followed by `rest`
// seconds; returns the time after them.
double add_moves(ExperimentProfile& p, std::vector<Move>& moves, double t, std::initializer_list<double> speeds,
                 double d, double a, double rest) {
  for (double vm : speeds) {
    for (double dir : {1.0, -1.0}) {
      const double dd = dir * d;
      moves.push_back({t, dir > 0 ? 0.0 : d, dd, vm});
      const double duration = move_duration(dd, vm, a);
      p.windows.push_back({"move", t, t + duration, dir * vm});
      t += duration + rest;
    }
  }
  return t;
}

// The position reference of `moves` (acceleration a) sampled at fs up to `total` seconds.
void sample_moves(ExperimentProfile& p, const std::vector<Move>& moves, double a, double total, double fs) {
  auto position = [&](double time) {
    double x = 0;
    for (const auto& m : moves) {
      if (time < m.t0) break;
      const double D = std::abs(m.dist), s = m.dist > 0 ? 1.0 : -1.0;
      const double vp = std::min(m.vmax, std::sqrt(D * a));
      const double ta = vp / a, tc = (D - vp * ta) / vp;
      const double tt = time - m.t0;
      double done = 0;
      if (tt < ta) done = 0.5 * a * tt * tt;
      else if (tt < ta + tc) done = 0.5 * vp * ta + vp * (tt - ta);
      else if (tt < 2 * ta + tc) {
        const double r = 2 * ta + tc - tt;
        done = D - 0.5 * a * r * r;
      } else done = D;
      x = m.x0 + s * done;
    }
    return x;
  };
  p.signal.shape = InputShape::table;
  const auto n = static_cast<std::size_t>(std::ceil(total * fs)) + 1;
  p.signal.times.resize(n);
  p.signal.values.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    p.signal.times[k] = static_cast<double>(k) / fs;
    p.signal.values[k] = position(p.signal.times[k]);
  }
  p.duration = p.signal.times.back();
}

constexpr double kMoveRest = 0.05;  // s: short, a standstill's friction is not the regressors' Fc sign(qd)
constexpr double kFirstMove = 0.5;  // s of rest before the first move (the loop settles)

ExperimentProfile design_idim(const PlanRig& rig, const PlanLimits& lim, const SensorNoise&, const PlanDesignOptions&,
                              double) {
  require_drive(rig, PlanMethod::idim, {PlanDrive::position_loop}, "a position loop (controller: {loop: position, ...})");
  ExperimentProfile p;
  const Axis ax = rig.axis;
  const std::string fu = u(Quantity::force, ax), vu = u(Quantity::velocity, ax), xu = u(Quantity::displacement, ax);
  const double Fc = need(rig, "Fc", "idim");
  const double Fv = std::isfinite(rig.prior("Fv")) ? rig.prior("Fv") : 0.0;
  const MoveLevels L = move_levels(rig, lim, p, Fc);
  std::vector<Move> moves;
  const double total = add_moves(p, moves, kFirstMove, {L.v, 0.5 * L.v, 0.25 * L.v}, L.d, L.a, kMoveRest);
  sample_moves(p, moves, L.a, total, rig.scenario.options.output_rate);
  add(p, "top_speed", L.v, vu, "speed of the fastest moves (then 1/2 and 1/4 of it)");
  add(p, "acceleration", L.a, u(Quantity::acceleration, ax), "acceleration of every move");
  add(p, "distance", L.d, xu, "length of each move out and back");
  add(p, "moves", static_cast<double>(moves.size()), "", "moves");
  add(p, "inertia_force", rig.inertia * L.a, fu, "M a, against Fc + Fv v = " + num(Fc + Fv * L.v) + " " + fu);
  return p;
}

// ---- load-steps: idim's moves at three loads ----
ExperimentProfile design_load_steps(const PlanRig& rig, const PlanLimits& lim, const PlanDesignOptions& o, double fs) {
  require_drive(rig, PlanMethod::load_steps, {PlanDrive::position_loop}, "a position loop (controller: {loop: position, ...})");
  const Axis ax = rig.axis;
  const std::string fu = u(Quantity::force, ax), vu = u(Quantity::velocity, ax), xu = u(Quantity::displacement, ax);
  if (!(o.load > 0 && std::isfinite(o.load)))
    throw std::invalid_argument("--load: a load-steps plan needs the largest load the rig applies, > 0 " + fu +
                                " (got " + num(o.load) + ")");
  ExperimentProfile p;
  const double Fc = need(rig, "Fc", "load-steps");
  const double mu = std::isfinite(rig.prior("mu_load")) ? rig.prior("mu_load") : 0.0;
  if (!rig.law.effects().load)
    p.warnings.push_back("the prior law has no load term (mu_load): the plan takes mu_load = 0 for its levels");
  const MoveLevels L = move_levels(rig, lim, p, Fc + mu * o.load);  // the largest load raises the level to overcome
  std::vector<Move> moves;
  std::vector<double> load_times, load_values;
  double t = kFirstMove;
  constexpr double kLoadRest = 0.5;  // s at rest after a load step: the loop settles before moving
  for (double f : {0.0, 0.5, 1.0}) {
    load_times.push_back(t == kFirstMove ? 0.0 : t - kLoadRest);
    load_values.push_back(f * o.load);
    const double begin = t;
    t = add_moves(p, moves, t, {L.v, 0.5 * L.v, 0.25 * L.v}, L.d, L.a, kMoveRest);
    p.windows.push_back({"load", begin, t, f * o.load});
    t += kLoadRest;
  }
  sample_moves(p, moves, L.a, t, fs);
  p.load = staircase(load_times, load_values);
  p.load_unit = fu;
  add(p, "top_speed", L.v, vu, "speed of the fastest moves (then 1/2 and 1/4 of it), at every load");
  add(p, "acceleration", L.a, u(Quantity::acceleration, ax), "acceleration of every move");
  add(p, "distance", L.d, xu, "length of each move out and back");
  add(p, "load_max", o.load, fu, "largest load; the moves run at 0, 1/2 and 1 of it");
  add(p, "load_rise", mu * o.load, fu, "mu_load Lmax: the prior's rise of the Coulomb level at the largest load");
  return p;
}

// ---- warm-up: moves at two speeds while the contact heats ----
ExperimentProfile design_warm_up(const PlanRig& rig, const PlanLimits& lim, const PlanDesignOptions& o, double fs) {
  require_drive(rig, PlanMethod::warm_up, {PlanDrive::position_loop}, "a position loop (controller: {loop: position, ...})");
  const auto& envs = rig.scenario.options.environments;
  if (envs.empty() || !envs[0].thermal)
    throw std::invalid_argument(rig.scenario_file + ": a warm-up plan needs the contact's thermal model: environment: "
                                "{thermal: {T_ambient, tau, R}} (its time constant sets the run's length)");
  const ThermalModel& th = *envs[0].thermal;
  const Axis ax = rig.axis;
  const std::string fu = u(Quantity::force, ax), vu = u(Quantity::velocity, ax), xu = u(Quantity::displacement, ax);
  if (!(o.warm_up >= 0 && std::isfinite(o.warm_up)))
    throw std::invalid_argument("--warm-up = " + num(o.warm_up) + " s must be > 0 (or 0: 2 thermal time constants)");
  ExperimentProfile p;
  const double Fc = need(rig, "Fc", "warm-up");
  if (!rig.law.effects().temperature)
    p.warnings.push_back("the prior law has no temperature term (Fv_per_K): the plan takes Fv_per_K = 0");
  const MoveLevels L = move_levels(rig, lim, p, Fc);
  const double length = o.warm_up > 0 ? o.warm_up : 2 * th.tau;
  // Every heat has both speeds: the temperature rises across the cycles, not with the speed
  // schedule, so Fv_per_K (qd (T - T_ref)) stays apart from Fv (qd) and Fc (sign(qd)).
  std::vector<Move> moves;
  double t = kFirstMove;
  while (t < length) t = add_moves(p, moves, t, {L.v, 0.5 * L.v}, L.d, L.a, kMoveRest);
  sample_moves(p, moves, L.a, t, fs);
  add(p, "top_speed", L.v, vu, "speed of the moves out and back (then 1/2 of it), in every cycle");
  add(p, "acceleration", L.a, u(Quantity::acceleration, ax), "acceleration of every move");
  add(p, "distance", L.d, xu, "length of each move out and back");
  add(p, "cycles", static_cast<double>(moves.size() / 4), "", "cycles of four moves");
  add(p, "thermal_tau", th.tau, "s", "the scenario's thermal time constant; the run lasts " + num(t / th.tau) + " of it");
  return p;
}

// ---- ripple-scan: slow moves over several ripple periods ----
ExperimentProfile design_ripple_scan(const PlanRig& rig, const PlanLimits& lim, const PlanDesignOptions& o, double fs) {
  require_drive(rig, PlanMethod::ripple_scan, {PlanDrive::position_loop}, "a position loop (controller: {loop: position, ...})");
  const auto& ripple = rig.law.effects().ripple;
  if (!ripple)
    throw std::invalid_argument(rig.prior_file + ": the prior law '" + rig.law.name() +
                                "' has no ripple (ripple_period, ripple_a, ripple_b); a ripple-scan plan needs its period");
  if (o.ripple_periods < 2 || o.ripple_periods > 10000)
    throw std::invalid_argument("--ripple-periods " + std::to_string(o.ripple_periods) + " must be in 2..10000 (periods per move)");
  const Axis ax = rig.axis;
  const std::string fu = u(Quantity::force, ax), vu = u(Quantity::velocity, ax), xu = u(Quantity::displacement, ax);
  ExperimentProfile p;
  const double Fc = need(rig, "Fc", "ripple-scan");
  const MoveLevels L = move_levels(rig, lim, p, Fc);
  const double P = ripple->period;
  const int K = static_cast<int>(std::max<std::size_t>(ripple->harmonics(), 1));
  const double d = o.ripple_periods * P;
  if (std::isfinite(lim.travel) && d > 0.9 * lim.travel)
    throw std::invalid_argument("--limits travel = " + num(lim.travel) + " " + xu + " is shorter than " +
                                std::to_string(o.ripple_periods) + " ripple periods of " + num(P) + " " + xu +
                                " (and 10 % margin): lower --ripple-periods or give more travel");
  // The ripple's top harmonic, K v / P Hz, a twentieth of idim's low-pass cut-off at most: the
  // filter passes it unchanged, and the ripple is quasi-static for the loop (at a fifth the cosine
  // terms came out 13 % off on the EMPS-like rig, at a twentieth 6 %).
  constexpr double kCutoffShare = 0.05;
  const double cutoff = idim_rate_defaults(fs).cutoff_hz;
  double v = std::min(L.v, kCutoffShare * cutoff * P / K);
  if (std::isfinite(lim.min_speed) && lim.min_speed > 0 && 0.5 * v < lim.min_speed)
    throw std::invalid_argument("--limits min_speed = " + num(lim.min_speed) + " " + vu + " is above the scan's slow speed " +
                                num(0.5 * v) + " " + vu + " (a twentieth of the low-pass cut-off " + num(cutoff) + " Hz times P / K)");
  std::vector<Move> moves;
  const double t = add_moves(p, moves, kFirstMove, {v, 0.5 * v}, d, L.a, kMoveRest);
  sample_moves(p, moves, L.a, t, fs);
  add(p, "scan_speed", v, vu, "speed of the scan (then 1/2 of it): the ripple's harmonic " + std::to_string(K) + " at " +
                                  num(K * v / P) + " Hz, idim's low-pass at " + num(cutoff) + " Hz");
  add(p, "acceleration", L.a, u(Quantity::acceleration, ax), "acceleration of every move");
  add(p, "distance", d, xu, std::to_string(o.ripple_periods) + " ripple periods of " + num(P) + " " + xu);
  add(p, "ripple_harmonics", K, "", "harmonics identified (the prior's)");
  // At rest stiction holds the ripple (the force is anything within the static level), and the
  // rests lie at the ends of whole periods: kept, they would bias the cosine terms.
  add(p, "exclude_below", 0.1 * 0.5 * v, vu, "identify with idim --exclude-below this: the rows at rest left out");
  (void)fu;
  return p;
}

// ---- lugre: presliding and sliding sines of force ----
ExperimentProfile design_lugre(const PlanRig& rig, const PlanLimits& lim, const SensorNoise&, const PlanDesignOptions& o,
                               double fs) {
  require_drive(rig, PlanMethod::lugre, {PlanDrive::force, PlanDrive::current},
                "an open-loop drive (an axis driven by force, or dc-motor with drive: current)");
  if (rig.law.name() != "lugre")
    throw std::invalid_argument(rig.prior_file + ": the prior law is '" + rig.law.name() +
                                "'; a lugre plan needs a LuGre prior (law: lugre) for its bristle stiffness");
  ExperimentProfile p;
  const Axis ax = rig.axis;
  const std::string fu = u(Quantity::force, ax), vu = u(Quantity::velocity, ax), xu = u(Quantity::displacement, ax);
  const double Fs = need(rig, "Fs", "lugre"), vs = need(rig, "vs", "lugre");
  const double k = rig.force_per_command;
  const ForceLimit fl = force_limit(rig, lim);
  double A = (o.margin > 0 ? o.margin : kDefaultLugreMargin) * Fs;
  if (A > kForceUse * fl.value) {
    if (kForceUse * fl.value < o.min_margin * Fs)
      throw std::invalid_argument(fl.name + " is below " + num(o.min_margin / kForceUse) + " Fs = " +
                                  num(o.min_margin * Fs / kForceUse / k) + " " + rig.command_unit +
                                  ": the sliding sine would not break the axis away with margin");
    A = kForceUse * fl.value;
    p.warnings.push_back(fl.name + " lowers the sliding amplitude to " + num(A / Fs) + " Fs");
  }
  const double Ap = 0.8 * Fs, fp = 1.0, pre_cycles = 2, slide_cycles = 5;
  const double t_slide = pre_cycles / fp;
  double w = kPi;  // rad/s: Canudas de Wit's 0.5 Hz
  auto build = [&](double omega) {
    InputSignal s;
    s.shape = InputShape::table;
    const double end = t_slide + slide_cycles * 2 * kPi / omega;
    // The table holds a sample every 1 / fs: its size is checked before it is built (--rate 1e9
    // once built 1.2e10 samples before the plan's own check of its runs).
    const double samples = std::ceil(end * fs) + 1;
    const std::string what = "the lugre profile of " + num(end) + " s at --rate " + num(fs) + " Hz (" + num(samples) + " samples)";
    const ErrorFields fields{.option = "--rate", .value = num(fs)};
    check_memory(samples * 2 * sizeof(double), what, fields);  // its times and values
    check_work(samples, "profile samples", what, fields);
    const auto n = static_cast<std::size_t>(samples);
    for (std::size_t i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) / fs;
      const double f = t < t_slide ? Ap * std::sin(2 * kPi * fp * t) : A * std::sin(omega * (t - t_slide));
      s.times.push_back(t);
      s.values.push_back(f / k);
    }
    return s;
  };
  std::string limiting;
  for (int attempt = 0; attempt < 6; ++attempt) {
    p.signal = build(w);
    p.duration = p.signal.times.back();
    p.sample_rate = fs;
    const Trajectory tr = simulate_profile(p, rig, rig.law);
    double xmax = 0, vmax = 0;
    for (std::size_t i = 0; i < tr.rows(); ++i) {
      xmax = std::max(xmax, std::abs(tr.position[i] - tr.position[0]));
      vmax = std::max(vmax, std::abs(tr.velocity[i]));
    }
    const double rx = xmax / (0.9 * lim.travel), rv = vmax / (0.9 * lim.speed);
    if (rx <= 1 && rv <= 1) {
      if (vmax < 10 * vs)
        throw std::invalid_argument(
            (limiting.empty() ? std::string("the force limits") : limiting) + " leave a sliding speed of " + num(vmax) +
            " " + vu + ", not above 10 vs = " + num(10 * vs) + " " + vu + ": the sliding sine would not show sliding");
      add(p, "presliding_amplitude", Ap / k, rig.command_unit, "amplitude of the presliding sine (0.8 Fs), " + num(fp) + " Hz");
      add(p, "sliding_amplitude", A / k, rig.command_unit, "amplitude of the sliding sine (" + num(A / Fs) + " Fs)");
      add(p, "sliding_frequency", w / (2 * kPi), "Hz", "frequency of the sliding sine");
      add(p, "peak_speed", vmax, vu, "peak speed on the prior, against vs = " + num(vs) + " " + vu);
      add(p, "excursion", xmax, xu, "largest |position - start| on the prior");
      p.windows.push_back({"presliding", 0, t_slide, Ap / k});
      p.windows.push_back({"sliding", t_slide, p.duration, A / k});
      return p;
    }
    // Displacement scales as 1 / w^2 and speed as 1 / w at a given force amplitude.
    const double factor = std::max(std::sqrt(rx), rv) * 1.1;
    limiting = rx >= rv ? "--limits travel = " + num(lim.travel) + " " + xu : "--limits speed = " + num(lim.speed) + " " + vu;
    w *= factor;
  }
  throw std::invalid_argument(limiting + " cannot be met by a sliding sine of " + num(A / Fs) + " Fs up to " +
                              num(w / (2 * kPi)) + " Hz");
}

}  // namespace

PlanMethod parse_plan_method(const std::string& name) {
  if (name == "breakaway") return PlanMethod::breakaway;
  if (name == "sweep") return PlanMethod::sweep;
  if (name == "idim") return PlanMethod::idim;
  if (name == "lugre") return PlanMethod::lugre;
  if (name == "load-steps") return PlanMethod::load_steps;
  if (name == "warm-up") return PlanMethod::warm_up;
  if (name == "ripple-scan") return PlanMethod::ripple_scan;
  throw std::invalid_argument("plan method '" + name +
                              "': expected one of breakaway, sweep, idim, lugre, load-steps, warm-up, ripple-scan");
}

const char* plan_method_name(PlanMethod method) {
  switch (method) {
    case PlanMethod::breakaway: return "breakaway";
    case PlanMethod::sweep: return "sweep";
    case PlanMethod::idim: return "idim";
    case PlanMethod::lugre: return "lugre";
    case PlanMethod::load_steps: return "load-steps";
    case PlanMethod::warm_up: return "warm-up";
    case PlanMethod::ripple_scan: return "ripple-scan";
  }
  return "breakaway";
}

void PlanDesignOptions::validate() const {
  if (!(margin == 0 || (std::isfinite(margin) && margin > min_margin)))
    throw std::invalid_argument("plan: margin = " + num(margin) + " must be > min_margin = " + num(min_margin) + " (or 0 for the default)");
  if (!(min_margin >= 1 && std::isfinite(min_margin)))
    throw std::invalid_argument("plan: min_margin = " + num(min_margin) + " must be >= 1 (a peak at least the breakaway level)");
  if (!(lag_fraction > 0 && lag_fraction < 1))
    throw std::invalid_argument("plan: lag_fraction = " + num(lag_fraction) + " must be in (0, 1)");
  if (speeds < 4 || speeds > 1000)
    throw std::invalid_argument("plan: speeds = " + std::to_string(speeds) + " must be in 4..1000 (per direction)");
  if (!(load >= 0 && std::isfinite(load)))
    throw std::invalid_argument("plan: load = " + num(load) + " must be >= 0 (N or N m; the largest load of load-steps)");
  if (!(warm_up >= 0 && std::isfinite(warm_up)))
    throw std::invalid_argument("plan: warm_up = " + num(warm_up) + " s must be >= 0 (0: 2 thermal time constants)");
  if (!(sample_rate >= 0 && std::isfinite(sample_rate)))
    throw std::invalid_argument("plan: sample_rate = " + num(sample_rate) + " Hz must be >= 0 (0: the scenario's)");
}

ExperimentProfile design_experiment(PlanMethod method, const PlanRig& rig, const PlanLimits& limits,
                                    const SensorNoise& noise, const PlanDesignOptions& options) {
  options.validate();
  limits.validate("--limits");
  noise.validate("--noise");
  if (rig.torque_constant == 0 && noise.current > 0)
    throw std::invalid_argument("--noise current = " + num(noise.current) + " A: the scenario's plant (" +
                                rig.scenario.plant->type() + ") has no motor current; use force=");
  const double fs = options.sample_rate > 0 ? options.sample_rate : rig.scenario.options.output_rate;
  PlanRig r = rig;
  r.scenario.options.output_rate = fs;
  ExperimentProfile p;
  switch (method) {
    case PlanMethod::breakaway: p = design_breakaway(r, limits, noise, options, fs); break;
    case PlanMethod::sweep: p = design_sweep(r, limits, noise, options, fs); break;
    case PlanMethod::idim: p = design_idim(r, limits, noise, options, fs); break;
    case PlanMethod::lugre: p = design_lugre(r, limits, noise, options, fs); break;
    case PlanMethod::load_steps: p = design_load_steps(r, limits, options, fs); break;
    case PlanMethod::warm_up: p = design_warm_up(r, limits, options, fs); break;
    case PlanMethod::ripple_scan: p = design_ripple_scan(r, limits, options, fs); break;
  }
  p.method = plan_method_name(method);
  p.command = rig.command;
  p.command_unit = rig.command_unit;
  p.sample_rate = fs;
  p.signal.validate("plan " + p.method + ": profile");
  if (p.load) p.load->validate("plan " + p.method + ": load");
  add(p, "duration", p.duration, "s", "length of the experiment");
  return p;
}

}  // namespace frictionlab
