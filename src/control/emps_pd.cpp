// The EMPS discrete PD controller: see include/frictionlab/control/emps_pd.hpp.
#include "frictionlab/control/emps_pd.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "frictionlab/models/parameter.hpp"

namespace frictionlab {
namespace {

constexpr const char* kWho = "controller (emps-pd)";

void require(bool ok, const char* name, double value, const char* rule) { detail::require(ok, kWho, name, value, rule); }

}  // namespace

void EmpsPdParams::validate() const {
  require(std::isfinite(kp) && kp >= 0, "kp", kp, ">= 0 (1/s)");
  require(std::isfinite(kv) && kv >= 0, "kv", kv, ">= 0 (V/(m/s))");
  require(std::isfinite(gtau) && gtau > 0, "gtau", gtau, "> 0 (N/V)");
  require(std::isfinite(limit) && limit > 0, "limit", limit, "> 0 (V)");
  require(std::isfinite(dt) && dt > 0, "dt", dt, "> 0 (s)");
  require(delay == 0 || delay == 1, "delay", delay, "0 or 1 (samples)");
  pulses.validate("controller (emps-pd): pulses");
}

EmpsPd::EmpsPd(EmpsPdParams p) : p_(std::move(p)) { p_.validate(); }

EmpsPdMeasurement EmpsPd::measure(std::span<double> s, double q, double r) const {
  using S = EmpsPdState;
  EmpsPdMeasurement m;
  m.first = s[S::primed] == 0.0;
  if (m.first) {  // first sample: the memory starts at rest at the current position and reference
    s[S::prev_q] = q;
    s[S::prev_qf] = q;
    s[S::prev_r] = r;
    s[S::primed] = 1.0;
  }
  m.filtered = 0.5 * q + 0.5 * s[S::prev_q];
  m.velocity = (m.filtered - s[S::prev_qf]) / p_.dt;
  m.reference_rate = (r - s[S::prev_r]) / p_.dt;
  return m;
}

double EmpsPd::sample(std::span<double> s, double t, double q, double r, const EmpsPdMeasurement& m,
                      double compensation) const {
  using S = EmpsPdState;
  const double v = std::clamp(p_.kp * p_.kv * (r - q) - p_.kv * m.velocity + compensation, -p_.limit, p_.limit) +
                   p_.pulses.at(t).value;
  // delay 1: the output computed at the previous sample goes to the drive now.
  s[S::applied] = p_.delay == 1 ? s[S::computed] : v;
  s[S::computed] = v;
  s[S::prev_q] = q;
  s[S::prev_qf] = m.filtered;
  s[S::prev_r] = r;
  return v;
}

}  // namespace frictionlab
