#include "frictionlab/analysis/map.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "frictionlab/analysis/describing_function.hpp"
#include "frictionlab/analysis/sliding_stability.hpp"
#include "frictionlab/analysis/stick_slip.hpp"
#include "frictionlab/format.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/simulate/closed_loop.hpp"
#include "frictionlab/plants/spring_base.hpp"
#include "frictionlab/simulate/batch.hpp"

namespace frictionlab {
namespace {

bool parse_double(const std::string& s, double& out) {
  if (s.empty()) return false;
  const char* end = s.data() + s.size();
  const auto r = std::from_chars(s.data(), end, out);
  return r.ec == std::errc() && r.ptr == end;
}

}  // namespace

std::vector<double> MapAxis::values() const {
  std::vector<double> v(count);
  for (std::size_t i = 0; i < count; ++i) {
    if (count == 1) {
      v[i] = start;
    } else if (i + 1 == count) {
      v[i] = stop;  // exactly the given end, free of rounding
    } else {
      const double f = static_cast<double>(i) / static_cast<double>(count - 1);
      v[i] = log ? start * std::pow(stop / start, f) : start + (stop - start) * f;
    }
  }
  return v;
}

std::string MapAxis::text() const {
  return key + "=" + (log ? "log:" : "") + format_exact(start) + ":" + format_exact(stop) + ":" + std::to_string(count);
}

MapAxis parse_map_axis(const std::string& text, const std::string& option) {
  const std::string head = option + " '" + text + "': ";
  const auto eq = text.find('=');
  if (eq == std::string::npos) throw std::invalid_argument(head + "expected KEY=START:STOP:N (or KEY=log:START:STOP:N)");
  MapAxis a;
  a.key = text.substr(0, eq);
  if (a.key.empty()) throw std::invalid_argument(head + "the key is empty; expected a scenario key such as plant.k");
  std::vector<std::string> parts;
  std::string rest = text.substr(eq + 1);
  for (std::size_t at = 0;;) {
    const auto colon = rest.find(':', at);
    parts.push_back(rest.substr(at, colon - at));
    if (colon == std::string::npos) break;
    at = colon + 1;
  }
  if (!parts.empty() && parts.front() == "log") {
    a.log = true;
    parts.erase(parts.begin());
  }
  if (parts.size() != 3) throw std::invalid_argument(head + "expected START:STOP:N after '=' (three fields separated by ':')");
  if (!parse_double(parts[0], a.start) || !std::isfinite(a.start))
    throw std::invalid_argument(head + "START '" + parts[0] + "' is not a finite number");
  if (!parse_double(parts[1], a.stop) || !std::isfinite(a.stop))
    throw std::invalid_argument(head + "STOP '" + parts[1] + "' is not a finite number");
  const std::string& n = parts[2];
  if (n.empty() || n.size() > 9 || !std::all_of(n.begin(), n.end(), [](char c) { return c >= '0' && c <= '9'; }) ||
      std::stoul(n) < 1)
    throw std::invalid_argument(head + "N '" + n + "' must be an integer >= 1 (the number of values)");
  a.count = std::stoul(n);
  if (a.count == 1 && a.start != a.stop)
    throw std::invalid_argument(head + "N = 1 gives one value: START and STOP must be equal");
  if (a.log && !(a.start > 0 && a.stop > 0))
    throw std::invalid_argument(head + "log spacing needs START and STOP > 0");
  return a;
}

std::size_t MapGrid::size() const {
  if (axes.empty()) return 0;
  std::size_t n = 1;
  for (const auto& a : axes) n *= a.count;
  return n;
}

std::vector<double> MapGrid::point(std::size_t i) const {
  if (i >= size()) throw std::out_of_range("MapGrid::point: " + std::to_string(i) + " >= " + std::to_string(size()));
  std::vector<double> p(axes.size());
  for (std::size_t k = axes.size(); k-- > 0;) {
    const std::size_t j = i % axes[k].count;
    i /= axes[k].count;
    p[k] = axes[k].values()[j];
  }
  return p;
}

void MapGrid::validate() const {
  if (axes.empty()) throw std::invalid_argument("map: no --vary given; vary at least one scenario key");
  std::set<std::string> keys;
  double n = 1;
  for (const auto& a : axes) {
    if (!keys.insert(a.key).second) throw std::invalid_argument("--vary " + a.key + ": key given twice; vary each key once");
    n *= static_cast<double>(a.count);
  }
  if (n > 1e7) throw std::invalid_argument("map: " + format_number(n) + " grid points; at most 1e7");
}

const char* motion_class_name(MotionClass c) {
  switch (c) {
    case MotionClass::converged: return "converged";
    case MotionClass::steady_sliding: return "steady-sliding";
    case MotionClass::stick_slip: return "stick-slip";
    case MotionClass::hunting: return "hunting";
    case MotionClass::oscillating: return "oscillating";
    case MotionClass::failed: return "failed";
  }
  return "failed";
}

void MotionOptions::validate() const {
  if (!(std::isnan(transient) || (std::isfinite(transient) && transient >= 0)))
    throw std::invalid_argument("map: transient = " + format_number(transient) + " must be >= 0 (s)");
  if (!(tolerance > 0 && tolerance < 1))
    throw std::invalid_argument("map: tolerance = " + format_number(tolerance) + " must be in (0, 1)");
}

MotionSummary classify_motion(std::span<const double> t, std::span<const double> x, std::span<const double> v,
                              const MotionOptions& options) {
  options.validate();
  if (x.size() != t.size() || v.size() != t.size())
    throw std::invalid_argument("classify_motion: t, x and v have " + std::to_string(t.size()) + ", " +
                                std::to_string(x.size()) + " and " + std::to_string(v.size()) + " samples; expected equal");
  constexpr std::size_t kMinKept = 8;
  if (t.size() < kMinKept) throw std::invalid_argument("classify_motion: fewer than 8 samples");
  MotionSummary s;
  const double t_end = t.back();
  s.transient = std::isnan(options.transient) ? 0.5 * (t_end - t.front()) : options.transient;
  const std::size_t k0 =
      static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), t.front() + s.transient) - t.begin());
  if (t.size() - std::min(k0, t.size()) < kMinKept)
    throw std::invalid_argument("classify_motion: transient " + format_number(s.transient) + " s leaves fewer than 8 of " +
                                std::to_string(t.size()) + " samples (the record ends at " + format_number(t_end) + " s)");
  const auto tk = t.subspan(k0), xk = x.subspan(k0), vk = v.subspan(k0);
  const std::size_t n = tk.size();
  double vscale = 0;
  for (double vi : v) vscale = std::max(vscale, std::abs(vi));
  const double span = tk.back() - tk.front();
  s.mean_velocity = (xk.back() - xk.front()) / span;
  const auto [vmin, vmax] = std::minmax_element(vk.begin(), vk.end());
  s.velocity_amplitude = 0.5 * (*vmax - *vmin);
  // Sustained: the last third still oscillates.
  const auto last = vk.subspan(n - n / 3);
  const auto [lmin, lmax] = std::minmax_element(last.begin(), last.end());
  const bool sustained = vscale > 0 && 0.5 * (*lmax - *lmin) > options.tolerance * vscale;
  // Drifts: net displacement more than half the total travel.
  double travel = 0;
  for (std::size_t i = 1; i < n; ++i) travel += std::abs(xk[i] - xk[i - 1]);
  const bool drifts = travel > 0 && std::abs(xk.back() - xk.front()) > 0.5 * travel;
  const double drift = drifts ? s.mean_velocity : 0.0;
  // Drift-free position: amplitude and period (upward crossings of the mid-range, armed below
  // the lower quarter so that noise at the crossing counts once).
  std::vector<double> d(n);
  for (std::size_t i = 0; i < n; ++i) d[i] = xk[i] - drift * (tk[i] - tk.front());
  const auto [dmin, dmax] = std::minmax_element(d.begin(), d.end());
  s.amplitude = 0.5 * (*dmax - *dmin);
  const double mid = 0.5 * (*dmax + *dmin), arm = mid - 0.25 * (*dmax - *dmin);
  std::vector<double> ups;
  bool armed = false;
  for (std::size_t i = 1; i < n; ++i) {
    if (d[i - 1] < arm) armed = true;
    if (armed && d[i - 1] < mid && d[i] >= mid) {
      ups.push_back(tk[i - 1] + (mid - d[i - 1]) / (d[i] - d[i - 1]) * (tk[i] - tk[i - 1]));
      armed = false;
    }
  }
  if (sustained && ups.size() >= 2) s.period = (ups.back() - ups.front()) / static_cast<double>(ups.size() - 1);
  // Sticking, by the stick-slip detector (exact zeros of a hybrid simulation, else 1 % of max |v|).
  double stuck = 0;
  if (sustained) {
    const StickSlipResult ss = detect_stick_slip(tk, vk, {});
    for (const auto& iv : ss.stick) stuck += iv.end - iv.start;
  }
  s.stuck_fraction = span > 0 ? stuck / span : 0.0;
  if (!sustained)  // moving on at a speed that counts, or settling (a slow creep to the setpoint is settling)
    s.kind = std::abs(s.mean_velocity) > options.tolerance * vscale ? MotionClass::steady_sliding : MotionClass::converged;
  else if (stuck > 0)
    s.kind = drifts ? MotionClass::stick_slip : MotionClass::hunting;
  else
    s.kind = drifts ? MotionClass::oscillating : MotionClass::hunting;
  return s;
}

MapTheory map_theory(const Scenario& scenario) {
  MapTheory th;
  if (!scenario.plant || !scenario.inputs.empty()) return th;
  const LawSpec law = scenario.law.to_spec();
  const auto value = [&](const char* name, double fallback) {
    const auto it = law.scalars.find(name);
    return it == law.scalars.end() ? fallback : it->second;
  };
  if (const auto* sb = dynamic_cast<const SpringBase*>(scenario.plant.get())) {
    const SpringBaseParams& p = sb->params();
    Stribeck st;
    if (law.name == "stribeck") {
      st = Stribeck{value("Fc", 1), value("Fs", 1.5), value("vs", 1e-3), value("delta", 2), value("Fv", 0.4)};
    } else if (law.name == "coulomb-viscous" || law.name == "static-coulomb-viscous" || law.name == "viscous" ||
               law.name == "coulomb") {
      // No falling part: the slope is Fv everywhere (a Stribeck law with Fs = Fc).
      const double Fc = value("Fc", 0);
      st = Stribeck{Fc, Fc, 1.0, 2.0, value("Fv", 0)};
    } else {
      return th;
    }
    th.kind = "spring-block";
    if (p.V0 == 0.0) {
      th.message = "V0 = 0: no steady sliding to linearise about";
      return th;
    }
    th.margin = sliding_damping_margin(st, p.c, p.V0);
    th.predicted = motion_class_name(th.margin > 0 ? MotionClass::steady_sliding : MotionClass::stick_slip);
    return th;
  }
  if (const auto* cl = dynamic_cast<const ClosedLoop*>(scenario.plant.get())) {
    const auto* axis = dynamic_cast<const RigidAxis*>(&cl->inner());
    const PidParams& c = cl->controller();
    if (!axis || cl->compensator() || c.loop != ControlLoop::position || c.limit != 0 || c.Ts != 0) return th;
    if (law.name != "coulomb" && !(law.name == "static-coulomb-viscous" && value("Fv", 0) == 0)) return th;
    th.kind = "pid-hunting";
    HuntingLoop h;
    h.M = axis->params().M;
    h.Kp = c.Kp;
    h.Ki = c.Ki;
    h.Kd = c.Kd;
    h.Fc = value("Fc", 1);
    h.Fs = law.name == "coulomb" ? h.Fc : value("Fs", h.Fc);
    try {
      h.validate();
    } catch (const std::invalid_argument& e) {
      th.message = e.what();
      return th;
    }
    const HuntingPrediction pr = predict_hunting(h);
    if (pr.found) {
      th.predicted = motion_class_name(MotionClass::hunting);
      th.amplitude = pr.amplitude;
      th.period = pr.period;
    } else if (h.Fs == h.Fc && h.Kd * h.Kp > h.M * h.Ki) {
      th.predicted = motion_class_name(MotionClass::converged);
      th.message = pr.message;
    } else {
      th.message = pr.message;
    }
    return th;
  }
  return th;
}

int map_contact(const Scenario& scenario, const std::string& which, const std::string& option) {
  if (!scenario.plant) throw std::invalid_argument(option + " '" + which + "': the scenario has no plant");
  const Plant& plant = *scenario.plant;
  const int n = plant.num_contacts();
  if (which.empty()) return 0;
  for (int i = 0; i < n; ++i)
    if (plant.contact(i).name == which) return i;
  std::size_t index = 0;
  if (which.size() < 9 && std::all_of(which.begin(), which.end(), [](char c) { return c >= '0' && c <= '9'; }) &&
      (index = std::stoul(which)) < static_cast<std::size_t>(n))
    return static_cast<int>(index);
  std::string list;
  for (int i = 0; i < n; ++i) {
    const std::string name = plant.contact(i).name;
    list += (i ? ", " : "") + std::to_string(i) + " " + (name.empty() ? std::string("(unnamed)") : name);
  }
  throw std::invalid_argument(option + " '" + which + "': the " + plant.type() + " plant has no such contact; its " +
                              (n == 1 ? std::string("contact: ") : std::to_string(n) + " contacts: ") + list +
                              " (a name or an index from 0)");
}

std::vector<MotionSummary> run_map(const std::vector<Scenario>& scenarios, const MapOptions& options) {
  options.motion.validate();
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    // A scenario without a plant is simulate()'s to refuse: its row fails, the others go on.
    const int n = scenarios[i].plant ? scenarios[i].plant->num_contacts() : 1;
    if (options.contact < 0 || options.contact >= n)
      throw std::invalid_argument("map: contact " + std::to_string(options.contact) + " is not a contact of scenario " +
                                  std::to_string(i) + "'s plant (" + std::to_string(n) + " contacts, indices from 0)");
  }
  std::vector<MotionSummary> out(scenarios.size());
  BatchOptions b;
  b.threads = options.threads;
  b.on_result = [&](std::size_t i, BatchResult& r) {
    const Trajectory& tr = r.trajectory;
    const ContactColumns& c = tr.contact(options.contact);
    out[i] = classify_motion(tr.time, c.position, c.velocity, options.motion);
    r.trajectory = Trajectory{};  // its columns go back to this thread's pool
  };
  if (options.progress) b.progress = [&](std::size_t, std::size_t done) { options.progress(done, scenarios.size()); };
  const std::vector<BatchResult> results = simulate_batch(scenarios, b);
  for (std::size_t i = 0; i < results.size(); ++i)
    if (!results[i].ok()) {
      out[i] = MotionSummary{};
      out[i].kind = MotionClass::failed;
      out[i].message = results[i].message;
    }
  return out;
}

}  // namespace frictionlab
