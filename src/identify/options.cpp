#include "frictionlab/identify/options.hpp"
#include "frictionlab/io/json_text.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace frictionlab {

namespace {

std::string number_text(double x) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, x);  // shortest text that reads back the same
  return std::string(buf, res.ptr);
}

// A variable's name as MATLAB and the CSV headers spell one: a letter or '_', then letters,
// digits and '_' (so that "1e3x" or "-5" is a bad number, not a name).
bool is_scalar_name(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  return std::all_of(s.begin(), s.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

std::string joined(const std::vector<std::string>& words, const char* last_sep) {
  std::string s;
  for (std::size_t i = 0; i < words.size(); ++i)
    s += (i == 0 ? "" : i + 1 == words.size() ? last_sep : ", ") + words[i];
  return s;
}

// "SPELLED 'TEXT': expected EXPECTED (UNIT)": a value that is not of the option's kind.
[[noreturn]] void bad_value(const OptionSpec& spec, const std::string& shown, const std::string& spelled) {
  const std::string unit = spec.unit_text();
  if (!spec.expected_text.empty()) throw std::invalid_argument(spelled + " " + shown + ": expected " + spec.expected_text);
  if (!spec.refusal.empty()) throw std::invalid_argument(spelled + " " + shown + " " + spec.refusal + "; expected " + spec.expected());
  throw std::invalid_argument(spelled + " " + shown + ": expected " + spec.expected() + (unit.empty() ? "" : " (" + unit + ")"));
}

// "SPELLED = VALUE must be RULE (UNIT)": a number out of the option's range.
[[noreturn]] void out_of_range(const OptionSpec& spec, double x, const std::string& spelled) {
  const std::string unit = spec.unit_text();
  throw std::invalid_argument(spelled + " = " + number_text(x) + " must be " + spec.rule(!std::isfinite(x)) +
                              (unit.empty() ? "" : " (" + unit + ")"));
}

bool in_range(const OptionSpec& s, double x) {
  if (!std::isfinite(x)) return false;
  if (s.min_open ? !(x > s.min) : !(x >= s.min)) return false;
  if (s.max_open ? !(x < s.max) : !(x <= s.max)) return false;
  return true;
}

}  // namespace

const char* to_string(OptionType type) {
  switch (type) {
    case OptionType::number: return "number";
    case OptionType::integer: return "integer";
    case OptionType::text: return "text";
    case OptionType::flag: return "flag";
    case OptionType::list: return "list";
    case OptionType::column: return "column";
    case OptionType::file: return "file";
  }
  return "?";
}

std::string OptionSpec::keyword() const {
  std::string k = name;
  std::replace(k.begin(), k.end(), '-', '_');
  static const char* kReserved[] = {"from", "import", "in", "is", "if", "for", "lambda", "global", "class", "def",
                                    "pass", "with", "as", "and", "or", "not", "del", "try", "return", "yield"};
  for (const char* w : kReserved)
    if (k == w) return k + "_";
  return k;
}

namespace {
// "A or B" of a linear and a rotary unit ("N/m or N m/rad"); the one when they are the same.
std::string both_axes(const std::string& unit, const std::string& rotary_unit) {
  if (rotary_unit.empty() || rotary_unit == unit) return unit;
  return unit + " or " + rotary_unit;
}
}  // namespace

std::string OptionSpec::unit_on(bool rotary) const {
  if (units.empty()) return rotary && !rotary_unit.empty() ? rotary_unit : unit;
  std::vector<std::string> seen;
  for (const OptionUnit& u : units) {
    const std::string& one = rotary && !u.rotary_unit.empty() ? u.rotary_unit : u.unit;
    if (std::find(seen.begin(), seen.end(), one) == seen.end()) seen.push_back(one);
  }
  return joined(seen, " or ");
}

std::string OptionSpec::unit_text() const {
  if (units.empty()) return both_axes(unit, rotary_unit);
  std::string s;
  for (const OptionUnit& u : units)
    s += (s.empty() ? "" : ", ") + both_axes(u.unit, u.rotary_unit) +
         (u.when.words.empty() ? "" : " with " + joined(u.when.words, " or "));
  return s;
}

std::string OptionSpec::rule(bool finite) const {
  auto bound = [](const char* op, double x) { return std::string(op) + " " + number_text(x); };
  std::string range;
  if (std::isfinite(min)) range += bound(min_open ? ">" : ">=", min);
  if (std::isfinite(max)) range += (range.empty() ? "" : " and ") + bound(max_open ? "<" : "<=", max);
  if (finite) return range.empty() ? "finite" : "finite and " + range;
  return range;
}

std::string OptionSpec::expected() const {
  if (!expected_text.empty()) return expected_text;
  const std::string r = rule(false);
  const std::string range = r.empty() ? "" : " " + r;
  switch (type) {
    case OptionType::number:
      return "a number" + range + (words.empty() ? "" : " or " + joined(words, " or ")) +
             (scalar_name ? " or the name of a scalar of the data file" : "");
    case OptionType::integer: return "an integer" + range;
    case OptionType::text: return words.empty() ? "a word" : joined(words, " or ");
    case OptionType::flag: return "true or false";
    case OptionType::list: return words.empty() ? "a list of words" : "a list of " + joined(words, ", ");
    case OptionType::column: return "a column name";
    case OptionType::file: return "a file name";
  }
  return "a value";
}

OptionValue check_option(const OptionSpec& spec, const OptionValue& value, const std::string& spelled) {
  const auto type_error = [&](const char* got) {
    throw std::invalid_argument(spelled + ": expected " + spec.expected() + ", got " + got);
  };
  switch (spec.type) {
    case OptionType::number: {
      double x;
      if (const auto* d = std::get_if<double>(&value)) x = *d;
      else if (const auto* i = std::get_if<long long>(&value)) x = static_cast<double>(*i);
      else if (const auto* s = std::get_if<std::string>(&value)) {
        if (std::find(spec.words.begin(), spec.words.end(), *s) != spec.words.end()) return *s;
        if (spec.scalar_name && is_scalar_name(*s)) return *s;  // resolved against the data file by the method
        bad_value(spec, "'" + *s + "'", spelled);
      } else {
        type_error(std::holds_alternative<bool>(value) ? "a flag" : "a list");
      }
      if (!in_range(spec, x)) out_of_range(spec, x, spelled);
      return x;
    }
    case OptionType::integer: {
      const auto* i = std::get_if<long long>(&value);
      if (!i) {
        const auto* d = std::get_if<double>(&value);
        if (!d) type_error(std::holds_alternative<bool>(value) ? "a flag" : "no number");
        if (!std::isfinite(*d)) out_of_range(spec, *d, spelled);
        if (std::nearbyint(*d) != *d || !(std::abs(*d) < 9e15)) bad_value(spec, number_text(*d), spelled);
        return check_option(spec, static_cast<long long>(*d), spelled);
      }
      if (!in_range(spec, static_cast<double>(*i))) out_of_range(spec, static_cast<double>(*i), spelled);
      return *i;
    }
    case OptionType::flag:
      if (!std::holds_alternative<bool>(value)) type_error("no flag");
      return value;
    case OptionType::text:
    case OptionType::column:
    case OptionType::file: {
      const auto* s = std::get_if<std::string>(&value);
      if (!s) type_error("no text");
      if (spec.type != OptionType::text && s->empty()) bad_value(spec, "''", spelled);
      if (!spec.words.empty() && std::find(spec.words.begin(), spec.words.end(), *s) == spec.words.end())
        bad_value(spec, "'" + *s + "'", spelled);
      return *s;
    }
    case OptionType::list: {
      std::vector<std::string> items;
      if (const auto* s = std::get_if<std::string>(&value)) items = {*s};
      else if (const auto* l = std::get_if<std::vector<std::string>>(&value)) items = *l;
      else type_error("no list");
      for (const auto& item : items)
        if (!spec.words.empty() && std::find(spec.words.begin(), spec.words.end(), item) == spec.words.end())
          bad_value(spec, "'" + item + "'", spelled);
      return items;
    }
  }
  return value;
}

OptionValue parse_option(const OptionSpec& spec, const std::string& text, const std::string& spelled) {
  switch (spec.type) {
    case OptionType::number: {
      if (std::find(spec.words.begin(), spec.words.end(), text) != spec.words.end()) return text;
      double x = 0;
      const auto res = std::from_chars(text.data(), text.data() + text.size(), x);
      if (res.ec != std::errc() || res.ptr != text.data() + text.size() || text.empty()) {
        if (spec.scalar_name && is_scalar_name(text)) return text;
        bad_value(spec, "'" + text + "'", spelled);
      }
      return check_option(spec, x, spelled);
    }
    case OptionType::integer: {
      long long x = 0;
      const auto res = std::from_chars(text.data(), text.data() + text.size(), x);
      if (res.ec != std::errc() || res.ptr != text.data() + text.size() || text.empty())
        bad_value(spec, "'" + text + "'", spelled);
      return check_option(spec, x, spelled);
    }
    case OptionType::flag:
      if (text == "true" || text == "on" || text == "1") return true;
      if (text == "false" || text == "off" || text == "0") return false;
      bad_value(spec, "'" + text + "'", spelled);
    case OptionType::list: {
      std::vector<std::string> items;
      std::size_t start = 0;
      while (start <= text.size()) {
        const std::size_t end = std::min(text.find(',', start), text.size());
        if (end > start) items.push_back(text.substr(start, end - start));
        start = end + 1;
      }
      return check_option(spec, items, spelled);
    }
    default: return check_option(spec, text, spelled);
  }
}

std::string option_text(const OptionValue& value) {
  if (const auto* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
  if (const auto* i = std::get_if<long long>(&value)) return std::to_string(*i);
  if (const auto* d = std::get_if<double>(&value)) return number_text(*d);
  if (const auto* s = std::get_if<std::string>(&value)) return *s;
  std::string list;  // "a,b" as the command line takes it (joined() would give "a, b,c")
  for (const auto& item : std::get<std::vector<std::string>>(value)) list += (list.empty() ? "" : ",") + item;
  return list;
}

const std::vector<OptionSpec>& OptionValues::table() const {
  static const std::vector<OptionSpec> none;
  return table_ ? *table_ : none;
}

const OptionSpec& OptionValues::spec(const std::string& name) const {
  for (const auto& s : table())
    if (s.name == name) return s;
  std::vector<std::string> names;
  for (const auto& s : table()) names.push_back(s.name);
  throw std::invalid_argument("option '" + name + "' is not known; expected one of " + joined(names, ", "));
}

void OptionValues::set(const std::string& name, const OptionValue& value, const std::string& spelled) {
  const OptionSpec& s = spec(name);
  if (s.type == OptionType::list && s.repeatable && given(name)) {  // repeated: one item each time
    auto items = std::get<std::vector<std::string>>(given_[name]);
    const OptionValue more = check_option(s, value, spelled);  // kept: the loop reads inside it
    for (const auto& item : std::get<std::vector<std::string>>(more)) items.push_back(item);
    given_[name] = items;
    return;
  }
  given_[name] = check_option(s, value, spelled);
}

std::optional<OptionValue> OptionValues::get(const std::string& name) const {
  const OptionSpec& s = spec(name);
  if (const auto it = given_.find(name); it != given_.end()) return it->second;
  return s.default_value;
}

double OptionValues::number(const std::string& name) const {
  const auto v = get(name);
  if (!v) return std::numeric_limits<double>::quiet_NaN();
  if (const auto* d = std::get_if<double>(&*v)) return *d;
  if (const auto* i = std::get_if<long long>(&*v)) return static_cast<double>(*i);
  return std::numeric_limits<double>::quiet_NaN();  // a word (the caller asks text() for it)
}

long long OptionValues::integer(const std::string& name) const {
  const auto v = get(name);
  if (!v) throw std::invalid_argument("option '" + name + "' has no value and no default");
  if (const auto* i = std::get_if<long long>(&*v)) return *i;
  return static_cast<long long>(std::get<double>(*v));
}

bool OptionValues::flag(const std::string& name) const {
  const auto v = get(name);
  return v && std::get<bool>(*v);
}

std::string OptionValues::text(const std::string& name) const {
  const auto v = get(name);
  return v ? option_text(*v) : std::string();
}

std::vector<std::string> OptionValues::list(const std::string& name) const {
  const auto v = get(name);
  if (!v) return {};
  if (const auto* l = std::get_if<std::vector<std::string>>(&*v)) return *l;
  return {option_text(*v)};
}

bool OptionValues::holds(const OptionCondition& c, const std::map<std::string, std::string>& texts) const {
  const OptionSpec& other = spec(c.option);
  bool met = false;
  if (c.words.empty()) {
    met = other.type == OptionType::flag ? flag(c.option) : given(c.option);
  } else {
    std::vector<std::string> items = list(c.option);  // a text is a list of one
    // Not given, no default: the value the run took, when the result records it.
    if (!get(c.option) && !other.taken_text.empty())
      if (const auto it = texts.find(other.taken_text); it != texts.end()) items = {it->second};
    for (const std::string& item : items)
      if (std::find(c.words.begin(), c.words.end(), item) != c.words.end()) met = true;
  }
  return met != c.negated;
}

bool OptionValues::applies(const std::string& name) const {
  for (const OptionCondition& c : spec(name).applies_if)
    if (!holds(c, {})) return false;
  return true;
}

std::string OptionValues::unit(const std::string& name, bool rotary, const std::map<std::string, std::string>& texts) const {
  const OptionSpec& s = spec(name);
  for (const OptionUnit& u : s.units)
    if (holds(u.when, texts)) return rotary && !u.rotary_unit.empty() ? u.rotary_unit : u.unit;
  return s.unit_on(rotary);
}

std::string options_json(const OptionValues& values, bool rotary, const std::map<std::string, std::string>& texts) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const auto& s : values.table()) {
    nlohmann::ordered_json o;
    const auto v = values.get(s.name);
    if (!v) o["value"] = nullptr;
    else if (const auto* b = std::get_if<bool>(&*v)) o["value"] = *b;
    else if (const auto* i = std::get_if<long long>(&*v)) o["value"] = *i;
    else if (const auto* d = std::get_if<double>(&*v)) o["value"] = std::isfinite(*d) ? nlohmann::ordered_json(*d) : nullptr;
    else if (const auto* t = std::get_if<std::string>(&*v)) o["value"] = *t;
    else o["value"] = std::get<std::vector<std::string>>(*v);
    o["unit"] = values.unit(s.name, rotary, texts);
    o["given"] = values.given(s.name);
    j[s.name] = o;
  }
  return json_text(j);  // option values may hold bytes that are not UTF-8 (file names)
}

}  // namespace frictionlab
