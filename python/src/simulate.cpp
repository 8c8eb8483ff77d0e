// Simulation: scenarios (from a YAML file or a dict of the same form) and trajectories.
#include <pybind11/stl.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <sstream>
#include <vector>

#include "cancellable.hpp"
#include "common.hpp"
#include "frictionlab/control/compensation_spec.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/simulate/closed_loop.hpp"
#include "frictionlab/simulate/emps_pd_loop.hpp"
#include "frictionlab/simulate/simulate.hpp"
#include "frictionlab/simulate/xy_table.hpp"

namespace frictionlab::python {

namespace {

// Deeper nesting than this is refused (the scenario reader's own limit); a real scenario is a few
// levels deep. With the check of a container that holds itself, the conversion cannot recurse
// without end and crash the interpreter.
constexpr std::size_t kMaxDepth = 100;

// A Python value (dict, list, tuple, numpy array, number, str, bool, None) as a YAML node, so
// that a dict goes through the same reader, checks and messages as a scenario file. `open` holds
// the containers being converted, outermost first.
YAML::Node to_yaml(const py::handle& x, const std::string& where, std::vector<const PyObject*>& open) {
  if (x.is_none()) return YAML::Node(YAML::NodeType::Null);
  if (py::isinstance<py::bool_>(x)) return YAML::Node(py::cast<bool>(x) ? "true" : "false");
  if (py::isinstance<py::str>(x)) return YAML::Node(py::cast<std::string>(x));
  const bool is_dict = py::isinstance<py::dict>(x);
  const bool is_sequence = py::isinstance<py::list>(x) || py::isinstance<py::tuple>(x) ||
                           (py::isinstance<py::array>(x) && py::cast<py::array>(x).ndim() > 0);
  if (is_dict || is_sequence) {
    if (std::find(open.begin(), open.end(), x.ptr()) != open.end())
      throw std::invalid_argument(where + ": the " + (is_dict ? "dict" : "list") +
                                  " contains itself; expected a tree of dicts, lists and values");
    if (open.size() >= kMaxDepth)
      throw std::invalid_argument(where + ": nested more than " + std::to_string(kMaxDepth) +
                                  " levels deep; expected a scenario of a few levels");
    open.push_back(x.ptr());
    YAML::Node n(is_dict ? YAML::NodeType::Map : YAML::NodeType::Sequence);
    if (is_dict) {
      for (auto item : py::reinterpret_borrow<py::dict>(x)) {
        const std::string key = py::cast<std::string>(py::str(item.first));
        n[key] = to_yaml(item.second, where + ": " + key, open);
      }
    } else {
      for (auto item : py::iter(x)) n.push_back(to_yaml(item, where, open));
    }
    open.pop_back();
    return n;
  }
  try {
    const double v = py::cast<double>(py::float_(py::reinterpret_borrow<py::object>(x)));
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return YAML::Node(std::string(buf, r.ptr));
  } catch (const py::error_already_set&) {
    throw std::invalid_argument(where + ": expected a number, text, list or dict, got " +
                                py::cast<std::string>(py::str(py::type::of(x).attr("__name__"))));
  }
}

YAML::Node to_yaml(const py::handle& x, const std::string& where) {
  std::vector<const PyObject*> open;
  return to_yaml(x, where, open);
}

// What the scenario's loop compensates with: the type, per axis on an xy-table; None without one.
py::object compensation_of(const Scenario& s) {
  auto type_of = [](const Compensator* c) -> py::object { return c ? py::object(py::str(c->type())) : py::none(); };
  if (const auto* loop = dynamic_cast<const ClosedLoop*>(s.plant.get())) return type_of(loop->compensator());
  if (const auto* loop = dynamic_cast<const EmpsPdLoop*>(s.plant.get())) return type_of(loop->compensator());
  if (const auto* xy = dynamic_cast<const XyTable*>(s.plant.get())) {
    py::dict d;
    d["x"] = type_of(xy->axis(0).compensator.get());
    d["y"] = type_of(xy->axis(1).compensator.get());
    return d;
  }
  return py::none();
}

constexpr const char* kSetWhere = "Scenario.compensation";

// None, a type name or {"type": TYPE, parameter: value, ...} (control/compensation_spec.hpp), as
// the compensator of a body of inertia M (kg or kg m^2, the disturbance observer's default)
// whose friction `law` is (the exact model); null for None.
std::shared_ptr<const Compensator> compensator_arg(const py::handle& c, const FrictionLaw& law, double M) {
  if (c.is_none()) return nullptr;
  const auto [type, values] = compensation_arg(c, "Scenario", "compensation");
  try {
    return make_compensator(make_compensation(type, values, M > 0 ? std::optional<double>(M) : std::nullopt), &law);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(kSetWhere) + ": " + e.what());
  }
}

// Rebuilds the scenario's loop with the compensation `c` (see the property's doc).
void set_compensation(Scenario& s, const py::object& c) {
  const std::shared_ptr<const Plant>& plant = s.plant;
  if (const auto* loop = dynamic_cast<const ClosedLoop*>(plant.get())) {
    const std::shared_ptr<const Plant> inner(plant, &loop->inner());  // shares the loop's ownership
    s.plant = close_loop(inner, loop->controller(), compensator_arg(c, s.law, loop->inertia()));
  } else if (const auto* pd = dynamic_cast<const EmpsPdLoop*>(plant.get())) {
    const std::shared_ptr<const Plant> inner(plant, &pd->inner());
    s.plant = close_loop(inner, pd->params(), compensator_arg(c, s.law, pd->inertia()));
  } else if (const auto* xy = dynamic_cast<const XyTable*>(plant.get())) {
    XyAxis axes[2] = {xy->axis(0), xy->axis(1)};
    const bool per_axis = py::isinstance<py::dict>(c) && !c.contains("type");
    for (int i = 0; i < 2; ++i) {
      const char* name = i == 0 ? "x" : "y";
      if (per_axis && !c.contains(name)) continue;  // an axis left out keeps its compensation
      const py::object spec = per_axis ? py::object(c[name]) : c;
      axes[i].compensator = compensator_arg(spec, axes[i].law ? *axes[i].law : s.law, xy->inertia(i));
    }
    if (per_axis)
      for (auto item : py::reinterpret_borrow<py::dict>(c)) {
        const std::string k = py::cast<std::string>(py::str(item.first));
        if (k != "x" && k != "y")
          throw std::invalid_argument(std::string(kSetWhere) + ": unknown key '" + k +
                                      "'; expected 'type' (both axes) or the axes 'x' and 'y'");
      }
    s.plant = std::make_shared<const XyTable>(axes[0], axes[1], xy->timing());
  } else {
    throw std::invalid_argument(std::string(kSetWhere) + ": plant '" + (plant ? plant->type() : std::string()) +
                                "' has no controller to compensate in (give the scenario a controller)");
  }
}

py::dict trajectory_dict(const Trajectory& tr) {
  py::dict d;
  for (const auto& n : tr.names()) d[py::str(n)] = to_array(tr.column(n));
  return d;
}

}  // namespace

void init_simulate(py::module_& m) {
  py::class_<Scenario>(m, "Scenario", R"doc(
A simulation problem: plant, friction law, input and options, read from a scenario YAML file
(Scenario.load(path)) or a dict of the same form (Scenario(dict)). Times in s, rates in Hz.)doc")
      .def(py::init([](const py::dict& d, const std::string& where, const py::object& base_dir) {
             ScenarioOptions o;
             if (!base_dir.is_none()) o.base_dir = path_arg(base_dir, "Scenario", "base_dir");
             const YAML::Node yaml = to_yaml(d, where);
             // The files it names (data:, a model:) are read without the GIL, stopped by Ctrl-C.
             return run_cancellable([&] { return scenario_from_yaml(yaml, where, o); });
           }),
           py::arg("spec"), py::arg("where") = "scenario", py::arg("base_dir") = py::none(),
           "From a dict of the scenario-file form; `where` prefixes error messages. Relative file names "
           "(data, a compensation's model) are resolved from `base_dir` (default: the working directory).")
      .def_static("load", [](const py::object& p) {
        const std::string path = path_arg(p, "Scenario.load");
        return run_cancellable([&] { return load_scenario(path); });  // a file read: without the GIL
      }, py::arg("path"),
                  "Reads a scenario YAML file; ValueError naming the file, key and value on bad content.")
      .def_property("law", [](const Scenario& s) { return s.law; },
                    [](Scenario& s, const py::object& law) { s.law = law_arg(law); },
                    "Friction law on the plant's friction body (FrictionLaw; a dict is accepted when set).")
      .def_property_readonly("plant", [](const Scenario& s) { return s.plant ? s.plant->type() : std::string(); },
                             "Plant type ('axis', 'pendulum', 'spring-base', 'dc-motor', 'velocity-drive', closed loops).")
      .def_property_readonly(
          "axis",
          [](const Scenario& s) {
            return std::string(s.plant && s.plant->motion_axis() == Axis::rotary ? "rotary" : "linear");
          },
          "How the plant moves: 'rotary' (rad, N m: pendulum, dc-motor) or 'linear' (m, N: the others).")
      .def_property("duration", [](const Scenario& s) { return s.options.duration; },
                    [](Scenario& s, double v) { s.options.duration = v; }, "Simulated time, s (> 0).")
      .def_property("output_rate", [](const Scenario& s) { return s.options.output_rate; },
                    [](Scenario& s, double v) { s.options.output_rate = v; }, "Output samples per second, Hz (> 0).")
      .def_property("initial_position", [](const Scenario& s) { return s.options.initial_position; },
                    [](Scenario& s, double v) { s.options.initial_position = v; }, "Initial position, m or rad.")
      .def_property("initial_velocity", [](const Scenario& s) { return s.options.initial_velocity; },
                    [](Scenario& s, double v) { s.options.initial_velocity = v; }, "Initial velocity, m/s or rad/s.")
      .def_property("compensation", &compensation_of, &set_compensation,
                    "The friction compensation of the scenario's controller (pid or emps-pd): its type "
                    "('feedforward', 'feedback', 'lugre-observer', 'disturbance-observer') or None; for an xy-table a "
                    "dict {'x': type or None, 'y': ...}. Set it to None, a type name or a dict {'type': NAME, "
                    "parameter: value} (band, dead_band, gain, bandwidth, inertia in SI units) to compensate with the "
                    "scenario's own law (the exact model; an xy-table axis: its own law) and the plant's inertia as "
                    "the disturbance observer's default; on an xy-table a dict {'x': ..., 'y': ...} sets the axes "
                    "one by one. ValueError naming the parameter for a bad value or a law that does not fit.")
      .def_property_readonly("solver", [](const Scenario& s) { return std::string(solver_mode_name(s.options.mode)); },
                             "Requested solver mode ('auto', 'hybrid', 'stiff', 'fixed-step').")
      .def("__copy__", [](const Scenario& s) { return s; })
      .def("__repr__", [](const Scenario& s) {
        std::ostringstream o;
        o << "Scenario(plant='" << (s.plant ? s.plant->type() : "") << "', law='" << s.law.name()
          << "', input='" << InputSignal::shape_name(s.input.shape) << "', duration=" << s.options.duration
          << ", output_rate=" << s.options.output_rate << ")";
        return o.str();
      });

  py::class_<Trajectory>(m, "Trajectory", R"doc(
Sampled simulation result, a read-only mapping of column name to numpy array:
time (s), position (m or rad), velocity (m/s or rad/s), friction (N or N m), applied (N or N m,
net non-friction force), current (A), voltage (V), reference (input signal), stuck (1 while stuck).
A plant with several contacts names them by contact: x.position, x.velocity, ..., x.drive, y.position, ...
dict(trajectory) gives the columns; also law_state, switches, stats, to_csv().)doc")
      .def("__getitem__", [](const Trajectory& t, const std::string& name) {
        try {
          return to_array(t.column(name));
        } catch (const std::invalid_argument& e) {
          throw py::key_error(e.what());
        }
      })
      .def("__len__", [](const Trajectory& t) { return t.rows(); })
      .def("__iter__", [](const Trajectory& t) { return py::iter(py::cast(t.names())); })
      .def("__contains__", [](const Trajectory& t, const std::string& n) {
        const auto names = t.names();
        return std::find(names.begin(), names.end(), n) != names.end();
      })
      .def("keys", [](const Trajectory& t) { return t.names(); }, "Column names in CSV order.")
      .def("to_dict", &trajectory_dict, "The columns as a dict of numpy arrays.")
      .def_property_readonly("rows", &Trajectory::rows, "Number of samples.")
      .def_property_readonly("law_state", [](const Trajectory& t) {
        py::array_t<double> a({static_cast<py::ssize_t>(t.law_state.size()), static_cast<py::ssize_t>(t.rows())});
        auto w = a.mutable_unchecked<2>();
        for (std::size_t i = 0; i < t.law_state.size(); ++i)
          for (std::size_t k = 0; k < t.rows(); ++k) w(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(k)) = t.law_state[i][k];
        return a;
      }, "Internal states of a dynamic law, shape (num_states, rows), m or rad; (0, rows) for static laws.")
      .def_property_readonly("switches", [](const Trajectory& t) {
        py::list l;
        for (const auto& s : t.switches) {
          py::dict d;
          d["time"] = s.time;
          d["kind"] = switch_kind_name(s.kind);
          d["position"] = s.position;
          d["applied"] = s.applied;
          d["direction"] = s.direction;
          d["contact"] = s.contact;
          l.append(d);
        }
        return l;
      }, "Mode switches of the hybrid solver: dicts {time (s), kind ('breakaway'|'stick'|'reversal'|'impact'), position, applied (N or N m), direction, contact (index)}.")
      .def_property_readonly("plant_events", [](const Trajectory& t) {
        py::list l;
        for (const auto& e : t.plant_events) {
          py::dict d;
          d["time"] = e.time;
          d["index"] = e.index;
          l.append(d);
        }
        return l;
      }, "The plant's own events: dicts {time (s), index}; a backlash: 0 the forward flank reached, 1 the "
         "backward flank, 2 a separation; a compensator: the edges of its velocity band.")
      .def_property_readonly("stats", [](const Trajectory& t) {
        py::dict d;
        d["steps"] = t.stats.steps;
        d["rhs_evaluations"] = t.stats.rhs_evaluations;
        d["jacobian_rhs_evaluations"] = t.stats.jacobian_rhs_evaluations;
        d["restarts"] = t.stats.restarts;
        d["solver"] = std::string(t.stats.solver);
        return d;
      }, "Integrator counters and the solver used: steps, rhs_evaluations, jacobian_rhs_evaluations (right-hand "
         "sides of difference-quotient Newton matrices; 0 with an analytic Jacobian), restarts, solver.")
      .def("to_csv", &Trajectory::to_csv, "The CSV text `frictionlab simulate -o` writes.")
      .def("__repr__", [](const Trajectory& t) {
        std::ostringstream o;
        o << "Trajectory(rows=" << t.rows();
        if (t.rows()) o << ", t=" << t.time.front() << ".." << t.time.back() << " s";
        o << ", solver='" << t.stats.solver << "', switches=" << t.switches.size() << ")";
        return o.str();
      });

  m.def("_simulate", [](const Scenario& s) {
    return run_cancellable([&] { return simulate(s); });
  }, py::arg("scenario"));
}

}  // namespace frictionlab::python
