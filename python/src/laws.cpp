// Friction laws: construction from a dict, evaluation on numpy arrays, dynamic stepping.
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <span>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "common.hpp"

namespace frictionlab::python {

namespace {

// The shape of an array argument for messages: "(3,)", "(2, 4)", "()" for a scalar.
std::string shape_text(const py::array& a) {
  std::string out = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) out += (d ? ", " : "") + std::to_string(a.shape(d));
  return out + (a.ndim() == 1 ? ",)" : ")");
}

// numpy's broadcasting rule, checked before py::vectorize, whose own error is a bare RuntimeError:
// trailing dimensions equal or 1. \throws std::invalid_argument naming the function and the shapes.
void check_broadcast(const std::string& function, std::initializer_list<std::pair<const char*, const py::array*>> arrays) {
  std::vector<py::ssize_t> shape;
  std::string named;
  for (const auto& [name, a] : arrays) {
    named += std::string(named.empty() ? "" : " and ") + name + " " + shape_text(*a);
    const auto nd = static_cast<std::size_t>(a->ndim());
    if (nd > shape.size()) shape.insert(shape.begin(), nd - shape.size(), 1);
    for (std::size_t k = 0; k < nd; ++k) {
      py::ssize_t& s = shape[shape.size() - nd + k];
      const py::ssize_t n = a->shape(static_cast<py::ssize_t>(k));
      if (s == 1) s = n;
      else if (n != 1 && n != s)
        throw std::invalid_argument(function + ": the shapes of " + named +
                                    " do not match; expected equal shapes or a scalar (numpy broadcasting)");
    }
  }
}

// A law from a Python dict {"law": name, param: value, ...} (the same form as the YAML files).
FrictionLaw law_from_dict(const py::dict& d) {
  LawSpec spec;
  for (auto item : d) {
    const std::string key = py::cast<std::string>(py::str(item.first));
    py::handle value = item.second;
    // Text only where the law takes a name ('law', 'shape'); everywhere else a number or a
    // list of numbers, so that {'Fc': 'a'} is "must be a number", not "missing".
    const std::string expected = "FrictionLaw: law parameter '" + key + "': expected a number or a list of numbers";
    auto got = [&] { return value.is_none() ? std::string("None") : py::cast<std::string>(py::repr(value)); };
    if (key == "law" || key == "shape") {
      if (!py::isinstance<py::str>(value))
        throw argument_type_error("FrictionLaw: '" + key + "': expected a name (str), got " + got());
      if (key == "law") spec.name = py::cast<std::string>(value);
      else spec.strings[key] = py::cast<std::string>(value);
    } else if (py::isinstance<py::bool_>(value) || py::isinstance<py::str>(value) || value.is_none()) {
      throw argument_type_error(expected + ", got " + got());
    } else if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value) ||
               (py::isinstance<py::array>(value) && py::cast<py::array>(value).ndim() == 0)) {
      double x;
      try {
        x = py::cast<double>(value);
      } catch (const py::cast_error&) {
        throw argument_type_error(expected + ", got " + got());
      }
      if (!std::isfinite(x))
        throw std::invalid_argument("FrictionLaw: law parameter '" + key + "' is " + (std::isnan(x) ? "NaN" : "infinite") +
                                    "; expected a finite number");
      spec.scalars[key] = x;
    } else {
      ArraySpec list;
      list.min_size = 1;
      try {
        spec.arrays[key] = std_vector_arg(value, "FrictionLaw", "law parameter '" + key + "'", list);
      } catch (const argument_type_error&) {
        throw argument_type_error(expected + ", got " + got());
      }
    }
  }
  if (spec.name.empty()) throw std::invalid_argument("FrictionLaw: missing 'law' (one of frictionlab.law_names())");
  return FrictionLaw::from_spec(spec);
}

std::string law_repr(const FrictionLaw& law) {
  std::ostringstream s;
  s << "FrictionLaw('" << law.name() << "'";
  for (const auto& p : law.parameters()) s << ", " << p.name << "=" << p.value;
  s << ")";
  return s.str();
}

// The sliding force (N or N m) at v (m/s or rad/s): a float for a number, an array of v's shape
// for anything array-like, computed by one batch call (FrictionLaw::sliding(v, F): one dispatch,
// then a loop) on v itself when it is a C-contiguous float64 array, on a float64 copy otherwise.
py::object sliding_of(const FrictionLaw& law, const py::object& v) {
  if ((py::isinstance<py::float_>(v) || py::isinstance<py::int_>(v)) && !py::isinstance<py::bool_>(v))
    return py::float_(law.sliding(number_arg(v, "FrictionLaw.sliding", "v")));
  ArraySpec any;
  any.min_size = 0;
  any.any_shape = true;
  py::array_t<double, py::array::c_style> a;
  try {
    a = check_array(v, "FrictionLaw.sliding", "v", any);
  } catch (const argument_type_error& e) {
    const std::string w = e.what();
    const auto got = w.find(", got ");
    throw argument_type_error("FrictionLaw.sliding: argument v: expected a number or an array of numbers (m/s or rad/s)" +
                              (got == std::string::npos ? std::string() : w.substr(got)));
  }
  if (a.ndim() == 0) return py::float_(law.sliding(*a.data()));
  py::array_t<double> F(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()));
  const auto n = static_cast<std::size_t>(a.size());
  law.sliding(std::span<const double>(a.data(), n), std::span<double>(F.mutable_data(), n));
  return F;
}

}  // namespace

FrictionLaw law_arg(const py::handle& x) {
  if (py::isinstance<FrictionLaw>(x)) return py::cast<FrictionLaw>(x);
  if (py::isinstance<py::dict>(x)) return law_from_dict(py::reinterpret_borrow<py::dict>(x));
  throw std::invalid_argument("law: expected a FrictionLaw or a dict {'law': NAME, ...}");
}

py::dict law_to_dict(const FrictionLaw& law) {
  const LawSpec spec = law.to_spec();
  py::dict d;
  d["law"] = spec.name;
  for (const auto& [k, v] : spec.scalars) d[py::str(k)] = v;
  for (const auto& [k, v] : spec.arrays) d[py::str(k)] = v;
  for (const auto& [k, v] : spec.strings) d[py::str(k)] = v;
  return d;
}

void init_laws(py::module_& m) {
  py::class_<FrictionLaw>(m, "FrictionLaw", R"doc(
A friction law chosen by name, e.g. FrictionLaw({"law": "stribeck", "Fc": 1, "Fs": 1.5, "vs": 0.001, "Fv": 0.4}).
Forces in N (N m on a rotary axis), velocities in m/s (rad/s). Friction has the sign of velocity.
Raises ValueError naming the law and parameter for an unknown name, a missing or invalid parameter.)doc")
      .def(py::init(&law_from_dict), py::arg("spec"))
      .def_property_readonly("name", &FrictionLaw::name, "The law's name, e.g. 'stribeck'.")
      .def_property_readonly("is_dynamic", &FrictionLaw::is_dynamic, "True for laws with internal state (dahl, lugre, elastoplastic, gms).")
      .def_property_readonly("num_states", &FrictionLaw::num_states, "Number of internal states (0 for static laws).")
      .def_property_readonly("parameters", [](const FrictionLaw& l) {
        py::dict d;
        for (const auto& p : l.parameters()) d[py::str(p.name)] = p.value;
        return d;
      }, "Scalar parameters by name (SI units).")
      .def("units", [](const FrictionLaw& l, const std::string& axis) {
        py::dict d;
        const Axis a = parse_axis(axis);
        for (const auto& p : l.parameters()) d[py::str(p.name)] = std::string(unit(p.quantity, a));
        return d;
      }, py::arg("axis") = "linear", "Unit of each scalar parameter on a 'linear' or 'rotary' axis, e.g. {'Fc': 'N', 'Fv': 'N s/m'}.")
      .def("to_dict", &law_to_dict, "The law as a dict, the form the constructor accepts.")
      .def("sliding", &sliding_of, py::arg("v"),
           "Friction force (N or N m) while sliding at velocity v (m/s or rad/s): a float for a number, an array "
           "of v's shape for an array (evaluated in one call, vectorised). For dynamic laws: the steady-state "
           "force at constant v.")
      .def("__call__", &sliding_of, py::arg("v"),
           "Same as sliding(v): friction force (N or N m) at velocity v (m/s or rad/s).")
      .def("force", [](const FrictionLaw& l, py::object v, py::object applied) {
        ArraySpec any;
        any.min_size = 0;
        any.any_shape = true;
        const auto va = check_array(v, "FrictionLaw.force", "v", any);
        const auto aa = check_array(applied, "FrictionLaw.force", "applied", any);
        check_broadcast("FrictionLaw.force", {{"v", &va}, {"applied", &aa}});
        return py::vectorize([&l](double x, double a) { return l.force(x, a); })(va, aa);
      }, py::arg("v"), py::arg("applied"),
           "Static law force with stiction (N or N m): at v == 0 it balances `applied` up to the breakaway level.")
      .def_property_readonly("breakaway", [](const FrictionLaw& l) {
        return py::make_tuple(l.breakaway_positive(), l.breakaway_negative());
      }, "(positive, negative) breakaway levels (N or N m) a stuck contact holds.")
      .def("step", [](const FrictionLaw& l, py::object v, py::object dt_arg, py::object z0_arg) {
        const double dt = number_arg(dt_arg, "FrictionLaw.step", "dt");
        ArraySpec states;
        states.min_size = 0;
        states.optional = true;
        std::vector<double> z = std_vector_arg(z0_arg, "FrictionLaw.step", "z0", states);
        if (z0_arg.is_none()) z.assign(static_cast<std::size_t>(l.num_states()), 0.0);
        if (static_cast<int>(z.size()) != l.num_states())
          throw std::invalid_argument("z0 has " + std::to_string(z.size()) + " entries; " + l.name() + " has " +
                                      std::to_string(l.num_states()) + " states");
        ArraySpec any_length;
        any_length.min_size = 0;
        const std::vector<double> vin = std_vector_arg(v, "FrictionLaw.step", "v", any_length);
        py::array_t<double> out(static_cast<py::ssize_t>(vin.size()));
        double* o = out.mutable_data();
        for (std::size_t i = 0; i < vin.size(); ++i) o[i] = l.step(z, vin[i], dt);
        return py::make_tuple(out, z);
      }, py::arg("v"), py::arg("dt"), py::arg("z0") = py::none(),
      "Fixed-step evaluation of a dynamic law over a velocity sequence v (m/s or rad/s, 1-D) at step dt (s): "
      "returns (force array in N or N m, final state in m or rad). Raises ValueError for a static law.")
      .def_property_readonly("effects", [](const FrictionLaw& l) {
        // The effect keys of to_dict(): the law's parameters left out.
        LawSpec plain = l.without_effects().to_spec(), all = l.to_spec();
        py::dict d;
        for (const auto& [k, v] : all.scalars)
          if (!plain.scalars.count(k)) d[py::str(k)] = v;
        for (const auto& [k, v] : all.arrays)
          if (!plain.arrays.count(k)) d[py::str(k)] = v;
        return d;
      }, "The law's load, temperature and ripple parameters (mu_load, T_ref, Fv_per_K, ripple_period, ripple_a, ...) "
         "by name; empty for a plain velocity law.")
      .def("sliding_at", [](const FrictionLaw& l, py::object v, double load, std::optional<double> temperature, double position) {
        ArraySpec any;
        any.min_size = 0;
        any.any_shape = true;
        const auto va = check_array(v, "FrictionLaw.sliding_at", "v", any);
        Conditions c{load, temperature, position};
        return py::vectorize([&](double x) { return l.sliding(x, c); })(va);
      }, py::arg("v"), py::arg("load") = 0.0, py::arg("temperature") = py::none(), py::arg("position") = 0.0,
      "Sliding force (N or N m) at velocity v (m/s or rad/s) with the levels moved to the load (N or N m; its "
      "magnitude counts) and temperature (degC or K; None = T_ref); the ripple is not included (add ripple(q)). "
      "Raises frictionlab.Error (code law.parameter) for a temperature that makes a coefficient negative.")
      .def("breakaway_at", [](const FrictionLaw& l, double load, std::optional<double> temperature) {
        Conditions c{load, temperature, 0.0};
        return py::make_tuple(l.breakaway_positive(c), l.breakaway_negative(c));
      }, py::arg("load") = 0.0, py::arg("temperature") = py::none(),
      "(positive, negative) breakaway levels (N or N m) at the load (N or N m) and temperature (degC or K).")
      .def("ripple", [](const FrictionLaw& l, py::object q) {
        ArraySpec any;
        any.min_size = 0;
        any.any_shape = true;
        const auto qa = check_array(q, "FrictionLaw.ripple", "q", any);
        return py::vectorize([&](double x) { return l.ripple(x); })(qa);
      }, py::arg("q"), "Position ripple force r(q) (N or N m) at positions q (m or rad); 0 without a ripple.")
      .def("force_at", [](const FrictionLaw& l, py::object v, py::object applied, double load, std::optional<double> temperature,
                          py::object position) {
        ArraySpec any;
        any.min_size = 0;
        any.any_shape = true;
        const auto va = check_array(v, "FrictionLaw.force_at", "v", any);
        const auto aa = check_array(applied, "FrictionLaw.force_at", "applied", any);
        const auto qa = check_array(position, "FrictionLaw.force_at", "position", any);
        check_broadcast("FrictionLaw.force_at", {{"v", &va}, {"applied", &aa}, {"position", &qa}});
        return py::vectorize([&](double x, double a, double q) { return l.force(x, a, Conditions{load, temperature, q}); })(va, aa, qa);
      }, py::arg("v"), py::arg("applied"), py::arg("load") = 0.0, py::arg("temperature") = py::none(), py::arg("position") = 0.0,
      "Static law's total friction (N or N m) with stiction at the conditions, ripple included: at v == 0 it balances "
      "`applied` while applied - ripple(position) lies within the breakaway levels at that load and temperature.")
      .def("__eq__", [](const FrictionLaw& a, const FrictionLaw& b) {
        const LawSpec x = a.to_spec(), y = b.to_spec();
        return x.name == y.name && x.scalars == y.scalars && x.arrays == y.arrays && x.strings == y.strings;
      })
      .def(py::pickle([](const FrictionLaw& l) { return law_to_dict(l); },
                      [](const py::dict& d) { return law_from_dict(d); }))
      .def("__repr__", &law_repr);

  m.def("law_names", &FrictionLaw::names, "Every friction law name the FrictionLaw constructor accepts.");
}

}  // namespace frictionlab::python
