// Data files (CSV, MAT) and law files.
#include <pybind11/stl.h>

#include "cancellable.hpp"
#include "common.hpp"
#include "io/atomic_write.hpp"
#include "frictionlab/io/column_expression.hpp"
#include "frictionlab/io/columns.hpp"
#include "frictionlab/scenario/law_file.hpp"
#include "frictionlab/io/load.hpp"
#include "io/sha256.hpp"

namespace frictionlab::python {

void init_io(py::module_& m) {
  m.def("_load_dataset",
        [](const py::object& path, const std::string& delimiter, bool drop_invalid, const std::string& comment,
           const std::vector<std::string>& names, bool resample, double dt, double max_gap, const std::string& time,
           const std::string& format) {
          if (delimiter.size() > 1) throw std::invalid_argument("delimiter '" + delimiter + "': expected one character, or None to detect it");
          if (comment.size() > 1) throw std::invalid_argument("comment '" + comment + "': expected one character or ''");
          CsvOptions o;
          o.delimiter = delimiter.empty() ? '\0' : delimiter[0];
          o.drop_invalid = drop_invalid;
          o.comment = comment.empty() ? '\0' : comment[0];
          o.header = CsvHeader::detect;
          o.names = names;
          o.names_option = "names";
          const std::string file = path_arg(path, "load");
          const DataFormat data_format = parse_data_format(format, "format");
          // Reading and resampling without the GIL, stopped by Ctrl-C (a FIFO waits for its writer).
          Dataset d = run_cancellable([&] {
            Dataset d = load_dataset(file, o, data_format);
            if (!names.empty() && d.lines.empty()) {
              throw std::invalid_argument(d.where() + "names: names the columns of a CSV file; a MAT file's variables have their own "
                                          "names: " + d.describe_contents());
            }
            if (resample) {
              // The time column: as given, else "time" when the file has one, else the first column.
              std::string t = time;
              if (t.empty()) t = d.has_column("time") || d.column_names().empty() ? "time" : d.column_names().front();
              ResampleOptions r;
              r.dt = dt;
              r.max_gap = max_gap;
              r.dt_name = "resample";
              r.max_gap_name = "max_gap";
              resample_dataset(d, t, r);
            }
            return d;
          });
          py::list columns;  // (name, array) pairs in file order
          for (const auto& name : d.column_names()) columns.append(py::make_tuple(name, to_array(d.column(name))));
          py::dict scalars;
          for (const auto& [k, v] : d.scalars) scalars[py::str(k)] = v;
          std::vector<double> lines(d.lines.begin(), d.lines.end());
          py::dict info;
          info["header_row"] = d.header_row;
          info["warnings"] = d.warnings;
          info["unusable"] = d.unusable;
          info["contents"] = d.describe_contents();
          if (d.resampling) {
            const ResampleReport& s = *d.resampling;
            py::dict r;
            r["dt_min"] = s.dt_min;
            r["dt_median"] = s.dt_median;
            r["dt_max"] = s.dt_max;
            r["dt"] = s.dt;
            r["max_gap"] = s.max_gap;
            r["samples_in"] = s.samples_in;
            r["samples_out"] = s.samples_out;
            r["merged"] = s.merged;
            info["resampling"] = r;
          } else {
            info["resampling"] = py::none();
          }
          return py::make_tuple(columns, scalars, d.file, d.sha256, to_array(lines), info);
        },
        py::arg("path"), py::arg("delimiter") = "", py::arg("drop_invalid") = false, py::arg("comment") = "#",
        py::arg("names") = std::vector<std::string>{}, py::arg("resample") = false, py::arg("dt") = 0.0,
        py::arg("max_gap") = 0.0, py::arg("time") = "", py::arg("format") = "auto",
        "Reads a CSV (header row or none) or MAT file, optionally resampled onto a uniform grid: ([(name, column)], "
        "{scalar: value}, file, sha256, csv line numbers, {header_row, warnings, unusable, contents, resampling}).");

  m.def("_column_expression",
        [](const std::vector<std::pair<std::string, py::object>>& columns, const std::map<std::string, double>& scalars,
           const std::string& file, const std::vector<std::size_t>& lines, const std::string& expression) {
          Dataset d;
          d.file = file;
          d.scalars = scalars;
          // Non-finite samples are let through here: the expression names the row of one it uses.
          const ArraySpec spec{.min_size = 0, .finite = false};
          for (const auto& [name, values] : columns) d.add_column(name, vector_arg(values, "Data.eval", name, spec));
          if (lines.size() == static_cast<std::size_t>(d.rows())) d.lines = lines;
          return to_array(evaluate_column_expression(d, expression, "expression"));
        },
        py::arg("columns"), py::arg("scalars"), py::arg("file"), py::arg("lines"), py::arg("expression"),
        "The value of an expression of columns (io/column_expression.hpp) over [(name, column)] and {scalar: value}.");

  m.def("load_law", [](const py::object& p) {
    const std::string path = path_arg(p, "load_law");
    return run_cancellable([&] { return load_law(path); });  // a FIFO waits for its writer: without the GIL
  }, py::arg("path"),
        "Reads a friction law from a .yaml/.yml file ({law: NAME, params...}) or a .json file (the same, or the "
        "MODEL.json an identification writes). Raises ValueError naming the file and key on bad content.");

  m.def("_write_file_atomic", [](const py::object& p, const std::string& text, bool overwrite) {
    AtomicWriteOptions o;
    o.overwrite = overwrite;
    write_file_atomic(path_arg(p, "write"), text, o);
  }, py::arg("path"), py::arg("text"), py::arg("overwrite") = false,
     "Writes `text` to `path` through a temporary file and a rename (io/atomic_write.hpp): a failed write "
     "leaves no half-written file. ValueError when the file exists and overwrite is False.");
  m.def("sha256_file", [](const py::object& p) {
    const std::string path = path_arg(p, "sha256_file");
    return run_cancellable([&] { return sha256_file(path); });
  }, py::arg("path"), "Lowercase hex SHA-256 of a file's bytes (as in results' data.sha256).");
}

}  // namespace frictionlab::python
