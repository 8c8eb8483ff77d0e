// Analyses of motion records: decay envelope and stick-slip detection; the fleet drift table.
#include <pybind11/stl.h>

#include <cmath>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "cancellable.hpp"
#include "common.hpp"
#include "frictionlab/analysis/drift.hpp"
#include "frictionlab/analysis/envelope.hpp"
#include "frictionlab/analysis/stick_slip.hpp"
#include "fleet/map_run.hpp"

namespace frictionlab::python {

namespace {
py::array_t<double> intervals(const std::vector<TimeInterval>& v) {
  py::array_t<double> a({static_cast<py::ssize_t>(v.size()), py::ssize_t{2}});
  auto w = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i) {
    w(static_cast<py::ssize_t>(i), 0) = v[i].start;
    w(static_cast<py::ssize_t>(i), 1) = v[i].end;
  }
  return a;
}
}  // namespace

void init_analysis(py::module_& m) {
  py::class_<EnvelopeOptions>(m, "EnvelopeOptions", "Options of decay_envelope.")
      .def(py::init<>())
      .def_readwrite("none_tolerance", &EnvelopeOptions::none_tolerance, "Relative amplitude loss below which the kind is 'none' (0.02).")
      .def_readwrite("mixed_gain", &EnvelopeOptions::mixed_gain, "Mixed model must beat the best 2-parameter rms by this factor (0.5).")
      .def_readwrite("fit_tolerance", &EnvelopeOptions::fit_tolerance, "A 2-parameter model with relative rms below this is kept (0.01).")
      .def_readwrite("min_relative_amplitude", &EnvelopeOptions::min_relative_amplitude, "Smaller half swings are ignored (1e-3 of the largest).");

  py::class_<EnvelopeFit>(m, "EnvelopeFit",
                          "A(t) = p exp(-lambda (t - t1)) + q with t1 the first peak time (linear model: q + slope t); "
                          "evaluate with EnvelopeResult.envelope(t).")
      .def_readonly("lambda_", &EnvelopeFit::lambda, "Decay rate, 1/s (0 for the linear model).")
      .def_readonly("p", &EnvelopeFit::p, "Position unit.")
      .def_readonly("q", &EnvelopeFit::q, "Position unit (linear model: intercept).")
      .def_readonly("slope", &EnvelopeFit::slope, "Linear model: position unit per s.")
      .def_readonly("relative_rms", &EnvelopeFit::relative_rms, "rms residual / mean amplitude.")
      .def("__repr__", [](const EnvelopeFit& f) {
        std::ostringstream o;
        o << "EnvelopeFit(lambda_=" << f.lambda << ", p=" << f.p << ", q=" << f.q << ", slope=" << f.slope
          << ", relative_rms=" << f.relative_rms << ")";
        return o.str();
      });

  py::class_<EnvelopeResult>(m, "EnvelopeResult", "Decay envelope of a free oscillation.")
      .def_property_readonly("peak_times", [](const EnvelopeResult& r) { return to_array(r.peak_times); }, "Time of each extreme after the first, s.")
      .def_property_readonly("amplitudes", [](const EnvelopeResult& r) { return to_array(r.amplitudes); }, "Half swings, position unit.")
      .def_readonly("half_period", &EnvelopeResult::half_period, "Mean time between extremes, s.")
      .def_property_readonly("kind", [](const EnvelopeResult& r) { return std::string(decay_kind_name(r.kind)); },
                             "'none', 'linear' (Coulomb), 'exponential' (viscous) or 'mixed'.")
      .def_readonly("linear", &EnvelopeResult::linear, "Linear envelope fit.")
      .def_readonly("exponential", &EnvelopeResult::exponential, "Exponential envelope fit.")
      .def_readonly("mixed", &EnvelopeResult::mixed, "Mixed envelope fit.")
      .def_property_readonly("fit", [](const EnvelopeResult& r) -> const EnvelopeFit& {
        switch (r.kind) {
          case DecayKind::linear: return r.linear;
          case DecayKind::mixed: return r.mixed;
          default: return r.exponential;
        }
      }, py::return_value_policy::copy, "The fit of the chosen kind (exponential for 'none').")
      .def("envelope", [](const EnvelopeResult& r, py::object t, const std::string& kind) {
        const EnvelopeFit* f = kind == "linear" ? &r.linear : kind == "exponential" ? &r.exponential : kind == "mixed" ? &r.mixed : nullptr;
        if (kind.empty()) f = r.kind == DecayKind::linear ? &r.linear : r.kind == DecayKind::mixed ? &r.mixed : &r.exponential;
        if (!f) throw std::invalid_argument("envelope kind '" + kind + "': expected linear, exponential or mixed");
        const bool linear = f == &r.linear;
        const double t1 = r.peak_times.empty() ? 0.0 : r.peak_times.front();
        const EnvelopeFit fit = *f;
        return py::vectorize([fit, linear, t1](double x) {
          return linear ? fit.q + fit.slope * x : fit.p * std::exp(-fit.lambda * (x - t1)) + fit.q;
        })(t);
      }, py::arg("t"), py::arg("kind") = "",
         "Amplitude (position unit) of the fitted envelope at times t (s): the detected kind's fit, or kind = "
         "'linear', 'exponential', 'mixed'. Exponential fits run from the first peak time.")
      .def_readonly("decrement_per_half_cycle", &EnvelopeResult::decrement_per_half_cycle, "Linear: amplitude lost per half cycle, position unit.")
      .def_readonly("log_decrement", &EnvelopeResult::log_decrement, "Exponential: logarithmic decrement per full cycle.")
      .def_readonly("decay_fraction", &EnvelopeResult::decay_fraction, "1 - last amplitude / first amplitude.")
      .def("__repr__", [](const EnvelopeResult& r) {
        std::ostringstream o;
        o << "EnvelopeResult(kind='" << decay_kind_name(r.kind) << "', half_cycles=" << r.amplitudes.size()
          << ", half_period=" << r.half_period << ", decay_fraction=" << r.decay_fraction << ")";
        return o.str();
      });

  py::class_<StickSlipOptions>(m, "StickSlipOptions", "Options of detect_stick_slip.")
      .def(py::init<>())
      .def_readwrite("velocity_threshold", &StickSlipOptions::velocity_threshold, "|v| at or below is stuck, m/s or rad/s (0: automatic).")
      .def_readwrite("min_slip_duration", &StickSlipOptions::min_slip_duration, "Shorter slips merge into the stick, s (0).");

  py::class_<StickSlipResult>(m, "StickSlipResult", "Stick and slip intervals of a record (forces in the force signal's unit).")
      .def_property_readonly("stick", [](const StickSlipResult& r) { return intervals(r.stick); }, "Stuck intervals, shape (n, 2): start, end in s.")
      .def_property_readonly("slip", [](const StickSlipResult& r) { return intervals(r.slip); }, "Sliding intervals, shape (n, 2), s.")
      .def_readonly("velocity_threshold", &StickSlipResult::velocity_threshold, "Threshold used, m/s or rad/s.")
      .def_readonly("period", &StickSlipResult::period, "Mean time between slip starts, s (NaN with < 2 slips).")
      .def_readonly("peak_slip_velocity", &StickSlipResult::peak_slip_velocity, "Largest |v| during slips, m/s or rad/s.")
      .def_readonly("mean_slip_duration", &StickSlipResult::mean_slip_duration, "s, over complete slips.")
      .def_property_readonly("breakaway_force", [](const StickSlipResult& r) { return to_array(r.breakaway_force); }, "Force at each breakaway.")
      .def_property_readonly("restick_force", [](const StickSlipResult& r) { return to_array(r.restick_force); }, "Force at each re-stick.")
      .def_readonly("mean_breakaway_force", &StickSlipResult::mean_breakaway_force)
      .def_readonly("mean_restick_force", &StickSlipResult::mean_restick_force)
      .def_readonly("mean_force_drop", &StickSlipResult::mean_force_drop, "Mean (breakaway - re-stick) force.")
      .def("__repr__", [](const StickSlipResult& r) {
        std::ostringstream o;
        o << "StickSlipResult(slips=" << r.slip.size() << ", period=" << r.period
          << ", peak_slip_velocity=" << r.peak_slip_velocity << ", mean_force_drop=" << r.mean_force_drop << ")";
        return o.str();
      });

  m.def("_decay_envelope", [](py::object t, py::object x, const EnvelopeOptions& o) {
    // Unequal lengths: the library's own message ("decay envelope: time has ... samples").
    const std::vector<double> tv = std_vector_arg(t, "decay_envelope", "t"), xv = std_vector_arg(x, "decay_envelope", "x");
    return decay_envelope(tv, xv, o);
  });
  m.def("_detect_stick_slip", [](py::object t, py::object v, py::object force, const StickSlipOptions& o) {
    ArraySpec optional;
    optional.optional = true;
    const std::vector<double> tv = std_vector_arg(t, "detect_stick_slip", "t"), vv = std_vector_arg(v, "detect_stick_slip", "v"),
                              fv = std_vector_arg(force, "detect_stick_slip", "force", optional);
    same_length("detect_stick_slip", {{"t", tv.size()}, {"v", vv.size()}, {"force", fv.size()}});
    return detect_stick_slip(tv, vv, fv, o);
  });

  m.def(
      "_analyze_map",
      [](const std::string& scenario, const std::vector<std::string>& vary, double transient, double tolerance, int jobs,
         const std::string& shard, const std::string& contact) {
        MapGrid grid;
        for (const auto& v : vary) grid.axes.push_back(parse_map_axis(v, "vary"));
        MapRunOptions o;
        if (!std::isnan(transient)) o.motion.transient = transient;
        o.motion.tolerance = tolerance;
        o.threads = jobs;
        if (!shard.empty()) o.shard = parse_shard(shard, "shard");
        o.contact = contact;
        o.contact_option = "contact";
        MapRun run;
        run = run_cancellable([&] { return map_scenario(scenario, grid, o); });
        py::list rows;
        for (std::size_t r = 0; r < run.part.table.rows.size(); ++r) {
          py::dict d;
          d["index"] = run.part.table.index[r];
          const auto& row = run.part.table.rows[r];
          for (std::size_t c = 0; c < row.size(); ++c) {
            const auto& name = run.part.table.columns[c];
            if (const double* x = std::get_if<double>(&row[c]))
              d[py::str(name)] = *x;
            else
              d[py::str(name)] = std::get<std::string>(row[c]);
          }
          rows.append(d);
        }
        py::dict out;
        out["rows"] = rows;
        out["theory"] = run.theory_kind;
        out["theory_note"] = run.theory_note;
        out["columns"] = run.part.table.columns;
        out["contact"] = py::make_tuple(run.contact, run.contact_name);
        return out;
      },
      py::arg("scenario"), py::arg("vary"), py::arg("transient"), py::arg("tolerance"), py::arg("jobs"), py::arg("shard"),
      py::arg("contact"), "Map of a scenario over a grid (see frictionlab.analyze_map).");

  // Fleet drift (frictionlab.batch.drift, log_date): dates as (iso, posix seconds) tuples.
  m.def("_log_date_from_name", [](const std::string& path) -> py::object {
    const auto d = log_date_from_name(path);
    if (!d) return py::none();
    return py::make_tuple(d->iso, d->posix_seconds);
  });
  m.def("_log_date_from_posix", [](double seconds) {
    const LogDate d = log_date_from_posix(seconds);
    return py::make_tuple(d.iso, d.posix_seconds);
  });
  m.def("_drift_table", [](const std::vector<std::tuple<std::string, std::string, double, std::string, double, double,
                                                        std::string>>& samples,
                           double threshold) {
    std::vector<DriftSample> in;
    in.reserve(samples.size());
    for (const auto& [file, iso, posix, parameter, value, sd, unit] : samples)
      in.push_back({file, {iso, posix}, parameter, value, sd, unit});
    py::list out;
    for (const DriftRow& r : drift_table(in, threshold)) {
      py::dict d;
      d["file"] = r.sample.file;
      d["date"] = r.sample.date.iso;
      d["parameter"] = r.sample.parameter;
      d["value"] = r.sample.value;
      d["std"] = r.sample.std;
      d["unit"] = r.sample.unit;
      d["change"] = r.change;
      d["combined_std"] = r.combined_std;
      d["flagged"] = r.flagged;
      out.append(d);
    }
    return out;
  });
}

}  // namespace frictionlab::python
