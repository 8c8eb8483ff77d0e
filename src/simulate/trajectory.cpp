#include "frictionlab/simulate/trajectory.hpp"

#include "column_pool.hpp"

#include <charconv>
#include <stdexcept>
#include <utility>

namespace frictionlab {

const char* switch_kind_name(SwitchKind kind) {
  switch (kind) {
    case SwitchKind::breakaway: return "breakaway";
    case SwitchKind::stick: return "stick";
    case SwitchKind::reversal: return "reversal";
  }
  return "?";
}

Trajectory& Trajectory::operator=(Trajectory&& other) noexcept {
  Trajectory taken(std::move(other));
  swap(taken);
  return *this;  // taken, now holding the old contents, recycles them
}

void Trajectory::swap(Trajectory& other) noexcept {
  using std::swap;
  swap(time, other.time);
  swap(position, other.position);
  swap(velocity, other.velocity);
  swap(friction, other.friction);
  swap(applied, other.applied);
  swap(current, other.current);
  swap(voltage, other.voltage);
  swap(reference, other.reference);
  swap(stuck, other.stuck);
  swap(law_state, other.law_state);
  swap(switches, other.switches);
  swap(stats, other.stats);
}

Trajectory::~Trajectory() {
  for (auto* c : {&time, &position, &velocity, &friction, &applied, &current, &voltage, &reference, &stuck})
    detail::recycle_column(std::move(*c));
  for (auto& c : law_state) detail::recycle_column(std::move(c));
}

const std::vector<std::string>& Trajectory::column_names() {
  static const std::vector<std::string> names = {"time",    "position", "velocity",  "friction", "applied",
                                                 "current", "voltage",  "reference", "stuck"};
  return names;
}

const std::vector<double>& Trajectory::column(std::string_view name) const {
  if (name == "time") return time;
  if (name == "position") return position;
  if (name == "velocity") return velocity;
  if (name == "friction") return friction;
  if (name == "applied") return applied;
  if (name == "current") return current;
  if (name == "voltage") return voltage;
  if (name == "reference") return reference;
  if (name == "stuck") return stuck;
  std::string list;
  for (const auto& n : column_names()) list += (list.empty() ? "" : ", ") + n;
  throw std::invalid_argument("trajectory has no column '" + std::string(name) + "'; columns: " + list);
}

std::string Trajectory::to_csv() const {
  const auto& names = column_names();
  std::string out;
  out.reserve(rows() * 9 * 14 + 128);
  for (std::size_t c = 0; c < names.size(); ++c) {
    if (c) out += ',';
    out += names[c];
  }
  out += '\n';
  const std::vector<double>* cols[] = {&time, &position, &velocity, &friction, &applied,
                                       &current, &voltage, &reference, &stuck};
  char buf[32];
  for (std::size_t r = 0; r < rows(); ++r) {
    for (std::size_t c = 0; c < 9; ++c) {
      if (c) out += ',';
      const auto res = std::to_chars(buf, buf + sizeof buf, (*cols[c])[r]);
      out.append(buf, res.ptr);
    }
    out += '\n';
  }
  return out;
}

}  // namespace frictionlab
