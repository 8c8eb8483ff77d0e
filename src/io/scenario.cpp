#include "frictionlab/io/scenario.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <initializer_list>
#include <numbers>
#include <set>
#include <sstream>
#include <stdexcept>

#include "frictionlab/io/law_file.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/plants/closed_loop.hpp"
#include "frictionlab/plants/dc_motor.hpp"
#include "frictionlab/plants/pendulum.hpp"
#include "frictionlab/plants/spring_base.hpp"
#include "frictionlab/plants/velocity_drive.hpp"
#include "frictionlab/simulate/simulate.hpp"

namespace frictionlab {
namespace {

std::string join(std::initializer_list<const char*> names) {
  std::string out;
  for (const char* n : names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

std::string fmt(double x) {
  std::ostringstream out;
  out.precision(10);
  out << x;
  return out.str();
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
      const std::string key = kv.first.as<std::string>();
      if (!ok.count(key))
        throw std::invalid_argument(at(key) + ": unknown field '" + key + "'; valid fields: " + join(allowed));
    }
  }

  bool has(const std::string& key) const { return static_cast<bool>(node_[key]); }

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

std::shared_ptr<const Plant> read_plant(const Section& s) {
  const std::string type = s.text("type", "");
  if (type.empty())
    throw std::invalid_argument(s.path() + ": missing 'type'; valid plant types: axis, pendulum, spring-base, dc-motor, velocity-drive");
  if (type == "axis") {
    s.allow({"type", "M", "offset"});
    AxisParams p;
    p.M = s.number("M");
    p.offset = s.number("offset", 0.0);
    return with_context(s.path(), [&] { return std::make_shared<const RigidAxis>(p); });
  }
  if (type == "pendulum") {
    s.allow({"type", "m", "l", "g", "B"});
    PendulumParams p;
    p.m = s.number("m");
    p.l = s.number("l");
    p.g = s.number("g", 9.81);
    p.B = s.number("B", 0.0);
    return with_context(s.path(), [&] { return std::make_shared<const Pendulum>(p); });
  }
  if (type == "spring-base") {
    s.allow({"type", "m", "k", "c", "V0", "x0"});
    SpringBaseParams p;
    p.m = s.number("m");
    p.k = s.number("k");
    p.V0 = s.number("V0");
    p.c = s.number("c", 0.0);
    p.x0 = s.number("x0", 0.0);
    return with_context(s.path(), [&] { return std::make_shared<const SpringBase>(p); });
  }
  if (type == "dc-motor") {
    s.allow({"type", "J", "R", "L", "Kt", "Kb", "Ka", "load", "drive"});
    DcMotorParams p;
    const std::string drive = s.text("drive", "voltage");
    if (drive == "voltage") {
      p.drive = MotorDrive::voltage;
    } else if (drive == "current") {
      p.drive = MotorDrive::current;
    } else {
      throw std::invalid_argument(s.at("drive") + ": unknown drive '" + drive + "'; valid drives: voltage, current");
    }
    p.J = s.number("J");
    p.R = s.number("R");
    p.Kt = s.number("Kt");
    p.Kb = s.number("Kb");
    p.L = p.drive == MotorDrive::voltage ? s.number("L") : s.number("L", 1e-3);
    p.Ka = s.number("Ka", 1.0);
    p.load = s.number("load", 0.0);
    return with_context(s.path(), [&] { return std::make_shared<const DcMotor>(p); });
  }
  if (type == "velocity-drive") {
    s.allow({"type", "M"});
    VelocityDriveParams p;
    p.M = s.number("M", 0.0);
    return with_context(s.path(), [&] { return std::make_shared<const VelocityDrive>(p); });
  }
  throw std::invalid_argument(s.at("type") + ": unknown plant type '" + type +
                              "'; valid plant types: axis, pendulum, spring-base, dc-motor, velocity-drive");
}

InputSignal read_input(const Section& s) {
  InputSignal in;
  const std::string type = s.text("type", "");
  const char* valid = "constant, step, ramp, trapezoid, sine, table";
  if (type.empty()) throw std::invalid_argument(s.path() + ": missing 'type'; valid input types: " + std::string(valid));
  if (type == "constant") {
    s.allow({"type", "value"});
    in.shape = InputShape::constant;
    in.value = s.number("value");
  } else if (type == "step") {
    s.allow({"type", "value", "initial", "time"});
    in.shape = InputShape::step;
    in.value = s.number("value");
    in.initial = s.number("initial", 0.0);
    in.time = s.number("time", 0.0);
  } else if (type == "ramp") {
    s.allow({"type", "rate", "initial", "time", "limit"});
    in.shape = InputShape::ramp;
    in.rate = s.number("rate");
    in.initial = s.number("initial", 0.0);
    in.time = s.number("time", 0.0);
    if (s.has("limit")) {
      in.has_limit = true;
      in.limit = s.number("limit");
    }
  } else if (type == "trapezoid") {
    s.allow({"type", "level", "rate", "hold", "rate_down", "initial", "time"});
    in.shape = InputShape::trapezoid;
    in.level = s.number("level");
    in.rate = s.number("rate");
    in.hold = s.number("hold", 0.0);
    in.rate_down = s.number("rate_down", 0.0);
    in.initial = s.number("initial", 0.0);
    in.time = s.number("time", 0.0);
  } else if (type == "sine") {
    s.allow({"type", "amplitude", "omega", "frequency", "phase", "offset"});
    in.shape = InputShape::sine;
    in.amplitude = s.number("amplitude");
    if (s.has("omega") && s.has("frequency"))
      throw std::invalid_argument(s.path() + ": give either 'omega' (rad/s) or 'frequency' (Hz), not both");
    if (s.has("frequency")) {
      const double f = s.number("frequency");
      if (!(f > 0)) throw std::invalid_argument(s.at("frequency") + ": " + fmt(f) + " must be > 0 (Hz)");
      in.omega = 2.0 * std::numbers::pi * f;
    } else {
      in.omega = s.number("omega");
    }
    in.phase = s.number("phase", 0.0);
    in.offset = s.number("offset", 0.0);
  } else if (type == "table") {
    s.allow({"type", "times", "values", "interpolation"});
    in.shape = InputShape::table;
    in.times = s.numbers("times");
    in.values = s.numbers("values");
    const std::string interp = s.text("interpolation", "linear");
    if (interp == "linear") {
      in.hold_steps = false;
    } else if (interp == "hold") {
      in.hold_steps = true;
    } else {
      throw std::invalid_argument(s.at("interpolation") + ": unknown interpolation '" + interp +
                                  "'; valid: linear, hold");
    }
  } else {
    throw std::invalid_argument(s.at("type") + ": unknown input type '" + type + "'; valid input types: " + valid);
  }
  in.validate(s.path());
  return in;
}

ControllerParams read_controller(const Section& s) {
  s.allow({"loop", "Kp", "Ki", "Kd", "limit"});
  ControllerParams c;
  const std::string loop = s.text("loop", "position");
  if (loop == "position") {
    c.loop = ControlLoop::position;
  } else if (loop == "velocity") {
    c.loop = ControlLoop::velocity;
  } else {
    throw std::invalid_argument(s.at("loop") + ": unknown loop '" + loop + "'; valid loops: position, velocity");
  }
  c.Kp = s.number("Kp", 0.0);
  c.Ki = s.number("Ki", 0.0);
  c.Kd = s.number("Kd", 0.0);
  c.limit = s.number("limit", 0.0);
  return c;
}

double positive(const Section& s, const std::string& key, double fallback, const char* unit, bool required) {
  const double v = required ? s.number(key) : s.number(key, fallback);
  if (!(std::isfinite(v) && v > 0)) throw std::invalid_argument(s.at(key) + ": " + fmt(v) + " must be > 0 (" + unit + ")");
  return v;
}

}  // namespace

Scenario scenario_from_yaml(const YAML::Node& root, const std::string& where) {
  const Section top(root, where);
  top.allow({"description", "plant", "friction", "input", "controller", "duration", "output_rate", "solver", "initial"});
  auto section = [&](const char* key) {
    if (!top.has(key)) throw std::invalid_argument(where + ": missing '" + key + "'");
    return Section(root[key], where + ": " + key);
  };
  Scenario sc;
  sc.plant = read_plant(section("plant"));
  sc.law = law_from_yaml(root["friction"], where + ": friction");
  if (top.has("input")) {
    sc.input = read_input(section("input"));
  } else {
    sc.input = InputSignal{};  // constant 0: a free response
  }
  if (top.has("controller")) {
    const ControllerParams c = read_controller(section("controller"));
    sc.plant = with_context(where + ": controller", [&] { return std::make_shared<const ClosedLoop>(sc.plant, c); });
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
    if (!(std::isfinite(v) && v > 0)) throw std::invalid_argument(top_key(key) + ": " + fmt(v) + " must be > 0 (" + unit + ")");
    return v;
  };
  o.duration = top_positive("duration", 0.0, "s", true);
  o.output_rate = top_positive("output_rate", 100.0, "Hz", false);
  if (top.has("solver")) {
    const Section s = section("solver");
    s.allow({"mode", "rtol", "atol", "dt", "max_step", "max_steps"});
    const std::string mode = s.text("mode", "auto");
    if (mode == "auto") {
      o.mode = SolverMode::automatic;
    } else if (mode == "hybrid") {
      o.mode = SolverMode::hybrid;
    } else if (mode == "stiff") {
      o.mode = SolverMode::stiff;
    } else if (mode == "fixed-step") {
      o.mode = SolverMode::fixed_step;
    } else {
      throw std::invalid_argument(s.at("mode") + ": unknown solver mode '" + mode + "'; valid modes: auto, hybrid, stiff, fixed-step");
    }
    o.rtol = positive(s, "rtol", o.rtol, "relative tolerance", false);
    o.atol = positive(s, "atol", o.atol, "absolute tolerance, state units", false);
    o.dt = positive(s, "dt", o.dt, "s", false);
    if (s.has("max_step")) {
      o.max_step = s.number("max_step");
      if (!(std::isfinite(o.max_step) && o.max_step >= 0))
        throw std::invalid_argument(s.at("max_step") + ": " + fmt(o.max_step) + " must be >= 0 (s; 0 = no limit)");
    }
    if (s.has("max_steps")) o.max_steps = static_cast<long>(positive(s, "max_steps", 0, "steps", true));
    with_context(s.at("mode"), [&] { return resolve_solver_mode(sc.law, o.mode); });
  }
  if (top.has("initial")) {
    const Section s = section("initial");
    s.allow({"position", "velocity"});
    o.initial_position = s.number("position", 0.0);
    o.initial_velocity = s.number("velocity", 0.0);
  }
  return sc;
}

Scenario load_scenario(const std::string& path) {
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
  return scenario_from_yaml(root, path);
}

}  // namespace frictionlab
