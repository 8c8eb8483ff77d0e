#include "frictionlab/simulate/trajectory.hpp"

#include <array>
#include <charconv>
#include <stdexcept>
#include <utility>

namespace frictionlab {

namespace {
// A contact's CSV columns, in CSV order, and their names; the 1-DOF CSV has the first eight.
constexpr std::array<std::vector<double> ContactColumns::*, 9> kContactColumns = {
    &ContactColumns::position, &ContactColumns::velocity,  &ContactColumns::friction,
    &ContactColumns::applied,  &ContactColumns::current,   &ContactColumns::voltage,
    &ContactColumns::reference, &ContactColumns::stuck,    &ContactColumns::drive};
constexpr std::array<const char*, 9> kContactNames = {"position", "velocity",  "friction", "applied", "current",
                                                      "voltage",  "reference", "stuck",    "drive"};
constexpr std::size_t kSingleColumns = 8;  // a 1-DOF CSV leaves out drive

// One unnamed contact: a 1-DOF plant's trajectory, with today's column names.
bool single(const Trajectory& t) { return t.contact_names.empty() || (t.contact_names.size() == 1 && t.contact_names[0].empty()); }
}  // namespace

const char* switch_kind_name(SwitchKind kind) {
  switch (kind) {
    case SwitchKind::breakaway: return "breakaway";
    case SwitchKind::stick: return "stick";
    case SwitchKind::reversal: return "reversal";
    case SwitchKind::impact: return "impact";
  }
  return "?";
}

const ContactColumns& Trajectory::contact(int i) const {
  if (i < 0 || i >= num_contacts())
    throw std::out_of_range("trajectory has no contact " + std::to_string(i) + "; it has " + std::to_string(num_contacts()));
  return i == 0 ? static_cast<const ContactColumns&>(*this) : others[static_cast<std::size_t>(i - 1)];
}

const std::vector<std::string>& Trajectory::column_names() {
  static const std::vector<std::string> names = {"time",    "position", "velocity",  "friction", "applied",
                                                 "current", "voltage",  "reference", "stuck"};
  return names;
}

std::vector<std::string> Trajectory::names() const {
  if (single(*this)) {
    std::vector<std::string> out = column_names();
    if (!load.empty()) out.push_back("load");
    if (!temperature.empty()) out.push_back("temperature");
    if (!motor_position.empty()) out.push_back("motor_position");
    return out;
  }
  std::vector<std::string> out{"time"};
  for (const auto& c : contact_names)
    for (const char* n : kContactNames) out.push_back(c + "." + n);
  return out;
}

const std::vector<double>& Trajectory::column(std::string_view name) const {
  if (name == "time") return time;
  if (single(*this)) {
    for (std::size_t k = 0; k < kContactColumns.size(); ++k)
      if (name == kContactNames[k]) return this->*kContactColumns[k];
    if (name == "load" && !load.empty()) return load;
    if (name == "temperature" && !temperature.empty()) return temperature;
    if (name == "motor_position" && !motor_position.empty()) return motor_position;
  } else {
    for (std::size_t c = 0; c < contact_names.size(); ++c) {
      const std::string& prefix = contact_names[c];
      if (name.size() <= prefix.size() + 1 || name.substr(0, prefix.size()) != prefix || name[prefix.size()] != '.') continue;
      const std::string_view rest = name.substr(prefix.size() + 1);
      for (std::size_t k = 0; k < kContactColumns.size(); ++k)
        if (rest == kContactNames[k]) return contact(static_cast<int>(c)).*kContactColumns[k];
    }
  }
  std::string list;
  for (const auto& n : names()) list += (list.empty() ? "" : ", ") + n;
  throw std::invalid_argument("trajectory has no column '" + std::string(name) + "'; columns: " + list);
}

std::string Trajectory::to_csv() const {
  const bool one = single(*this);
  const std::size_t per_contact = one ? kSingleColumns : kContactColumns.size();
  std::vector<const std::vector<double>*> cols{&time};
  for (int c = 0; c < num_contacts(); ++c)
    for (std::size_t k = 0; k < per_contact; ++k) cols.push_back(&(contact(c).*kContactColumns[k]));
  if (one) {
    if (!load.empty()) cols.push_back(&load);
    if (!temperature.empty()) cols.push_back(&temperature);
    if (!motor_position.empty()) cols.push_back(&motor_position);
  }
  const auto header = names();
  std::string out;
  out.reserve(rows() * cols.size() * 14 + 16 * cols.size());
  for (std::size_t c = 0; c < header.size(); ++c) {
    if (c) out += ',';
    out += header[c];
  }
  out += '\n';
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
