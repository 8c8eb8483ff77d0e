// The registry of the Python module's identification methods (FRICTIONLAB_METHODS pairs each
// method's library side with its NAME_binding()), and the keywords made from the option tables.
#include "method.hpp"

#include <Python.h>

namespace frictionlab::python {

const std::vector<PyMethod>& py_methods() {
  static const std::vector<PyMethod> methods = [] {
    std::vector<PyMethod> all;
#define FRICTIONLAB_PY_METHOD(method) \
  all.push_back(method##_binding());  \
  all.back().name = method_info(MethodId::FRICTIONLAB_METHOD_ENUM(method)).name;
    FRICTIONLAB_METHODS(FRICTIONLAB_PY_METHOD)
#undef FRICTIONLAB_PY_METHOD
    return all;
  }();
  return methods;
}

namespace {

// A Python value as an OptionValue: bool, int (and numpy integers), float (and numpy floats),
// str, or a list/tuple of str.
OptionValue python_value(const py::handle& v, const std::string& spelled) {
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>();
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  if (PyLong_Check(v.ptr())) return v.cast<long long>();
  if (PyFloat_Check(v.ptr())) return v.cast<double>();
  const std::string type = py::str(v.get_type().attr("__name__"));
  if (type.rfind("int", 0) == 0 || type.rfind("uint", 0) == 0) return py::int_(py::reinterpret_borrow<py::object>(v)).cast<long long>();
  if (type.rfind("float", 0) == 0) return py::float_(py::reinterpret_borrow<py::object>(v)).cast<double>();
  if (type == "bool_") return py::bool_(py::reinterpret_borrow<py::object>(v)).cast<bool>();
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    std::vector<std::string> items;
    for (const auto& item : v) {
      if (!py::isinstance<py::str>(item))
        throw argument_type_error(spelled + ": expected a list of words, got an item of type " +
                                  std::string(py::str(item.get_type().attr("__name__"))));
      items.push_back(item.cast<std::string>());
    }
    return items;
  }
  throw argument_type_error(spelled + ": expected a number, a word or a list of words, got " + type);
}

}  // namespace

OptionValues option_values(const MethodInfo& method, const py::dict& keywords) {
  OptionValues values = method.values();
  for (const auto& [k, v] : keywords) {
    const std::string keyword = py::str(k);
    const OptionSpec* spec = nullptr;
    for (const auto& o : method.options)
      if (o.keyword() == keyword || std::find(o.deprecated_keywords.begin(), o.deprecated_keywords.end(), keyword) !=
                                        o.deprecated_keywords.end())
        spec = &o;
    if (!spec) {
      std::string names;
      for (const auto& o : method.options) names += (names.empty() ? "" : ", ") + o.keyword();
      throw std::invalid_argument(method.name + ": no option '" + keyword + "'; expected one of " + names);
    }
    if (v.is_none()) continue;
    // Named as the caller wrote it; a number under the table's keyword also by its command-line flag.
    const bool number = spec->type == OptionType::number || spec->type == OptionType::integer;
    const std::string spelled =
        method.name + ": " + keyword + (number && keyword == spec->keyword() ? " (--" + spec->name + ")" : "");
    const OptionValue value = python_value(v, spelled);
    // Text for a list or a number is read as the command line reads it ("a,b"; a number's words).
    if (const auto* text = std::get_if<std::string>(&value); text && spec->type == OptionType::list)
      values.set(spec->name, parse_option(*spec, *text, spelled), spelled);
    else
      values.set(spec->name, value, spelled);
  }
  return values;
}

void bind_option_tables(py::module_& m) {
  py::class_<OptionValues>(m, "OptionValues",
                           "The options of one run of a method, checked against its option table (internal: the "
                           "keyword functions make it with _option_values).")
      .def("given", &OptionValues::given, py::arg("name"))
      .def("text", &OptionValues::text, py::arg("name"))
      .def("to_json", [](const OptionValues& v, const std::string& axis) { return options_json(v, axis == "rotary"); },
           py::arg("axis") = "linear");
  m.def(
      "_option_values",
      [](const std::string& method, const py::dict& keywords) { return option_values(method_info(method), keywords); },
      py::arg("method"), py::arg("keywords"));
  // The result records the options that shaped it (its JSON "options": name, value, unit, given).
  py::class_<Result> result = py::reinterpret_borrow<py::class_<Result>>(py::type::of<Result>());
  result.def("_record_options", [](Result& r, const OptionValues& v) {
    r.json_sections["options"] = options_json(v, r.axis == Axis::rotary, r.diagnostics.texts);
  });
}

std::tuple<Eigen::VectorXd, Eigen::VectorXd, Eigen::VectorXd> time_force_velocity(const char* function,
                                                                                 const py::object& time,
                                                                                 const py::object& force,
                                                                                 const py::object& velocity) {
  Eigen::VectorXd t = vector_arg(time, function, "time"), f = vector_arg(force, function, "force"),
                  v = vector_arg(velocity, function, "velocity");
  same_length(function, {{"time", t.size()}, {"force", f.size()}, {"velocity", v.size()}});
  return {std::move(t), std::move(f), std::move(v)};
}

}  // namespace frictionlab::python
