// The circular test of a two-axis machine (analysis/contour.hpp): fl.analyze_contour.
#include <pybind11/stl.h>

#include <limits>
#include <sstream>

#include "common.hpp"
#include "frictionlab/analysis/contour.hpp"

namespace frictionlab::python {

void init_contour(py::module_& m) {
  py::class_<QuadrantGlitch>(m, "QuadrantGlitch", "The radial error spike near one axis reversal.")
      .def_readonly("reversal_deg", &QuadrantGlitch::reversal_deg, "The reversal: 0, 90, 180 or 270 deg.")
      .def_readonly("peak_m", &QuadrantGlitch::peak_m,
                    "Peak height over the median radial error within +-45 deg, m (outward positive).")
      .def_readonly("angle_deg", &QuadrantGlitch::angle_deg, "Angle of the peak, [0, 360) deg.")
      .def_readonly("extent_deg", &QuadrantGlitch::extent_deg, "Angular span above half the peak, deg.")
      .def_readonly("time", &QuadrantGlitch::time, "Time of the peak, s.")
      .def("__repr__", [](const QuadrantGlitch& g) {
        std::ostringstream o;
        o << "QuadrantGlitch(reversal_deg=" << g.reversal_deg << ", peak_m=" << g.peak_m << ", angle_deg=" << g.angle_deg
          << ", extent_deg=" << g.extent_deg << ")";
        return o.str();
      });

  py::class_<ContourResult>(m, "ContourResult", "A circular test: radial error, quadrant glitches, roundness.")
      .def_property_readonly("centre", [](const ContourResult& r) { return py::make_tuple(r.centre_x, r.centre_y); },
                             "Centre of the nominal circle (x, y), m.")
      .def_readonly("radius", &ContourResult::radius, "Nominal radius, m.")
      .def_readonly("centre_source", &ContourResult::centre_source, "'given', 'reference' or 'fit'.")
      .def_readonly("turns", &ContourResult::turns, "Turns the measured path covers.")
      .def_property_readonly("angle_deg", [](const ContourResult& r) { return to_array(r.angle_deg); },
                             "Angle of each sample about the centre, [0, 360) deg.")
      .def_property_readonly("radial_error", [](const ContourResult& r) { return to_array(r.radial_error); },
                             "r - R of each sample, m.")
      .def_property_readonly("x_error", [](const ContourResult& r) { return to_array(r.x_error); },
                             "x - x reference of each sample, m (empty without a reference).")
      .def_property_readonly("y_error", [](const ContourResult& r) { return to_array(r.y_error); },
                             "y - y reference of each sample, m (empty without a reference).")
      .def_property_readonly("glitches", [](const ContourResult& r) { return std::vector<QuadrantGlitch>(r.glitches.begin(), r.glitches.end()); },
                             "The four quadrant glitches, at 0, 90, 180 and 270 deg.")
      .def_property_readonly("quadrant_glitch_m", [](const ContourResult& r) {
        std::vector<double> v;
        for (const auto& g : r.glitches) v.push_back(g.peak_m);
        return to_array(v);
      }, "The four glitch peaks, m.")
      .def_readonly("roundness_m", &ContourResult::roundness_m, "max - min radial error, m.")
      .def_readonly("max_radial_error_m", &ContourResult::max_radial_error_m, "max |radial error|, m.")
      .def("__repr__", [](const ContourResult& r) {
        std::ostringstream o;
        o << "ContourResult(radius=" << r.radius << ", roundness_m=" << r.roundness_m
          << ", max_radial_error_m=" << r.max_radial_error_m << ")";
        return o.str();
      });

  m.def(
      "analyze_contour",
      [](py::object t, py::object x, py::object y, py::object xr, py::object yr, py::object centre, py::object radius,
         double extent_fraction) {
        ArraySpec optional;
        optional.optional = true;
        const char* f = "analyze_contour";
        const std::vector<double> tv = std_vector_arg(t, f, "t"), xv = std_vector_arg(x, f, "x"),
                                  yv = std_vector_arg(y, f, "y"), xrv = std_vector_arg(xr, f, "xr", optional),
                                  yrv = std_vector_arg(yr, f, "yr", optional);
        same_length(f, {{"t", tv.size()}, {"x", xv.size()}, {"y", yv.size()}, {"xr", xrv.size()}, {"yr", yrv.size()}});
        ContourOptions o;
        o.extent_fraction = extent_fraction;
        if (!centre.is_none()) {
          const std::vector<double> c = std_vector_arg(centre, f, "centre");
          if (c.size() != 2) throw std::invalid_argument("analyze_contour: argument centre: expected (x, y) in m");
          o.centre = std::array<double, 2>{c[0], c[1]};
        }
        if (!radius.is_none()) o.radius = number_arg(radius, f, "radius");
        return analyze_contour(tv, xv, yv, xrv, yrv, o);
      },
      py::arg("t"), py::arg("x"), py::arg("y"), py::arg("xr") = py::none(), py::arg("yr") = py::none(),
      py::arg("centre") = py::none(), py::arg("radius") = py::none(), py::arg("extent_fraction") = 0.5,
      "Circular test of a two-axis machine: t (s), measured x, y (m), optionally the reference xr, yr (m) or the "
      "nominal centre (x, y) and radius (m); default centre and radius from the reference, else a least-squares "
      "circle fit. Returns a ContourResult. Raises ValueError for fewer than 20 samples, NaN, unequal lengths, "
      "time not increasing, a reference that is not a circle, or a path covering less than one turn.");
}

}  // namespace frictionlab::python
