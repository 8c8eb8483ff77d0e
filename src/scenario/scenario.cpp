#include "frictionlab/models/parameter.hpp"
#include "frictionlab/scenario/scenario.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <map>
#include <initializer_list>
#include <numbers>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "frictionlab/control/compensation_spec.hpp"
#include "frictionlab/error.hpp"
#include "frictionlab/io/columns.hpp"
#include "frictionlab/scenario/law_file.hpp"
#include "frictionlab/scenario/model_file.hpp"
#include "frictionlab/io/load.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/plants/backlash_axis.hpp"
#include "frictionlab/plants/dc_motor.hpp"
#include "frictionlab/plants/pendulum.hpp"
#include "frictionlab/plants/spring_base.hpp"
#include "frictionlab/plants/velocity_drive.hpp"
#include "frictionlab/core/contour_input.hpp"
#include "frictionlab/simulate/closed_loop.hpp"
#include "frictionlab/simulate/emps_pd_loop.hpp"
#include "frictionlab/simulate/simulate.hpp"
#include "frictionlab/simulate/xy_table.hpp"
#include "frictionlab/simulate/output_size.hpp"
#include "io/input_file.hpp"
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
    if (!node_.IsMap()) throw InputError(errc::scenario_value, path_ + ": expected a mapping of keys to values", detail::key_fields(path_));
  }

  const std::string& path() const { return path_; }
  std::string at(const std::string& key) const { return path_ + "." + key; }
  // The fields of an error at `key` (file and dotted key).
  ErrorFields fields(const std::string& key, const std::string& value = "") const {
    ErrorFields f = detail::key_fields(path_, key);
    f.value = value;
    return f;
  }

  // Rejects keys outside `allowed`, naming the key and listing the valid ones.
  void allow(std::initializer_list<const char*> allowed) const {
    std::set<std::string> ok;
    for (const char* a : allowed) ok.insert(a);
    for (const auto& kv : node_) {
      if (!kv.first.IsScalar())  // yaml-cpp would throw its own bad conversion
        throw InputError(errc::scenario_key_unknown,
                         path_ + ": line " + std::to_string(kv.first.Mark().line + 1) +
                             ": expected a field name as key, got a list, mapping or empty key; valid fields: " + join(allowed),
                         detail::key_fields(path_));
      const std::string key = kv.first.as<std::string>();
      if (!ok.count(key))
        throw InputError(errc::scenario_key_unknown, at(key) + ": unknown field '" + key + "'; valid fields: " + join(allowed),
                         fields(key));
    }
  }

  bool has(const std::string& key) const { return static_cast<bool>(node_[key]); }
  std::vector<std::string> keys() const {
    std::vector<std::string> out;
    for (const auto& kv : node_) out.push_back(kv.first.as<std::string>());
    return out;
  }
  YAML::Node node(const std::string& key) const { return node_[key]; }

  double number(const std::string& key) const {
    const YAML::Node v = node_[key];
    if (!v) throw InputError(errc::scenario_key_missing, path_ + ": missing '" + key + "' (a number)", fields(key));
    return to_number(v, at(key), fields(key));
  }
  double number(const std::string& key, double fallback) const { return has(key) ? number(key) : fallback; }

  std::string text(const std::string& key, const std::string& fallback) const {
    const YAML::Node v = node_[key];
    if (!v) return fallback;
    if (!v.IsScalar()) throw InputError(errc::scenario_value, at(key) + ": expected a name", fields(key));
    return v.as<std::string>();
  }

  std::vector<double> numbers(const std::string& key) const {
    const YAML::Node v = node_[key];
    if (!v) throw InputError(errc::scenario_key_missing, path_ + ": missing '" + key + "' (a list of numbers)", fields(key));
    if (!v.IsSequence()) {
      throw InputError(errc::scenario_value, at(key) + ": expected a list of numbers, e.g. [0, 1, 2]", fields(key));
    }
    std::vector<double> out;
    for (std::size_t i = 0; i < v.size(); ++i) {
      out.push_back(to_number(v[i], at(key) + "[" + std::to_string(i) + "]", fields(key + "[" + std::to_string(i) + "]")));
    }
    return out;
  }

  static double to_number(const YAML::Node& v, const std::string& where, ErrorFields fields = {}) {
    if (fields.file.empty() && fields.key.empty()) fields = detail::key_fields(where);
    if (!v.IsScalar()) throw InputError(errc::scenario_value, where + ": expected a number", fields);
    const std::string s = v.as<std::string>();
    try {
      return v.as<double>();
    } catch (const YAML::Exception&) {
      fields.value = s;
      throw InputError(errc::scenario_value, where + ": expected a number, got '" + s + "'", fields);
    }
  }

 private:
  YAML::Node node_;
  std::string path_;
};

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
  throw InputError(errc::scenario_value,
                   s.at(key) + ": unknown " + what + " '" + name + "'; valid" + (plural.empty() ? "" : " " + plural) + ": " + valid,
                   s.fields(key, name));
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
  DataSource(const ScenarioOptions& o, std::string default_file) : o_(o), default_file_(std::move(default_file)) {
    // The top-level data file is an input of the run even when no section reads it (or the
    // caller's data set replaces it).
    if (o_.files_read && !default_file_.empty()) o_.files_read->push_back(resolve(default_file_));
  }

  // The data set of a section: options.data, else the section's `file`, else the top-level one.
  // Null when there is none (the caller decides whether that is an error).
  std::shared_ptr<const Dataset> get(const std::string& file = "") {
    if (o_.data) return o_.data;
    const std::string name = file.empty() ? default_file_ : file;
    if (name.empty()) return nullptr;
    const std::filesystem::path path(resolve(name));
    auto& slot = cache_[path.string()];
    if (!slot) {
      if (o_.files_read) o_.files_read->push_back(path.string());
      slot = std::make_shared<const Dataset>(load_dataset(path.string()));
    }
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
    return detail::with_context(s.at(key), [&] { return resolve_constant(*d, name, key); });
  }

  std::string resolve(const std::string& name) const {
    std::filesystem::path path(name);
    if (path.is_relative() && !o_.base_dir.empty()) path = std::filesystem::path(o_.base_dir) / path;
    return path.string();
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

// What a plant reader may need beyond its section: whether a law for contacts without their
// own exists (the top-level `friction`, or the caller's law), that law (read when a compensation
// needs it), and the directory a compensation's model file is resolved from.
struct PlantContext {
  bool fallback_law = false;
  std::function<FrictionLaw()> fallback;
  std::string base_dir;
  const ScenarioOptions* options = nullptr;  // the caller's: its per-axis models (axis_models)
};

// What a `compensation:` block falls back on: the directory its model file is resolved from, the
// law of the contact it compensates (the exact model; read only when the block names none) and
// the inertia of the body (kg or kg m^2, the disturbance observer's default).
struct CompensationContext {
  std::string base_dir;
  std::vector<std::string>* files_read = nullptr;  // ScenarioOptions::files_read
  std::function<FrictionLaw()> law;
  double inertia = 0.0;
  Axis axis = Axis::linear;  // how the plant moves (Plant::motion_axis): a model file must be of it
};

// The law with every parameter that carries newtons (forces, viscous coefficients, stiffnesses,
// force rates, a table's forces, GMS's element stiffnesses, a ripple's amplitudes) multiplied by
// `scale`: its force is then scale times the original's for every velocity history and position
// (the states, in m or rad, and the velocities are the same), so scale 1.2 models a 20 %
// over-estimated friction.
FrictionLaw scaled_law(const FrictionLaw& law, double scale) {
  LawSpec spec = law.to_spec();
  for (const Parameter& p : law.parameters()) {
    const bool newtons = p.quantity == Quantity::force || p.quantity == Quantity::viscous ||
                         p.quantity == Quantity::stiffness || p.quantity == Quantity::force_rate;
    if (newtons && spec.scalars.count(p.name)) spec.scalars[p.name] *= scale;
  }
  // Table forces (N), GMS element stiffnesses (N/m), the ripple's amplitudes or its table's forces
  // (N): a compensation that carries the ripple scales it with the rest.
  for (const char* name : {"force", "k", "ripple_a", "ripple_b", "ripple_force"})
    if (spec.arrays.count(name))
      for (double& v : spec.arrays[name]) v *= scale;
  return FrictionLaw::from_spec(spec);
}

// compensation: {type, model: FILE | friction: {law: ...}, scale, and the type's own parameters}
// (see scenario/scenario.hpp): the compensator it builds, with messages naming the block's keys.
std::shared_ptr<const Compensator> read_compensation(const Section& s, const CompensationContext& ctx) {
  const std::string type = s.text("type", "");
  const auto& types = compensation_types();
  if (std::find(types.begin(), types.end(), type) == types.end()) {
    std::string valid;
    for (const auto& t : types) valid += (valid.empty() ? "" : ", ") + t;
    if (type.empty()) throw std::invalid_argument(s.path() + ": missing 'type'; valid compensation types: " + valid);
    throw std::invalid_argument(s.at("type") + ": unknown compensation type '" + type + "'; valid types: " + valid);
  }
  // The type's own parameters (band, dead_band, gain, bandwidth, inertia): make_compensation
  // knows which belong to which type and refuses the others, naming them.
  std::optional<double> inertia = ctx.inertia > 0 ? std::optional<double>(ctx.inertia) : std::nullopt;
  auto make = [&](const std::map<std::string, double>& v) {
    try {
      return make_compensation(type, v, inertia);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(s.path() + ": " + e.what() + " (and type, model, friction, scale)");
    }
  };
  std::map<std::string, double> values;
  for (const std::string& key : s.keys()) {
    if (key == "type" || key == "model" || key == "friction" || key == "scale") continue;
    make({{key, 0.0}});  // a key of another type, or of none, is named before its value is read
    values[key] = s.number(key);
  }
  const CompensationParams params = make(values);
  const bool observer = std::holds_alternative<DisturbanceObserverParams>(params);
  if (s.has("model") && s.has("friction"))
    throw std::invalid_argument(s.path() + ": give either 'model' (a MODEL.json or law file) or 'friction' (a law), not both");
  if (observer && (s.has("friction") || s.has("scale")))
    throw std::invalid_argument(s.at(s.has("friction") ? "friction" : "scale") +
                                ": a disturbance-observer uses no friction law (its parameters: bandwidth, inertia; "
                                "'model' may give the inertia M)");
  std::optional<FrictionLaw> law;
  std::string law_key = "type";  // the key a law that does not fit the type is blamed on
  if (s.has("model")) {
    std::filesystem::path path(s.text("model", ""));
    if (path.is_relative() && !ctx.base_dir.empty()) path = std::filesystem::path(ctx.base_dir) / path;
    if (ctx.files_read) ctx.files_read->push_back(path.string());
    const ModelFile m = detail::with_context(s.at("model"), [&] { return read_model_file(path.string()); });
    // A model identified on the other kind of axis has its numbers in other units (N m, not N).
    if (m.axis && *m.axis != ctx.axis) {
      const auto name = [](Axis x) { return std::string(x == Axis::rotary ? "rotary" : "linear"); };
      throw InputError(errc::scenario_value,
                       s.at("model") + ": " + path.string() + ": axis: a " + name(*m.axis) + " model on a " +
                           name(ctx.axis) + " plant; expected a model identified on a " + name(ctx.axis) + " axis",
                       {.file = path.string(), .key = "axis", .value = name(*m.axis)});
    }
    law = m.law;
    law_key = "model";
    if (observer && m.inertia && !values.count("inertia")) inertia = m.inertia;
  } else if (s.has("friction")) {
    law = law_from_yaml(s.node("friction"), s.at("friction"));
    law_key = "friction";
  } else if (!observer) {
    law = detail::with_context(s.path(), ctx.law);  // the exact model: the contact's own law
  }
  const double scale = s.number("scale", 1.0);
  if (!(std::isfinite(scale) && scale > 0))
    throw std::invalid_argument(s.at("scale") + ": " + detail::format_value(scale) + " must be > 0 (factor on the law's forces)");
  if (law && scale != 1.0) law = detail::with_context(s.at("scale"), [&] { return scaled_law(*law, scale); });
  auto build = [&]() -> std::shared_ptr<const Compensator> {
    CompensationParams q = params;
    if (auto* dob = std::get_if<DisturbanceObserverParams>(&q); dob && inertia && !values.count("inertia"))
      dob->inertia = *inertia;
    return make_compensator(q, law ? &*law : nullptr);
  };
  try {
    return build();
  } catch (const std::invalid_argument& e) {
    // A law that does not fit the type is the law's key's fault; a bad band, gain, ... names
    // its parameter itself ("feedforward: band = -1 must be > 0").
    const std::string what = e.what();
    if (what.find(": law = ") == std::string::npos) throw std::invalid_argument(s.path() + ": " + what);
    throw std::invalid_argument(s.at(law_key) + ": " + what +
                                (law_key == "type" ? "; without 'model' or 'friction' the compensation uses the compensated "
                                                     "contact's own law: give a LuGre law in 'friction' or 'model'"
                                                   : ""));
  }
}

PlantPtr read_axis(const Section& s, const PlantContext&) {
  s.allow({"type", "M", "offset", "backlash"});
  AxisParams p;
  p.M = s.number("M");
  p.offset = s.number("offset", p.offset);
  if (!s.has("backlash")) return detail::with_context(s.path(), [&] { return std::make_shared<const RigidAxis>(p); });
  // Backlash: M is the load's inertia, the input drives the motor across the play.
  const Section b(s.node("backlash"), s.at("backlash"));
  b.allow({"width", "motor_inertia", "restitution", "friction_side", "initial_gap"});
  BacklashParams q;
  q.M_load = p.M;
  q.offset = p.offset;
  q.width = b.number("width");
  q.M_motor = b.number("motor_inertia");
  q.restitution = b.number("restitution", q.restitution);
  q.initial_gap = b.number("initial_gap", q.initial_gap);
  static constexpr std::pair<const char*, FrictionSide> kSides[] = {{"load", FrictionSide::load}, {"motor", FrictionSide::motor}};
  q.friction_side = choose(b, "friction_side", "load", kSides, "friction side", "sides");
  return detail::with_context(s.path(), [&] { return std::make_shared<const BacklashAxis>(q); });
}

PlantPtr read_pendulum(const Section& s, const PlantContext&) {
  s.allow({"type", "m", "l", "g", "B"});
  PendulumParams p;
  p.m = s.number("m");
  p.l = s.number("l");
  p.g = s.number("g", p.g);
  p.B = s.number("B", p.B);
  return detail::with_context(s.path(), [&] { return std::make_shared<const Pendulum>(p); });
}

PlantPtr read_spring_base(const Section& s, const PlantContext&) {
  s.allow({"type", "m", "k", "c", "V0", "x0"});
  SpringBaseParams p;
  p.m = s.number("m");
  p.k = s.number("k");
  p.V0 = s.number("V0");
  p.c = s.number("c", p.c);
  p.x0 = s.number("x0", p.x0);
  return detail::with_context(s.path(), [&] { return std::make_shared<const SpringBase>(p); });
}

PlantPtr read_dc_motor(const Section& s, const PlantContext&) {
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
  return detail::with_context(s.path(), [&] { return std::make_shared<const DcMotor>(p); });
}

PlantPtr read_velocity_drive(const Section& s, const PlantContext&) {
  s.allow({"type", "M"});
  VelocityDriveParams p;
  p.M = s.number("M", p.M);
  return detail::with_context(s.path(), [&] { return std::make_shared<const VelocityDrive>(p); });
}

// Position-loop gains and force limit of an xy-table axis (N per m, m/s, m/s^2; N): the plant's
// `controller` gives both axes' values, an axis's `drive` overrides any of them.
void read_xy_gains(const Section& s, PidParams& c) {
  c.Kp = s.number("Kp", c.Kp);
  c.Ki = s.number("Ki", c.Ki);
  c.Kd = s.number("Kd", c.Kd);
  c.Kvff = s.number("Kvff", c.Kvff);
  c.Kaff = s.number("Kaff", c.Kaff);
  c.limit = s.number("limit", c.limit);
}

// `shared`: the plant's `compensation` block (null when none), which the axis's own replaces.
// An identified model of the axis (ScenarioOptions::axis_models) replaces its law, mass and
// offset; its inertia and lead go (the model's M is the equivalent mass).
XyAxis read_xy_axis(const Section& s, const std::string& name, const PidParams& common, const PlantContext& ctx,
                    const Section* shared) {
  s.allow({"mass", "inertia", "lead", "offset", "friction", "drive", "compensation"});
  XyAxis a;
  const AxisModel* model = nullptr;
  if (ctx.options) {
    const auto it = ctx.options->axis_models.find(name);
    if (it != ctx.options->axis_models.end()) model = &it->second;
  }
  if (!s.has("mass") && !s.has("inertia"))
    throw std::invalid_argument(s.path() + ": missing 'mass' (kg) or 'inertia' (kg m^2) with 'lead' (m/rev)");
  a.mass = s.number("mass", a.mass);
  if (s.has("inertia")) {
    a.inertia = s.number("inertia");
    if (!s.has("lead")) throw std::invalid_argument(s.path() + ": missing 'lead' (m/rev, the screw's), needed with 'inertia'");
    a.lead = s.number("lead");
  } else if (s.has("lead")) {
    throw std::invalid_argument(s.at("lead") + ": a lead without 'inertia' (kg m^2) has nothing to reflect; give both or neither");
  }
  a.offset = s.number("offset", a.offset);
  if (model) {
    a.law = model->law;
    a.mass = model->axis.M;
    a.inertia = a.lead = 0.0;
    a.offset = model->axis.offset;
  } else if (s.has("friction")) {
    a.law = law_from_yaml(s.node("friction"), s.at("friction"));
  } else if (!ctx.fallback_law) {
    throw std::invalid_argument(s.path() + ": missing 'friction' (the axis's law), and there is no top-level 'friction' for it");
  }
  a.gains = common;
  if (s.has("drive")) {
    const Section d(s.node("drive"), s.at("drive"));
    d.allow({"limit", "Kp", "Ki", "Kd", "Kvff", "Kaff"});
    read_xy_gains(d, a.gains);
  }
  const YAML::Node own = s.node("compensation");
  if (own && own.IsScalar() && own.as<std::string>() == "none") return a;  // the shared one switched off
  if (own || shared) {
    CompensationContext cc;
    cc.base_dir = ctx.base_dir;
    cc.files_read = ctx.options ? ctx.options->files_read : nullptr;
    cc.law = a.law ? std::function<FrictionLaw()>([law = *a.law] { return law; }) : ctx.fallback;
    cc.inertia = detail::with_context(s.path(), [&] { return a.equivalent_mass(); });
    a.compensator = own ? read_compensation(Section(own, s.at("compensation")), cc) : read_compensation(*shared, cc);
  }
  return a;
}

PlantPtr read_xy_table(const Section& s, const PlantContext& ctx) {
  s.allow({"type", "axes", "controller", "compensation"});
  if (!s.has("axes")) throw std::invalid_argument(s.path() + ": missing 'axes' (a mapping with the x and y axes)");
  const Section axes(s.node("axes"), s.at("axes"));
  axes.allow({"x", "y"});
  for (const char* name : {"x", "y"})
    if (!axes.has(name)) throw std::invalid_argument(axes.path() + ": missing '" + name + "' (the " + name + " axis)");
  PidParams common;
  XyTiming timing;
  if (s.has("controller")) {
    const Section c(s.node("controller"), s.at("controller"));
    c.allow({"Kp", "Ki", "Kd", "Kvff", "Kaff", "limit", "Ts", "delay"});
    read_xy_gains(c, common);
    timing.Ts = c.number("Ts", timing.Ts);
    const double delay = c.number("delay", timing.delay);
    if (delay != 0.0 && delay != 1.0)
      throw std::invalid_argument(c.at("delay") + ": " + detail::format_value(delay) + " must be 0 or 1 (samples)");
    timing.delay = static_cast<int>(delay);
  }
  std::optional<Section> shared;
  if (s.has("compensation")) shared.emplace(s.node("compensation"), s.at("compensation"));
  const Section* sh = shared ? &*shared : nullptr;
  XyAxis x = read_xy_axis(Section(axes.node("x"), axes.at("x")), "x", common, ctx, sh);
  XyAxis y = read_xy_axis(Section(axes.node("y"), axes.at("y")), "y", common, ctx, sh);
  // A bad identified mass or offset is the model file's (the caller checks it; this names the axis).
  const bool modelled = ctx.options && !ctx.options->axis_models.empty();
  const std::string source = modelled && !ctx.options->model_source.empty() ? ctx.options->model_source : s.path();
  return detail::with_context(source, [&] { return std::make_shared<const XyTable>(std::move(x), std::move(y), timing); });
}

constexpr std::pair<const char*, PlantPtr (*)(const Section&, const PlantContext&)> kPlantReaders[] = {
    {"axis", read_axis},
    {"pendulum", read_pendulum},
    {"spring-base", read_spring_base},
    {"dc-motor", read_dc_motor},
    {"velocity-drive", read_velocity_drive},
    {"xy-table", read_xy_table},
};

PlantPtr read_plant(const Section& s, const ScenarioOptions& o, const PlantContext& ctx) {
  if (!o.axis_models.empty()) {
    const std::string type = s.text("type", "");
    if (type != "xy-table")
      throw std::invalid_argument(s.at("type") + ": plant type '" + type + "' has one axis; models named by axis (" +
                                  o.axis_models.begin()->first + ") need a two-axis plant (xy-table)");
    if (o.law || o.axis)
      throw std::invalid_argument(s.at("type") + ": give the xy-table models by axis name only, not also a one-axis model");
    for (const auto& [name, m] : o.axis_models)
      if (name != "x" && name != "y")
        throw std::invalid_argument(s.at("type") + ": the xy-table has no axis '" + name + "'; expected x or y");
  }
  if (o.axis) {
    const std::string type = s.text("type", "axis");
    if (type == "xy-table")
      throw std::invalid_argument(s.at("type") + ": the xy-table has two axes (x, y): a one-axis model (inertia, offset, "
                                  "law) must name the axis it replaces (frictionlab validate: x=MODEL.json, or "
                                  "x=MODEL_X.json,y=MODEL_Y.json)");
    if (type != "axis")
      throw std::invalid_argument(s.at("type") + ": plant type '" + type +
                                  "' cannot take an identified inertia and offset; expected axis");
    s.allow({"type", "M", "offset"});
    // M and offset come from the identified model: a bad value is the model file's.
    const std::string source = o.model_source.empty() ? s.path() : o.model_source + ": parameters";
    return detail::with_context(source, [&] { return std::make_shared<const RigidAxis>(*o.axis); });
  }
  const std::string type = s.text("type", "");
  if (type.empty())
    throw std::invalid_argument(s.path() + ": missing 'type'; valid plant types: " + names_of(kPlantReaders));
  return choose(s, "type", "", kPlantReaders, "plant type", "plant types")(s, ctx);
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
  InputSignal in = detail::with_context(s.path(), [&] { return input_from_column(*d, s.text("time", "time"), column, scale, read_interpolation(s)); });
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

// Two-axis inputs (an xy-table's x and y references), one reader per type as the 1-input ones:
// each gives both signals and the duration the contour takes.
struct Contour {
  std::array<InputSignal, 2> inputs;
  double duration = 0.0;  // s: the circle's turns, the path's last time
};

Contour read_circle(const Section& s, DataSource&) {
  s.allow({"type", "centre", "radius", "feed", "direction", "turns", "start_angle"});
  CircleContour c;
  if (s.has("centre")) {
    const std::vector<double> v = s.numbers("centre");
    if (v.size() != 2)
      throw std::invalid_argument(s.at("centre") + ": expected [x, y] (m), got " + std::to_string(v.size()) + " numbers");
    c.cx = v[0];
    c.cy = v[1];
  }
  c.radius = s.number("radius");
  c.feed = s.number("feed");
  static constexpr std::pair<const char*, bool> kDirections[] = {{"ccw", false}, {"cw", true}};
  c.clockwise = choose(s, "direction", "ccw", kDirections, "direction", "directions");
  c.turns = s.number("turns", c.turns);
  c.start_angle = s.number("start_angle", c.start_angle);
  c.validate(s.path());
  return {c.inputs(), c.duration()};
}

Contour read_path(const Section& s, DataSource& src) {
  s.allow({"type", "file", "time", "x", "y", "scale"});
  const auto d = src.get(s.text("file", ""));
  if (!d) throw std::invalid_argument(s.path() + ": no path file: give 'file' (a CSV with time, x and y columns) or a top-level 'data'");
  const double scale = s.number("scale", 1.0);
  if (!(std::isfinite(scale) && scale > 0))
    throw std::invalid_argument(s.at("scale") + ": " + detail::format_value(scale) + " must be > 0 (m per file unit)");
  const std::string tn = s.text("time", "time"), xn = s.text("x", "x"), yn = s.text("y", "y");
  const auto column = [&](const std::string& name, const char* role) {
    return detail::with_context(s.path(), [&]() -> const Eigen::VectorXd& { return finite_column(*d, name, role); });
  };
  const Eigen::VectorXd t = column(tn, "time"), x = column(xn, "x"), y = column(yn, "y");
  for (Eigen::Index k = 1; k < t.size(); ++k)
    if (!(t[k] > t[k - 1]))
      throw std::invalid_argument(s.path() + ": " + d->where() + d->row_label(k) + ", column '" + tn + "': time " +
                                  detail::format_value(t[k]) + " s must be after the previous row's " + detail::format_value(t[k - 1]) + " s");
  std::vector<double> xs(x.data(), x.data() + x.size()), ys(y.data(), y.data() + y.size());
  for (double& v : xs) v *= scale;
  for (double& v : ys) v *= scale;
  Contour c;
  c.inputs = path_inputs(std::span<const double>(t.data(), static_cast<std::size_t>(t.size())), xs, ys, s.path());
  c.duration = t.size() > 0 ? t[t.size() - 1] : 0.0;
  return c;
}

constexpr std::pair<const char*, Contour (*)(const Section&, DataSource&)> kContourReaders[] = {
    {"circle", read_circle},
    {"path", read_path},
};

EmpsPdParams read_emps_pd(const Section& s, DataSource& src) {
  s.allow({"type", "kp", "kv", "gtau", "limit", "dt", "delay", "pulses", "compensation"});
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
      p.pulses = detail::with_context(s.at("pulses"), [&] { return input_from_column(*d, time, column, scale, true); });
    } else if (!optional) {
      throw std::invalid_argument(s.at("pulses") + ": " + d->where() + "no column '" + column +
                                  "'; the file has columns: " + d->describe_contents() + " (set optional: true to run without pulses)");
    }
  }
  return p;
}

PidParams read_controller(const Section& s) {
  s.allow({"type", "loop", "Kp", "Ki", "Kd", "limit", "compensation", "compensation_gain", "measure"});
  PidParams c;
  static constexpr std::pair<const char*, ControlLoop> kLoops[] = {{"position", ControlLoop::position}, {"velocity", ControlLoop::velocity}};
  c.loop = choose(s, "loop", "position", kLoops, "loop", "loops");
  c.Kp = s.number("Kp", c.Kp);
  c.Ki = s.number("Ki", c.Ki);
  c.Kd = s.number("Kd", c.Kd);
  c.limit = s.number("limit", c.limit);
  c.compensation_gain = s.number("compensation_gain", c.compensation_gain);
  return c;
}

// Controller readers, one per controller type: each closes the loop around `plant`.
// A loop's `compensation:` block (null when none), the plant's inertia as the observers' default.
std::shared_ptr<const Compensator> loop_compensation(const Section& s, const PlantPtr& plant, const CompensationContext& cc) {
  if (!s.has("compensation")) return nullptr;
  CompensationContext with_inertia = cc;
  with_inertia.inertia = plant->inertia();
  with_inertia.axis = plant->motion_axis();
  return read_compensation(Section(s.node("compensation"), s.at("compensation")), with_inertia);
}

PlantPtr close_pid(const Section& s, DataSource&, const PlantPtr& plant, const CompensationContext& cc) {
  const PidParams c = read_controller(s);
  const std::shared_ptr<const Compensator> comp = loop_compensation(s, plant, cc);
  // measure: motor | load, on a backlash axis: the body the loop's encoder is on (default: the
  // contact, the body the friction acts on).
  static constexpr std::pair<const char*, MeasuredBody> kBodies[] = {{"motor", MeasuredBody::motor}, {"load", MeasuredBody::load}};
  const std::optional<MeasuredBody> body =
      s.has("measure") ? std::optional<MeasuredBody>(choose(s, "measure", "load", kBodies, "measured body", "bodies")) : std::nullopt;
  if (body && dynamic_cast<const BacklashAxis*>(plant.get()) == nullptr)
    throw InputError(errc::scenario_value,
                     s.at("measure") + ": the " + plant->type() +
                         " has one body, which the loop measures; measure (motor or load) needs an axis with backlash "
                         "(plant.backlash)",
                     s.fields("measure", s.text("measure", "")));
  return detail::with_context(s.path(), [&]() -> PlantPtr {
    PlantPtr loop = close_loop(plant, c, comp);
    if (!body) return loop;
    return static_cast<const ClosedLoop&>(*loop).measuring(*body);
  });
}

PlantPtr close_emps_pd(const Section& s, DataSource& src, const PlantPtr& plant, const CompensationContext& cc) {
  const EmpsPdParams p = read_emps_pd(s, src);
  const std::shared_ptr<const Compensator> comp = loop_compensation(s, plant, cc);
  return detail::with_context(s.path(), [&] { return close_loop(plant, p, comp); });
}

constexpr std::pair<const char*, PlantPtr (*)(const Section&, DataSource&, const PlantPtr&, const CompensationContext&)>
    kControllerReaders[] = {
    {"pid", close_pid},
    {"emps-pd", close_emps_pd},
};

double positive(const Section& s, const std::string& key, double fallback, const char* unit, bool required) {
  const double v = required ? s.number(key) : s.number(key, fallback);
  if (!(std::isfinite(v) && v > 0)) throw std::invalid_argument(s.at(key) + ": " + detail::format_value(v) + " must be > 0 (" + unit + ")");
  return v;
}

// environment: {load: INPUT | {type: gravity, m, l, g, phase}, temperature: T | thermal: {T_ambient,
// T0, tau, R}} (simulate/environment.hpp): the conditions of a one-contact plant's friction.
ContactEnvironment read_environment(const Section& s, DataSource& src) {
  s.allow({"load", "temperature", "thermal"});
  ContactEnvironment env;
  if (s.has("load")) {
    const Section ls(s.node("load"), s.at("load"));
    if (ls.text("type", "") == "gravity") {
      // A joint's gravity load m g l cos(q + phase) (N m; l = 1 m gives the weight's share in N).
      ls.allow({"type", "m", "l", "g", "phase"});
      const double m = ls.number("m"), l = ls.number("l", 1.0), g = ls.number("g", 9.81), phase = ls.number("phase", 0.0);
      for (const auto& [key, v] : {std::pair<const char*, double>{"m", m}, {"l", l}, {"g", g}, {"phase", phase}})
        if (!std::isfinite(v) || (std::string(key) != "phase" && v < 0))
          throw InputError(errc::scenario_value, ls.at(key) + ": " + detail::format_value(v) + " must be " +
                               (std::string(key) == "phase" ? "finite (rad)" : ">= 0 (kg, m, m/s^2)"),
                           ls.fields(key, detail::format_value(v)));
      env.load.of_state = [w = m * g * l, phase](double, std::span<const double> x) { return w * std::cos(x[0] + phase); };
    } else {
      const std::string type = ls.text("type", "");
      bool known = false;
      for (const auto& r : kInputReaders) known = known || type == r.first;
      if (!known)
        throw InputError(type.empty() ? errc::scenario_key_missing : errc::scenario_value,
                         ls.at("type") + ": " + (type.empty() ? "missing" : "unknown load type '" + type + "'") +
                             "; valid load types: " + names_of(kInputReaders) + ", gravity",
                         ls.fields("type", type));
      // Any input type; a data column here must not become the run's data input (its duration).
      const auto step = src.data_step;
      const auto time = src.time_column;
      env.load.signal = read_input(ls, src);
      src.data_step = step;
      src.time_column = time;
    }
  }
  if (s.has("temperature") && s.has("thermal"))
    throw InputError(errc::scenario_value, s.at("thermal") + ": give a 'temperature' (fixed or over time) or a 'thermal' model, not both",
                     s.fields("thermal"));
  if (s.has("temperature") && s.node("temperature").IsMap()) {
    // A temperature over time: any input type, a log's column as a data input (degC or K); like
    // the load, it must not become the run's data input (its duration).
    const Section ts(s.node("temperature"), s.at("temperature"));
    const auto step = src.data_step;
    const auto time = src.time_column;
    env.temperature_log = read_input(ts, src);
    src.data_step = step;
    src.time_column = time;
  } else if (s.has("temperature")) {
    env.temperature = s.number("temperature");
  }
  if (s.has("thermal")) {
    const Section ts(s.node("thermal"), s.at("thermal"));
    ts.allow({"T_ambient", "T0", "tau", "R"});
    ThermalModel th;
    th.T_ambient = ts.number("T_ambient", th.T_ambient);
    if (ts.has("T0")) th.T0 = ts.number("T0");
    for (const auto& [key, unit, field] : {std::tuple<const char*, const char*, double*>{"tau", "s", &th.tau}, {"R", "K/W", &th.R}}) {
      *field = ts.number(key);
      if (!(std::isfinite(*field) && *field > 0))
        throw InputError(errc::scenario_value, ts.at(key) + ": " + detail::format_value(*field) + " must be > 0 (" + unit + ")",
                         ts.fields(key, detail::format_value(*field)));
    }
    env.thermal = th;
  }
  detail::with_context(s.path(), [&] {
    env.validate();
    return 0;
  });
  return env;
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
             "initial", "environment"});
  auto section = [&](const char* key) {
    if (!top.has(key)) throw InputError(errc::scenario_key_missing, where + ": missing '" + key + "'", detail::key_fields(where, key));
    return Section(root[key], where + ": " + key);
  };
  DataSource src(options, top.text("data", ""));
  Scenario sc;
  PlantContext ctx;
  ctx.fallback_law = options.law.has_value() || top.has("friction");
  ctx.fallback = [&] { return options.law ? *options.law : law_from_yaml(root["friction"], where + ": friction"); };
  ctx.base_dir = options.base_dir;
  ctx.options = &options;
  sc.plant = read_plant(section("plant"), options, ctx);
  const bool two_axis = sc.plant->num_inputs() == 2;  // an xy-table: its axes carry their laws
  if (options.law) {
    sc.law = *options.law;
  } else if (top.has("friction") || !two_axis) {
    sc.law = law_from_yaml(root["friction"], where + ": friction");
  }  // else every axis has its own law: sc.law stays unused
  std::optional<double> contour_duration;  // s: the time the two-axis contour takes
  if (two_axis) {
    if (!top.has("input"))
      throw std::invalid_argument(where + ": missing 'input' (the contour of the " + sc.plant->type() + "); valid input types: " +
                                  names_of(kContourReaders));
    const Section is = section("input");
    if (is.text("type", "").empty())
      throw std::invalid_argument(is.path() + ": missing 'type'; valid two-axis input types: " + names_of(kContourReaders));
    const Contour c = choose(is, "type", "", kContourReaders, "two-axis input type", "input types")(is, src);
    sc.inputs.assign(c.inputs.begin(), c.inputs.end());
    contour_duration = c.duration;
    if (top.has("controller"))
      throw std::invalid_argument(where + ": controller: the " + sc.plant->type() +
                                  "'s axes have their controller inside the plant: move it to plant.controller");
  } else if (top.has("input")) {
    const Section is = section("input");
    for (const auto& c : kContourReaders)
      if (is.text("type", "") == c.first)
        throw std::invalid_argument(is.at("type") + ": input type '" + c.first + "' gives two references and needs a two-axis plant (xy-table); plant " +
                                    sc.plant->type() + " takes one input: " + names_of(kInputReaders));
    sc.input = read_input(is, src);
  } else {
    sc.input = InputSignal{};  // constant 0: a free response
  }
  if (top.has("controller") && !two_axis) {
    const Section cs = section("controller");
    CompensationContext cc;
    cc.base_dir = options.base_dir;
    cc.files_read = options.files_read;
    cc.law = [&] { return sc.law; };
    sc.plant = choose(cs, "type", "pid", kControllerReaders, "controller type", "")(cs, src, sc.plant, cc);
  }
  if (top.has("environment")) {
    const Section es = section("environment");
    if (sc.plant->num_contacts() != 1)
      throw InputError(errc::scenario_value,
                       es.path() + ": the " + sc.plant->type() + " has " + std::to_string(sc.plant->num_contacts()) +
                           " contacts; an environment serves a one-contact plant",
                       detail::key_fields(es.path()));
    sc.options.environments = {read_environment(es, src)};
    // A compensator of a law with load or temperature terms sees the same load (a signal: measured;
    // a gravity load: the plant's known load function, estimated from its state) and a fixed
    // temperature; a thermal state it does not see (the law's T_ref). Both loops, the PID's and
    // the EMPS controller's sampled one.
    const CompensationConditions seen = CompensationConditions::of(sc.options.environments[0]);
    if (const auto* loop = dynamic_cast<const ClosedLoop*>(sc.plant.get()); loop && loop->compensator())
      sc.plant = loop->with_conditions(seen);
    else if (const auto* emps = dynamic_cast<const EmpsPdLoop*>(sc.plant.get()); emps && emps->compensator())
      sc.plant = emps->with_conditions(seen);
    // The temperatures the run starts at must lie in the law's range (it would stop at t = 0).
    const ContactEnvironment& env = sc.options.environments[0];
    const std::optional<double> T0 = env.thermal ? std::optional<double>(env.thermal->T0.value_or(env.thermal->T_ambient))
                                                 : env.temperature_at(0.0);
    if (T0) {
      const char* key = env.thermal ? "thermal" : "temperature";
      try {
        Conditions c;
        c.temperature = *T0;
        (void)sc.law.sliding(1.0, c);
      } catch (const InputError& e) {
        throw InputError(e.code(), es.at(key) + ": " + e.what() + " (the temperature the run starts at)",
                         es.fields(key, detail::format_value(*T0)));
      }
    }
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
  const double default_duration = contour_duration ? *contour_duration : data_input ? sc.input.times.back() : 0.0;
  o.duration = top_positive("duration", default_duration, "s", !data_input && !contour_duration);
  o.output_rate = top_positive("output_rate", o.output_rate, "Hz", false);
  std::vector<const FrictionLaw*> laws;  // every contact's: its own, else the scenario's
  for (int k = 0; k < sc.plant->num_contacts(); ++k) {
    const FrictionLaw* own = sc.plant->contact(k).law;
    laws.push_back(own ? own : &sc.law);
  }
  {
    // Refused here, before anything is allocated, naming the keys (simulate() checks it too).
    // Columns beyond one contact's nine: every law's states, and nine per further contact.
    int extra = 9 * (static_cast<int>(laws.size()) - 1);
    for (const FrictionLaw* law : laws) extra += law->is_dynamic() ? law->num_states() : 0;
    const bool rate_given = top.has("output_rate");
    std::ostringstream m;
    m << where << ": " << (rate_given ? "duration and output_rate" : "duration") << ": "
      << detail::format_value(o.duration) << " s at " << detail::format_value(o.output_rate) << " Hz"
      << (rate_given ? "" : " (the default output_rate)") << " gives " << std::setprecision(3) << output_rows(o)
      << " output rows (shorten duration or lower output_rate)";
    const ErrorFields fields{.file = where, .key = "duration", .value = detail::format_value(o.duration)};
    check_memory(output_bytes(o, extra), m.str(), fields);
    check_work(output_rows(o), "output rows", m.str(), fields);
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
    detail::with_context(s.at("mode"), [&] { return resolve_solver_mode(std::span<const FrictionLaw* const>(laws), o.mode); });
  }
  if (two_axis) {
    // The axes start at rest on the contour's first point (no step at t = 0), unless `initial`
    // gives positions [x, y] (m) and velocities [vx, vy] (m/s).
    for (const InputSignal& in : sc.inputs) {
      o.initial_positions.push_back(in.at(0.0).value);
      o.initial_velocities.push_back(0.0);
    }
    if (top.has("initial")) {
      const Section s = section("initial");
      s.allow({"position", "velocity"});
      for (const char* key : {"position", "velocity"}) {
        if (!s.has(key)) continue;
        const std::vector<double> v = s.numbers(key);
        if (v.size() != 2)
          throw std::invalid_argument(s.at(key) + ": expected [x, y] (" + (key[0] == 'p' ? "m" : "m/s") + "), got " +
                                      std::to_string(v.size()) + " numbers");
        (key[0] == 'p' ? o.initial_positions : o.initial_velocities) = v;
      }
    }
  } else if (top.has("initial")) {
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
      const Eigen::VectorXd& q = detail::with_context(s.at("position"), [&]() -> const Eigen::VectorXd& { return select_column(*d, name, "initial position"); });
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
  // Read once within the budget: a device is refused, a FIFO read as a stream.
  const std::string text = read_input_file(path, "scenario file", errc::scenario_format);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(errc::scenario_format,
                     path + ": not valid YAML at line " + std::to_string(e.mark.line + 1) + ", column " +
                         std::to_string(e.mark.column + 1) + ": " + e.msg,
                     {.file = path, .row = static_cast<std::size_t>(e.mark.line + 1)});
  }
  detail::check_quotes_closed(root, text, path);
  if (!root || root.IsNull()) throw InputError(errc::scenario_format, path + ": empty scenario file", {.file = path});
  ScenarioOptions o = options;
  if (o.base_dir.empty()) o.base_dir = std::filesystem::path(path).parent_path().string();
  return scenario_from_yaml(root, path, o);
}

}  // namespace frictionlab
