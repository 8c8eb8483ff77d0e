#include "frictionlab/models/parameter.hpp"
#include "frictionlab/io/scenario.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <initializer_list>
#include <numbers>
#include <set>
#include <sstream>
#include <stdexcept>

#include "frictionlab/io/columns.hpp"
#include "frictionlab/io/law_file.hpp"
#include "frictionlab/io/load.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/plants/closed_loop.hpp"
#include "frictionlab/plants/dc_motor.hpp"
#include "frictionlab/plants/emps_pd.hpp"
#include "frictionlab/plants/pendulum.hpp"
#include "frictionlab/plants/spring_base.hpp"
#include "frictionlab/plants/velocity_drive.hpp"
#include "frictionlab/simulate/simulate.hpp"
#include "frictionlab/simulate/output_size.hpp"
#include "yaml_keys.hpp"

namespace frictionlab {
namespace {

std::string join(std::initializer_list<const char*> names) {
  std::string out;
  for (const char* n : names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}


// A YAML mapping being read: knows its path for messages, the keys allowed, and reads values.
class Section {
 public:
  Section(const YAML::Node& node, std::string path) : node_(node), path_(std::move(path)) {
    if (!node_.IsMap()) throw std::invalid_argument(path_ + ": expected a mapping of keys to values");
  }

  const std::string& path() const { return path_; }
  std::string at(const std::string& key) const { return path_ + "." + key; }

  // Rejects keys outside `allowed`, naming the key and listing the valid ones.
  void allow(std::initializer_list<const char*> allowed) const {
    std::set<std::string> ok;
    for (const char* a : allowed) ok.insert(a);
    for (const auto& kv : node_) {
      if (!kv.first.IsScalar())  // yaml-cpp would throw its own bad conversion
        throw std::invalid_argument(path_ + ": line " + std::to_string(kv.first.Mark().line + 1) +
                                    ": expected a field name as key, got a list, mapping or empty key; valid fields: " + join(allowed));
      const std::string key = kv.first.as<std::string>();
      if (!ok.count(key))
        throw std::invalid_argument(at(key) + ": unknown field '" + key + "'; valid fields: " + join(allowed));
    }
  }

  bool has(const std::string& key) const { return static_cast<bool>(node_[key]); }
  YAML::Node node(const std::string& key) const { return node_[key]; }

  double number(const std::string& key) const {
    const YAML::Node v = node_[key];
    if (!v) throw std::invalid_argument(path_ + ": missing '" + key + "' (a number)");
    return to_number(v, at(key));
  }
  double number(const std::string& key, double fallback) const { return has(key) ? number(key) : fallback; }

  std::string text(const std::string& key, const std::string& fallback) const {
    const YAML::Node v = node_[key];
    if (!v) return fallback;
    if (!v.IsScalar()) throw std::invalid_argument(at(key) + ": expected a name");
    return v.as<std::string>();
  }

  std::vector<double> numbers(const std::string& key) const {
    const YAML::Node v = node_[key];
    if (!v) throw std::invalid_argument(path_ + ": missing '" + key + "' (a list of numbers)");
    if (!v.IsSequence()) throw std::invalid_argument(at(key) + ": expected a list of numbers, e.g. [0, 1, 2]");
    std::vector<double> out;
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(to_number(v[i], at(key) + "[" + std::to_string(i) + "]"));
    return out;
  }

  static double to_number(const YAML::Node& v, const std::string& where) {
    if (!v.IsScalar()) throw std::invalid_argument(where + ": expected a number");
    const std::string s = v.as<std::string>();
    try {
      return v.as<double>();
    } catch (const YAML::Exception&) {
      throw std::invalid_argument(where + ": expected a number, got '" + s + "'");
    }
  }

 private:
  YAML::Node node_;
  std::string path_;
};

// Wraps a constructor's own message ("axis: M = 0 must be > 0") with the file and key path.
template <class F>
auto with_context(const std::string& where, F&& make) {
  try {
    return make();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(where + ": " + e.what());
  }
}

// A name chosen from a fixed list: `key` of `s` (or `fallback` when absent) looked up in
// `choices`; an unknown one is refused naming the key, the value and the valid names in the
// table's order ("FILE: solver.mode: unknown solver mode 'x'; valid modes: auto, hybrid, ...").
template <class T, std::size_t N>
T choose(const Section& s, const std::string& key, const std::string& fallback, const std::pair<const char*, T> (&choices)[N],
         const std::string& what, const std::string& plural) {
  const std::string name = s.text(key, fallback);
  for (const auto& [n, value] : choices)
    if (name == n) return value;
  std::string valid;
  for (const auto& c : choices) valid += (valid.empty() ? "" : ", ") + std::string(c.first);
  throw std::invalid_argument(s.at(key) + ": unknown " + what + " '" + name + "'; valid" + (plural.empty() ? "" : " " + plural) +
                              ": " + valid);
}

// The names of a reader table, in order, for messages.
template <class Entry, std::size_t N>
std::string names_of(const Entry (&table)[N]) {
  std::string out;
  for (const auto& e : table) out += (out.empty() ? "" : ", ") + std::string(e.first);
  return out;
}

// Where data come from while one scenario is read: the caller's data set, or files by name
// (each read once), resolved from the scenario's directory.
class DataSource {
 public:
  DataSource(const ScenarioOptions& o, std::string default_file) : o_(o), default_file_(std::move(default_file)) {}

  // The data set of a section: options.data, else the section's `file`, else the top-level one.
  // Null when there is none (the caller decides whether that is an error).
  std::shared_ptr<const Dataset> get(const std::string& file = "") {
    if (o_.data) return o_.data;
    const std::string name = file.empty() ? default_file_ : file;
    if (name.empty()) return nullptr;
    std::filesystem::path path(name);
    if (path.is_relative() && !o_.base_dir.empty()) path = std::filesystem::path(o_.base_dir) / path;
    auto& slot = cache_[path.string()];
    if (!slot) slot = std::make_shared<const Dataset>(load_dataset(path.string()));
    return slot;
  }

  // A number, or the name of a scalar of the data set (resolve_constant).
  double constant(const Section& s, const std::string& key, const std::shared_ptr<const Dataset>& d) {
    const YAML::Node v = s.node(key);
    if (!v) throw std::invalid_argument(s.path() + ": missing '" + key + "' (a number or a scalar of the data file)");
    if (!v.IsScalar()) throw std::invalid_argument(s.at(key) + ": expected a number or the name of a scalar of the data file");
    try {
      return v.as<double>();
    } catch (const YAML::Exception&) {
    }
    const std::string name = v.as<std::string>();
    if (!d)
      throw std::invalid_argument(s.at(key) + ": '" + name +
                                  "' is not a number, and the scenario names no data file to read a scalar from (top-level 'data')");
    return with_context(s.at(key), [&] { return resolve_constant(*d, name, key); });
  }

  std::optional<double> data_step;  // s: step of the data input's grid, when there is one
  std::string time_column;          // the data input's time column

 private:
  const ScenarioOptions& o_;
  std::string default_file_;
  std::map<std::string, std::shared_ptr<const Dataset>> cache_;
};

// Plant readers, one per plant type: each lists its keys, reads the required ones and takes
// every optional one's default from the parameter struct.
using PlantPtr = std::shared_ptr<const Plant>;

PlantPtr read_axis(const Section& s) {
  s.allow({"type", "M", "offset"});
  AxisParams p;
  p.M = s.number("M");
  p.offset = s.number("offset", p.offset);
  return with_context(s.path(), [&] { return std::make_shared<const RigidAxis>(p); });
}

PlantPtr read_pendulum(const Section& s) {
  s.allow({"type", "m", "l", "g", "B"});
  PendulumParams p;
  p.m = s.number("m");
  p.l = s.number("l");
  p.g = s.number("g", p.g);
  p.B = s.number("B", p.B);
  return with_context(s.path(), [&] { return std::make_shared<const Pendulum>(p); });
}

PlantPtr read_spring_base(const Section& s) {
  s.allow({"type", "m", "k", "c", "V0", "x0"});
  SpringBaseParams p;
  p.m = s.number("m");
  p.k = s.number("k");
  p.V0 = s.number("V0");
  p.c = s.number("c", p.c);
  p.x0 = s.number("x0", p.x0);
  return with_context(s.path(), [&] { return std::make_shared<const SpringBase>(p); });
}

PlantPtr read_dc_motor(const Section& s) {
  s.allow({"type", "J", "R", "L", "Kt", "Kb", "Ka", "load", "drive"});
  static constexpr std::pair<const char*, MotorDrive> kDrives[] = {{"voltage", MotorDrive::voltage}, {"current", MotorDrive::current}};
  DcMotorParams p;
  p.drive = choose(s, "drive", "voltage", kDrives, "drive", "drives");
  p.J = s.number("J");
  p.R = s.number("R");
  p.Kt = s.number("Kt");
  p.Kb = s.number("Kb");
  p.L = p.drive == MotorDrive::voltage ? s.number("L") : s.number("L", p.L);  // a current drive hides L
  p.Ka = s.number("Ka", p.Ka);
  p.load = s.number("load", p.load);
  return with_context(s.path(), [&] { return std::make_shared<const DcMotor>(p); });
}

PlantPtr read_velocity_drive(const Section& s) {
  s.allow({"type", "M"});
  VelocityDriveParams p;
  p.M = s.number("M", p.M);
  return with_context(s.path(), [&] { return std::make_shared<const VelocityDrive>(p); });
}

constexpr std::pair<const char*, PlantPtr (*)(const Section&)> kPlantReaders[] = {
    {"axis", read_axis},
    {"pendulum", read_pendulum},
    {"spring-base", read_spring_base},
    {"dc-motor", read_dc_motor},
    {"velocity-drive", read_velocity_drive},
};

PlantPtr read_plant(const Section& s, const ScenarioOptions& o) {
  if (o.axis) {
    const std::string type = s.text("type", "axis");
    if (type != "axis")
      throw std::invalid_argument(s.at("type") + ": plant type '" + type +
                                  "' cannot take an identified inertia and offset; expected axis");
    s.allow({"type", "M", "offset"});
    // M and offset come from the identified model: a bad value is the model file's.
    const std::string source = o.model_source.empty() ? s.path() : o.model_source + ": parameters";
    return with_context(source, [&] { return std::make_shared<const RigidAxis>(*o.axis); });
  }
  const std::string type = s.text("type", "");
  if (type.empty())
    throw std::invalid_argument(s.path() + ": missing 'type'; valid plant types: " + names_of(kPlantReaders));
  return choose(s, "type", "", kPlantReaders, "plant type", "plant types")(s);
}

bool read_interpolation(const Section& s) {
  static constexpr std::pair<const char*, bool> kHold[] = {{"linear", false}, {"hold", true}};
  return choose(s, "interpolation", "linear", kHold, "interpolation", "");
}

// Input readers, one per input type, as the plant readers: optional keys default to the
// InputSignal's own fields. Each but `data` leaves the checks of the whole signal to read_input.
InputSignal read_data_input(const Section& s, DataSource& src) {
  s.allow({"type", "file", "column", "time", "scale", "interpolation"});
  const std::string column = s.text("column", "");
  if (column.empty()) throw std::invalid_argument(s.path() + ": missing 'column' (the column of the data file to read)");
  const auto d = src.get(s.text("file", ""));
  if (!d) throw std::invalid_argument(s.path() + ": no data file: give 'file' here or a top-level 'data'");
  const double scale = s.number("scale", 1.0);
  if (!std::isfinite(scale)) throw std::invalid_argument(s.at("scale") + ": " + detail::format_value(scale) + " must be a finite number");
  InputSignal in = with_context(s.path(), [&] { return input_from_column(*d, s.text("time", "time"), column, scale, read_interpolation(s)); });
  src.data_step = in.times.size() > 1 ? in.times[1] - in.times[0] : 0.0;
  src.time_column = s.text("time", "time");
  return in;
}

InputSignal read_constant(const Section& s, DataSource&) {
  s.allow({"type", "value"});
  InputSignal in;
  in.shape = InputShape::constant;
  in.value = s.number("value");
  return in;
}

InputSignal read_step(const Section& s, DataSource&) {
  s.allow({"type", "value", "initial", "time"});
  InputSignal in;
  in.shape = InputShape::step;
  in.value = s.number("value");
  in.initial = s.number("initial", in.initial);
  in.time = s.number("time", in.time);
  return in;
}

InputSignal read_ramp(const Section& s, DataSource&) {
  s.allow({"type", "rate", "initial", "time", "limit"});
  InputSignal in;
  in.shape = InputShape::ramp;
  in.rate = s.number("rate");
  in.initial = s.number("initial", in.initial);
  in.time = s.number("time", in.time);
  if (s.has("limit")) {
    in.has_limit = true;
    in.limit = s.number("limit");
  }
  return in;
}

InputSignal read_trapezoid(const Section& s, DataSource&) {
  s.allow({"type", "level", "rate", "hold", "rate_down", "initial", "time"});
  InputSignal in;
  in.shape = InputShape::trapezoid;
  in.level = s.number("level");
  in.rate = s.number("rate");
  in.hold = s.number("hold", in.hold);
  in.rate_down = s.number("rate_down", in.rate_down);
  in.initial = s.number("initial", in.initial);
  in.time = s.number("time", in.time);
  return in;
}

InputSignal read_sine(const Section& s, DataSource&) {
  s.allow({"type", "amplitude", "omega", "frequency", "phase", "offset"});
  InputSignal in;
  in.shape = InputShape::sine;
  in.amplitude = s.number("amplitude");
  if (s.has("omega") && s.has("frequency"))
    throw std::invalid_argument(s.path() + ": give either 'omega' (rad/s) or 'frequency' (Hz), not both");
  if (s.has("frequency")) {
    const double f = s.number("frequency");
    if (!(f > 0)) throw std::invalid_argument(s.at("frequency") + ": " + detail::format_value(f) + " must be > 0 (Hz)");
    in.omega = 2.0 * std::numbers::pi * f;
  } else {
    in.omega = s.number("omega");
  }
  in.phase = s.number("phase", in.phase);
  in.offset = s.number("offset", in.offset);
  return in;
}

InputSignal read_table(const Section& s, DataSource&) {
  s.allow({"type", "times", "values", "interpolation"});
  InputSignal in;
  in.shape = InputShape::table;
  in.times = s.numbers("times");
  in.values = s.numbers("values");
  in.hold_steps = read_interpolation(s);
  return in;
}

struct InputReader {
  InputSignal (*read)(const Section&, DataSource&);
  bool checked = false;  // the reader checks the signal itself (a data column)
};

constexpr std::pair<const char*, InputReader> kInputReaders[] = {
    {"constant", {read_constant}}, {"step", {read_step}}, {"ramp", {read_ramp}},           {"trapezoid", {read_trapezoid}},
    {"sine", {read_sine}},         {"table", {read_table}}, {"data", {read_data_input, true}},
};

InputSignal read_input(const Section& s, DataSource& src) {
  const std::string type = s.text("type", "");
  if (type.empty()) throw std::invalid_argument(s.path() + ": missing 'type'; valid input types: " + names_of(kInputReaders));
  const InputReader r = choose(s, "type", "", kInputReaders, "input type", "input types");
  InputSignal in = r.read(s, src);
  if (!r.checked) in.validate(s.path());
  return in;
}

EmpsPdParams read_emps_pd(const Section& s, DataSource& src) {
  s.allow({"type", "kp", "kv", "gtau", "limit", "dt", "delay", "pulses"});
  const auto d = src.get();
  EmpsPdParams p;
  p.kp = src.constant(s, "kp", d);
  p.kv = src.constant(s, "kv", d);
  p.gtau = src.constant(s, "gtau", d);
  p.limit = s.number("limit", p.limit);
  if (s.has("dt")) {
    p.dt = s.number("dt");
  } else if (src.data_step && *src.data_step > 0) {
    p.dt = *src.data_step;
  } else {
    throw std::invalid_argument(s.path() + ": missing 'dt' (sample period, s); without it the controller takes the step of a data input");
  }
  const double delay = s.number("delay", p.delay);
  if (delay != 0.0 && delay != 1.0) throw std::invalid_argument(s.at("delay") + ": " + detail::format_value(delay) + " must be 0 or 1 (samples)");
  p.delay = static_cast<int>(delay);
  if (s.has("pulses")) {
    std::string column;
    double scale = 1.0;
    bool optional = false;
    const YAML::Node node = s.node("pulses");
    if (node.IsScalar()) {
      column = node.as<std::string>();
    } else {
      const Section ps(node, s.at("pulses"));
      ps.allow({"column", "scale", "optional"});
      column = ps.text("column", "");
      if (column.empty()) throw std::invalid_argument(ps.path() + ": missing 'column' (pulses in V)");
      scale = ps.number("scale", 1.0);
      const std::string opt = ps.text("optional", "false");
      if (opt != "true" && opt != "false") throw std::invalid_argument(ps.at("optional") + ": expected true or false, got '" + opt + "'");
      optional = opt == "true";
    }
    if (!d) throw std::invalid_argument(s.at("pulses") + ": the scenario names no data file to read column '" + column + "' from");
    if (d->has_column(column)) {
      const std::string time = src.time_column.empty() ? "time" : src.time_column;
      p.pulses = with_context(s.at("pulses"), [&] { return input_from_column(*d, time, column, scale, true); });
    } else if (!optional) {
      throw std::invalid_argument(s.at("pulses") + ": " + d->where() + "no column '" + column +
                                  "'; the file has columns: " + d->describe_contents() + " (set optional: true to run without pulses)");
    }
  }
  return p;
}

ControllerParams read_controller(const Section& s) {
  s.allow({"type", "loop", "Kp", "Ki", "Kd", "limit"});
  ControllerParams c;
  static constexpr std::pair<const char*, ControlLoop> kLoops[] = {{"position", ControlLoop::position}, {"velocity", ControlLoop::velocity}};
  c.loop = choose(s, "loop", "position", kLoops, "loop", "loops");
  c.Kp = s.number("Kp", c.Kp);
  c.Ki = s.number("Ki", c.Ki);
  c.Kd = s.number("Kd", c.Kd);
  c.limit = s.number("limit", c.limit);
  return c;
}

// Controller readers, one per controller type: each closes the loop around `plant`.
PlantPtr close_pid(const Section& s, DataSource&, const PlantPtr& plant) {
  const ControllerParams c = read_controller(s);
  return with_context(s.path(), [&] { return std::make_shared<const ClosedLoop>(plant, c); });
}

PlantPtr close_emps_pd(const Section& s, DataSource& src, const PlantPtr& plant) {
  const EmpsPdParams p = read_emps_pd(s, src);
  return with_context(s.path(), [&] { return std::make_shared<const EmpsPdLoop>(plant, p); });
}

constexpr std::pair<const char*, PlantPtr (*)(const Section&, DataSource&, const PlantPtr&)> kControllerReaders[] = {
    {"pid", close_pid},
    {"emps-pd", close_emps_pd},
};

double positive(const Section& s, const std::string& key, double fallback, const char* unit, bool required) {
  const double v = required ? s.number(key) : s.number(key, fallback);
  if (!(std::isfinite(v) && v > 0)) throw std::invalid_argument(s.at(key) + ": " + detail::format_value(v) + " must be > 0 (" + unit + ")");
  return v;
}

}  // namespace

InputSignal input_from_column(const Dataset& data, const std::string& time_column, const std::string& column,
                              double scale, bool hold) {
  const Eigen::VectorXd& t = select_column(data, time_column, "time");
  const Eigen::VectorXd& x = select_column(data, column, "input");
  const double dt = check_time(data, t);
  InputSignal in;
  in.shape = InputShape::table;
  in.hold_steps = hold;
  in.times.resize(static_cast<std::size_t>(t.size()));
  in.values.resize(in.times.size());
  for (Eigen::Index k = 0; k < t.size(); ++k) {
    if (!std::isfinite(x[k]))
      throw std::invalid_argument(data.where() + data.row_label(k) + ", column '" + column + "': value is not a finite number");
    // k * dt: the same product the engine forms for a sampled controller's instants.
    in.times[static_cast<std::size_t>(k)] = static_cast<double>(k) * dt;
    in.values[static_cast<std::size_t>(k)] = scale * x[k];
  }
  return in;
}

namespace {
Scenario read_scenario(const YAML::Node& root, const std::string& where, const ScenarioOptions& options);
}  // namespace

Scenario scenario_from_yaml(const YAML::Node& root, const std::string& where, const ScenarioOptions& options) {
  detail::check_unique_keys(root, where);
  try {
    return read_scenario(root, where, options);
  } catch (const YAML::Exception& e) {
    // A value of the wrong kind met where the reader asked for another (a list as a name, ...).
    throw detail::yaml_error(where, e);
  }
}

namespace {
Scenario read_scenario(const YAML::Node& root, const std::string& where, const ScenarioOptions& options) {
  const Section top(root, where);
  top.allow({"description", "data", "plant", "friction", "input", "controller", "duration", "output_rate", "solver",
             "initial"});
  auto section = [&](const char* key) {
    if (!top.has(key)) throw std::invalid_argument(where + ": missing '" + key + "'");
    return Section(root[key], where + ": " + key);
  };
  DataSource src(options, top.text("data", ""));
  Scenario sc;
  sc.plant = read_plant(section("plant"), options);
  sc.law = options.law ? *options.law : law_from_yaml(root["friction"], where + ": friction");
  if (top.has("input")) {
    sc.input = read_input(section("input"), src);
  } else {
    sc.input = InputSignal{};  // constant 0: a free response
  }
  if (top.has("controller")) {
    const Section cs = section("controller");
    sc.plant = choose(cs, "type", "pid", kControllerReaders, "controller type", "")(cs, src, sc.plant);
  }
  // Top-level values: messages as "FILE: duration: ..." to match the key path style.
  SimulationOptions& o = sc.options;
  auto top_key = [&](const char* key) { return where + ": " + key; };
  auto top_positive = [&](const char* key, double fallback, const char* unit, bool required) {
    if (!top.has(key)) {
      if (required) throw std::invalid_argument(where + ": missing '" + std::string(key) + "' (" + unit + ", > 0)");
      return fallback;
    }
    const double v = Section::to_number(root[key], top_key(key));
    if (!(std::isfinite(v) && v > 0)) throw std::invalid_argument(top_key(key) + ": " + detail::format_value(v) + " must be > 0 (" + unit + ")");
    return v;
  };
  const bool data_input = src.data_step.has_value();
  o.duration = top_positive("duration", data_input ? sc.input.times.back() : 0.0, "s", !data_input);
  o.output_rate = top_positive("output_rate", o.output_rate, "Hz", false);
  {
    // Refused here, before anything is allocated, naming the keys (simulate() checks it too).
    const double need = output_bytes(o, sc.law.is_dynamic() ? sc.law.num_states() : 0), limit = max_output_bytes();
    if (!(need <= limit)) {
      const bool rate_given = top.has("output_rate");
      std::ostringstream m;
      m << where << ": " << (rate_given ? "duration and output_rate" : "duration") << ": "
        << detail::format_value(o.duration) << " s at " << detail::format_value(o.output_rate) << " Hz"
        << (rate_given ? "" : " (the default output_rate)") << " gives " << std::setprecision(3) << output_rows(o)
        << " output rows, which need " << format_bytes(need) << " of memory; the limit is half this machine's memory, "
        << format_bytes(limit) << ": shorten duration or lower output_rate";
      throw std::invalid_argument(m.str());
    }
  }
  if (top.has("solver")) {
    const Section s = section("solver");
    s.allow({"mode", "rtol", "atol", "dt", "max_step", "max_steps"});
    static constexpr std::pair<const char*, SolverMode> kModes[] = {
        {"auto", SolverMode::automatic}, {"hybrid", SolverMode::hybrid}, {"stiff", SolverMode::stiff}, {"fixed-step", SolverMode::fixed_step}};
    o.mode = choose(s, "mode", "auto", kModes, "solver mode", "modes");
    o.rtol = positive(s, "rtol", o.rtol, "relative tolerance", false);
    o.atol = positive(s, "atol", o.atol, "absolute tolerance, state units", false);
    o.dt = positive(s, "dt", o.dt, "s", false);
    if (s.has("max_step")) {
      o.max_step = s.number("max_step");
      if (!(std::isfinite(o.max_step) && o.max_step >= 0))
        throw std::invalid_argument(s.at("max_step") + ": " + detail::format_value(o.max_step) + " must be >= 0 (s; 0 = no limit)");
    }
    if (s.has("max_steps")) {
      const double n = positive(s, "max_steps", 0, "steps", true);
      constexpr double kLongEnd = 0x1p63;  // 2^63: the first value a long cannot hold
      if (!(n < kLongEnd)) throw std::invalid_argument(s.at("max_steps") + ": " + detail::format_value(n) + " must be < 9.2e18 (steps)");
      o.max_steps = static_cast<long>(n);
    }
    with_context(s.at("mode"), [&] { return resolve_solver_mode(sc.law, o.mode); });
  }
  if (top.has("initial")) {
    const Section s = section("initial");
    s.allow({"position", "velocity"});
    const YAML::Node pos = s.node("position");
    bool is_number = true;
    if (pos && pos.IsScalar()) {
      try {
        (void)pos.as<double>();
      } catch (const YAML::Exception&) {
        is_number = false;
      }
    }
    if (!is_number) {  // a column of the data file: its first sample
      const auto d = src.get();
      const std::string name = pos.as<std::string>();
      if (!d) throw std::invalid_argument(s.at("position") + ": '" + name + "' is not a number, and the scenario names no data file");
      const Eigen::VectorXd& q = with_context(s.at("position"), [&]() -> const Eigen::VectorXd& { return select_column(*d, name, "initial position"); });
      if (q.size() == 0) throw std::invalid_argument(s.at("position") + ": column '" + name + "' is empty");
      o.initial_position = q[0];
    } else {
      o.initial_position = s.number("position", o.initial_position);
    }
    o.initial_velocity = s.number("velocity", o.initial_velocity);
  }
  return sc;
}
}  // namespace

Scenario load_scenario(const std::string& path, const ScenarioOptions& options) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw std::invalid_argument(path + " is a directory; expected a scenario YAML file");
  std::ifstream file(path);
  if (!file) throw std::invalid_argument(path + ": cannot open the scenario file");
  YAML::Node root;
  try {
    root = YAML::Load(file);
  } catch (const YAML::ParserException& e) {
    throw std::invalid_argument(path + ": not valid YAML at line " + std::to_string(e.mark.line + 1) + ", column " +
                                std::to_string(e.mark.column + 1) + ": " + e.msg);
  }
  if (!root || root.IsNull()) throw std::invalid_argument(path + ": empty scenario file");
  ScenarioOptions o = options;
  if (o.base_dir.empty()) o.base_dir = std::filesystem::path(path).parent_path().string();
  return scenario_from_yaml(root, path, o);
}

}  // namespace frictionlab
