// Experiment planning (analysis/plan/*.hpp): fl.plan's core, the JSON text and the profile samples.
#include <pybind11/stl.h>

#include "cancellable.hpp"
#include "common.hpp"
#include "frictionlab/analysis/plan/plan.hpp"
#include "io/atomic_write.hpp"
#include "frictionlab/scenario/plan_files.hpp"

namespace frictionlab::python {

void init_plan(py::module_& m) {
  m.def(
      "_plan",
      [](const std::string& method, const py::handle& prior, const py::handle& scenario,
         const std::vector<std::string>& noise, const std::vector<std::string>& limits, int runs, std::uint64_t seed,
         double margin, double lag_fraction, int speeds, double rate, double load, double warm_up, int ripple_periods,
         const py::handle& output, bool overwrite) {
        const PlanMethod pm = parse_plan_method(method);
        PlanOptions o;
        o.noise = parse_sensor_noise(noise, "plan: noise");
        o.limits = parse_plan_limits(limits, "plan: limits");
        o.design.margin = margin;
        o.design.lag_fraction = lag_fraction;
        o.design.speeds = speeds;
        o.design.sample_rate = rate;
        o.design.load = load;
        o.design.warm_up = warm_up;
        o.design.ripple_periods = ripple_periods;
        o.runs = runs;
        o.seed = seed;
        const std::string out_path = output.is_none() ? std::string() : path_arg(output, "plan", "output");
        if (!out_path.empty()) check_output_path(out_path, overwrite);
        const std::string prior_path = path_arg(prior, "plan", "prior"), scenario_path = path_arg(scenario, "plan", "scenario");
        const PlanRig rig = run_cancellable([&] { return load_plan_rig(prior_path, scenario_path); });  // files: no GIL
        PlanResult r;
        r = run_cancellable([&] { return plan_experiment(pm, rig, o); });
        if (r.ok && !out_path.empty()) write_file_atomic(out_path, r.profile.to_csv(), {overwrite});
        std::vector<double> t, u;
        r.profile.samples(t, u);
        py::object load_samples = py::none();
        if (r.profile.load) {
          std::vector<double> l(t.size());
          for (std::size_t k = 0; k < t.size(); ++k) l[k] = r.profile.load->at(t[k]).value;
          load_samples = to_array(l);
        }
        return py::make_tuple(plan_to_json(r, o, out_path, -1), to_array(t), to_array(u), load_samples);
      },
      py::arg("method"), py::arg("prior"), py::arg("scenario"), py::arg("noise"), py::arg("limits"), py::arg("runs"),
      py::arg("seed"), py::arg("margin"), py::arg("lag_fraction"), py::arg("speeds"), py::arg("rate"), py::arg("load"),
      py::arg("warm_up"), py::arg("ripple_periods"), py::arg("output"),
      py::arg("overwrite"),
      "Core of frictionlab.plan: returns (JSON text, profile time s, profile command, profile load N or N m or None).");
}

}  // namespace frictionlab::python
