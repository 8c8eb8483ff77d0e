// Data files (CSV, MAT) and law files.
#include <pybind11/stl.h>

#include "common.hpp"
#include "frictionlab/io/law_file.hpp"
#include "frictionlab/io/load.hpp"
#include "frictionlab/io/sha256.hpp"

namespace frictionlab::python {

void init_io(py::module_& m) {
  m.def("_load_dataset", [](const py::object& path, const std::string& delimiter, bool drop_invalid, const std::string& comment) {
        if (delimiter.size() != 1) throw std::invalid_argument("delimiter '" + delimiter + "': expected one character");
        if (comment.size() > 1) throw std::invalid_argument("comment '" + comment + "': expected one character or ''");
        CsvOptions o;
        o.delimiter = delimiter[0];
        o.drop_invalid = drop_invalid;
        o.comment = comment.empty() ? '\0' : comment[0];
        const Dataset d = load_dataset(path_arg(path, "load"), o);
        py::list columns;  // (name, array) pairs in file order
        for (const auto& name : d.column_names()) columns.append(py::make_tuple(name, to_array(d.column(name))));
        py::dict scalars;
        for (const auto& [k, v] : d.scalars) scalars[py::str(k)] = v;
        std::vector<double> lines(d.lines.begin(), d.lines.end());
        return py::make_tuple(columns, scalars, d.file, d.sha256, to_array(lines));
      },
      py::arg("path"), py::arg("delimiter") = ",", py::arg("drop_invalid") = false, py::arg("comment") = "#",
      "Reads a CSV (header row) or MAT file: ([(name, column)], {scalar: value}, file, sha256, csv line numbers).");

  m.def("load_law", [](const py::object& p) { return load_law(path_arg(p, "load_law")); }, py::arg("path"),
        "Reads a friction law from a .yaml/.yml file ({law: NAME, params...}) or a .json file (the same, or the "
        "MODEL.json an identification writes). Raises ValueError naming the file and key on bad content.");

  m.def("sha256_file", [](const py::object& p) { return sha256_file(path_arg(p, "sha256_file")); }, py::arg("path"), "Lowercase hex SHA-256 of a file's bytes (as in results' data.sha256).");
}

}  // namespace frictionlab::python
