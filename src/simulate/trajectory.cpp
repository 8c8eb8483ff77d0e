#include "frictionlab/simulate/trajectory.hpp"

#include "column_pool.hpp"

#include <array>
#include <charconv>
#include <stdexcept>
#include <utility>

namespace frictionlab {

namespace {
// The nine columns, in the order of column_names() (the CSV's).
constexpr std::array<std::vector<double> Trajectory::*, 9> kColumns = {
    &Trajectory::time,    &Trajectory::position, &Trajectory::velocity,  &Trajectory::friction, &Trajectory::applied,
    &Trajectory::current, &Trajectory::voltage,  &Trajectory::reference, &Trajectory::stuck};
}  // namespace

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
  for (auto column : kColumns) swap(this->*column, other.*column);
  swap(drive, other.drive);
  swap(law_state, other.law_state);
  swap(switches, other.switches);
  swap(stats, other.stats);
}

Trajectory::~Trajectory() {
  for (auto column : kColumns) detail::recycle_column(std::move(this->*column));
  detail::recycle_column(std::move(drive), detail::Shelf::side);
  for (auto& c : law_state) detail::recycle_column(std::move(c));
}

const std::vector<std::string>& Trajectory::column_names() {
  static const std::vector<std::string> names = {"time",    "position", "velocity",  "friction", "applied",
                                                 "current", "voltage",  "reference", "stuck"};
  return names;
}

const std::vector<double>& Trajectory::column(std::string_view name) const {
  const auto& names = column_names();
  for (std::size_t c = 0; c < kColumns.size(); ++c)
    if (name == names[c]) return this->*kColumns[c];
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
  std::array<const std::vector<double>*, kColumns.size()> cols{};
  for (std::size_t c = 0; c < kColumns.size(); ++c) cols[c] = &(this->*kColumns[c]);
  char buf[32];
  for (std::size_t r = 0; r < rows(); ++r) {
    for (std::size_t c = 0; c < cols.size(); ++c) {
      if (c) out += ',';
      const auto res = std::to_chars(buf, buf + sizeof buf, (*cols[c])[r]);
      out.append(buf, res.ptr);
    }
    out += '\n';
  }
  return out;
}

}  // namespace frictionlab
