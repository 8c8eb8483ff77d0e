#include "frictionlab/models/parameter.hpp"
#include "frictionlab/core/input.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace frictionlab {
namespace {


void require(bool ok, const std::string& where, const std::string& field, double value, const std::string& rule) {
  if (!ok) throw std::invalid_argument(where + "." + field + ": " + detail::format_value(value) + " must be " + rule);
}

// Corner times of a trapezoid: start, end of rise, end of hold, end of fall.
struct Corners {
  double t0, t1, t2, t3;
};
Corners corners(const InputSignal& s) {
  const double span = std::abs(s.level - s.initial);
  const double down = s.rate_down > 0 ? s.rate_down : s.rate;
  Corners c{};
  c.t0 = s.time;
  c.t1 = c.t0 + span / s.rate;
  c.t2 = c.t1 + s.hold;
  c.t3 = c.t2 + span / down;
  return c;
}

}  // namespace

std::string InputSignal::shape_name(InputShape shape) {
  switch (shape) {
    case InputShape::constant: return "constant";
    case InputShape::step: return "step";
    case InputShape::ramp: return "ramp";
    case InputShape::trapezoid: return "trapezoid";
    case InputShape::sine: return "sine";
    case InputShape::table: return "table";
  }
  return "?";
}

void InputSignal::validate(const std::string& where) const {
  auto finite = [&](const char* field, double v) { require(std::isfinite(v), where, field, v, "a finite number"); };
  finite("value", value);
  finite("initial", initial);
  finite("time", time);
  finite("rate", rate);
  switch (shape) {
    case InputShape::constant:
    case InputShape::step:
      break;
    case InputShape::ramp:
      if (has_limit) {
        finite("limit", limit);
        require(rate == 0.0 || (limit - initial) * rate >= 0, where, "limit", limit,
                "on the side the ramp moves to from initial = " + detail::format_value(initial) + " at rate " + detail::format_value(rate));
      }
      break;
    case InputShape::trapezoid:
      finite("level", level);
      require(rate > 0, where, "rate", rate, "> 0 (input unit per second)");
      require(std::isfinite(hold) && hold >= 0, where, "hold", hold, ">= 0 (s)");
      require(std::isfinite(rate_down) && rate_down >= 0, where, "rate_down", rate_down,
              "> 0 (input unit per second; omit it to use rate)");
      break;
    case InputShape::sine:
      finite("amplitude", amplitude);
      finite("offset", offset);
      finite("phase", phase);
      require(std::isfinite(omega) && omega > 0, where, "omega", omega, "> 0 (rad/s)");
      break;
    case InputShape::table:
      if (times.size() != values.size())
        throw std::invalid_argument(where + ": 'times' has " + std::to_string(times.size()) + " entries but 'values' has " +
                                    std::to_string(values.size()) + "; expected equal lengths");
      if (times.empty()) throw std::invalid_argument(where + ".times: empty; expected at least one (time, value) pair");
      for (std::size_t i = 0; i < times.size(); ++i) {
        require(std::isfinite(times[i]), where, "times[" + std::to_string(i) + "]", times[i], "a finite time (s)");
        require(std::isfinite(values[i]), where, "values[" + std::to_string(i) + "]", values[i], "a finite number");
        if (i > 0)
          require(times[i] > times[i - 1], where, "times[" + std::to_string(i) + "]", times[i],
                  "> times[" + std::to_string(i - 1) + "] = " + detail::format_value(times[i - 1]) + " (strictly increasing, s)");
      }
      break;
  }
}

InputValue InputSignal::at(double t) const {
  switch (shape) {
    case InputShape::constant:
      return {value, 0.0};
    case InputShape::step:
      return {t < time ? initial : value, 0.0};
    case InputShape::ramp: {
      if (t <= time) return {initial, 0.0};
      const double u = initial + rate * (t - time);
      if (has_limit && (rate > 0 ? u >= limit : u <= limit)) return {limit, 0.0};
      return {u, rate};
    }
    case InputShape::trapezoid: {
      const Corners c = corners(*this);
      const double dir = level >= initial ? 1.0 : -1.0;
      const double down = rate_down > 0 ? rate_down : rate;
      if (t <= c.t0 || t >= c.t3) return {initial, 0.0};
      if (t < c.t1) return {initial + dir * rate * (t - c.t0), dir * rate};
      if (t <= c.t2) return {level, 0.0};
      return {level - dir * down * (t - c.t2), -dir * down};
    }
    case InputShape::sine: {
      const double a = omega * t + phase;
      const double sa = std::sin(a);
      return {offset + amplitude * sa, amplitude * omega * std::cos(a), -amplitude * omega * omega * sa};
    }
    case InputShape::table: {
      if (t <= times.front()) return {values.front(), 0.0};
      if (t >= times.back()) return {values.back(), 0.0};
      // upper_bound: first time > t, so a value takes effect at its own time (from the right).
      const auto it = std::upper_bound(times.begin(), times.end(), t);
      const std::size_t k = static_cast<std::size_t>(it - times.begin()) - 1;
      if (hold_steps) return {values[k], 0.0};
      const double slope = (values[k + 1] - values[k]) / (times[k + 1] - times[k]);
      return {values[k] + slope * (t - times[k]), slope};
    }
  }
  return {};
}

std::vector<double> InputSignal::breakpoints(double t_begin, double t_end) const {
  std::vector<double> out;
  auto add = [&](double t) {
    if (t > t_begin && t < t_end) out.push_back(t);
  };
  switch (shape) {
    case InputShape::constant:
    case InputShape::sine:
      break;
    case InputShape::step:
      add(time);
      break;
    case InputShape::ramp:
      add(time);
      if (has_limit && rate != 0.0) add(time + (limit - initial) / rate);
      break;
    case InputShape::trapezoid: {
      const Corners c = corners(*this);
      add(c.t0);
      add(c.t1);
      add(c.t2);
      add(c.t3);
      break;
    }
    case InputShape::table:
      for (double t : times) add(t);
      break;
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

double InputSignal::max_step() const {
  if (shape == InputShape::sine && amplitude != 0.0) return 2.0 * std::numbers::pi / omega / 8.0;
  return 0.0;
}

}  // namespace frictionlab
