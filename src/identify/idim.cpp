#include "frictionlab/models/parameter.hpp"
#include "frictionlab/identify/idim.hpp"

#include <algorithm>
#include <optional>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "frictionlab/error.hpp"
#include "frictionlab/identify/adequacy.hpp"
#include "frictionlab/identify/covariance.hpp"
#include "frictionlab/identify/finite_result.hpp"
#include "frictionlab/identify/method.hpp"
#include "idim_stribeck.hpp"
#include "method_support.hpp"
#include "idim_internal.hpp"
#include "frictionlab/identify/least_squares.hpp"
#include "frictionlab/identify/uncertainty.hpp"
#include "frictionlab/signal/butterworth.hpp"
#include "frictionlab/signal/decimate.hpp"
#include "frictionlab/signal/differentiate.hpp"
#include "frictionlab/signal/filtfilt.hpp"
#include "frictionlab/signal/sampling.hpp"
#include "../signal/all_finite.hpp"

namespace frictionlab {
namespace {

using Vec = Eigen::VectorXd;


std::string where(const IdimData& d) { return d.file.empty() ? std::string("idim: ") : d.file + ": "; }


void check_signal(const IdimData& d, const Vec& v, const char* name, Eigen::Index n) {
  if (v.size() != n) {
    throw std::invalid_argument(where(d) + name + " has " + std::to_string(v.size()) + " samples; expected " +
                                std::to_string(n) + " like time");
  }
  if (detail::all_finite(v)) return;  // the common case; else the loop finds the sample
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!std::isfinite(v(k))) {
      throw std::invalid_argument(where(d) + "sample " + std::to_string(k + 1) + ": " + name + " = " + detail::format_value(v(k), 6) +
                                  " is not a finite number");
    }
  }
}

// Mean sample step after checking time is finite, strictly increasing and regular (1 %). Run
// once per identification: the pipeline's passes take the step from their caller.
double checked_step(const IdimData& d) {
  RegularSamplingCheck check;  // the one rule of signal/sampling.hpp: 1 % of the median step
  check.where = where(d);
  check.requirement = "IDIM needs regularly sampled data";
  return check_regular_sampling(d.time, check);
}

// A built-in term from its value at one sample, f(qd, qdd), in both forms: written into a
// buffer (what the pipeline uses) and returned as a new column.
template <class F>
IdimTerm sample_term(const char* parameter, Quantity quantity, F f) {
  auto fill = [f](const IdimKinematics& k, Eigen::Ref<Vec> out) {
    // Plain pointers, the output marked unaliased, so that the loop is vectorised.
    const double* const qd = k.qd.data();
    const double* const qdd = k.qdd.data();
    double* __restrict const o = out.data();
    for (Eigen::Index i = 0; i < out.size(); ++i) o[i] = f(qd[i], qdd[i]);
  };
  auto column = [fill](const IdimKinematics& k) {
    Vec v(k.qd.size());
    fill(k, v);
    return v;
  };
  return {parameter, quantity, column, fill};
}

// Selects rather than converts a comparison, so that loops over it are vectorised.
double sign_of(double v) { return (v > 0 ? 1.0 : 0.0) - (v < 0 ? 1.0 : 0.0); }

// A term of a measured condition at one sample, f(qd, c), with c the kinematics' `condition`
// (load or temperature), in both forms as sample_term.
template <class F>
IdimTerm condition_term(std::string parameter, Quantity quantity, IdimKinematics::View IdimKinematics::*condition,
                        const char* needs, F f) {
  auto fill = [parameter, condition, needs, f](const IdimKinematics& k, Eigen::Ref<Vec> out) {
    const IdimKinematics::View& c = k.*condition;
    if (c.size() != out.size())
      throw std::invalid_argument("idim: parameter " + parameter + " needs " + needs + " (" + std::to_string(c.size()) +
                                  " samples given; expected " + std::to_string(out.size()) + ")");
    for (Eigen::Index i = 0; i < out.size(); ++i) out(i) = f(k.qd(i), c(i));
  };
  auto column = [fill](const IdimKinematics& k) {
    Vec v(k.qd.size());
    fill(k, v);
    return v;
  };
  return {std::move(parameter), quantity, column, fill};
}

// The ripple's sine (or cosine) of harmonic h: sin(2 pi h q / period) of the filtered position.
IdimTerm ripple_term(int h, bool cosine, double period) {
  std::string parameter = std::string(cosine ? "ripple_cos_" : "ripple_sin_") + std::to_string(h);
  const double wavenumber = 2.0 * M_PI * h / period;  // rad per m (or per rad)
  auto fill = [parameter, cosine, wavenumber](const IdimKinematics& k, Eigen::Ref<Vec> out) {
    if (k.q.size() != out.size())
      throw std::invalid_argument("idim: parameter " + parameter +
                                  " needs the position (the ripple repeats with position); the regressors were built "
                                  "from the velocity");
    for (Eigen::Index i = 0; i < out.size(); ++i) out(i) = cosine ? std::cos(wavenumber * k.q(i)) : std::sin(wavenumber * k.q(i));
  };
  auto column = [fill](const IdimKinematics& k) {
    Vec v(k.qd.size());
    fill(k, v);
    return v;
  };
  return {std::move(parameter), Quantity::force, column, fill};
}

// The terms of a measured condition or of position that one term name adds ("load" adds two,
// "ripple" two per harmonic); empty for any other name.
std::vector<IdimTerm> condition_terms(const std::string& name, const IdimOptions& o) {
  if (name == "load") {
    constexpr const char* kLoad = "the load column (N or N m; --load COLUMN, Python load=array)";
    return {condition_term("load_gain", Quantity::dimensionless, &IdimKinematics::load, kLoad,
                           [](double, double load) { return load; }),
            condition_term("mu_load", Quantity::dimensionless, &IdimKinematics::load, kLoad,
                           [](double qd, double load) { return sign_of(qd) * std::abs(load); })};
  }
  if (name == "temperature") {
    if (!std::isfinite(o.temperature_ref))
      throw std::invalid_argument("idim: temperature_ref = " + detail::format_value(o.temperature_ref, 6) +
                                  " must be a finite temperature (degC or K) for the 'temperature' term");
    const double ref = o.temperature_ref;
    return {condition_term("Fv_per_K", Quantity::viscous_per_kelvin, &IdimKinematics::temperature,
                           "the temperature column (degC or K; --temperature COLUMN, Python temperature=array)",
                           [ref](double qd, double t) { return qd * (t - ref); })};
  }
  if (name == "ripple") {
    if (!(o.ripple_period > 0.0) || !std::isfinite(o.ripple_period))
      throw std::invalid_argument("idim: ripple period = " + detail::format_value(o.ripple_period, 6) +
                                  " must be > 0 (m or rad) for the 'ripple' term (--ripple-period P)");
    if (o.ripple_harmonics < 1)
      throw std::invalid_argument("idim: ripple harmonics = " + std::to_string(o.ripple_harmonics) + " must be >= 1");
    std::vector<IdimTerm> out;
    for (int h = 1; h <= o.ripple_harmonics; ++h) {
      out.push_back(ripple_term(h, false, o.ripple_period));
      out.push_back(ripple_term(h, true, o.ripple_period));
    }
    return out;
  }
  return {};
}

// True when `terms` asks for the term `name`.
bool asks_for(const IdimOptions& o, const char* name) { return std::find(o.terms.begin(), o.terms.end(), name) != o.terms.end(); }

IdimTerm builtin(const std::string& name, const IdimOptions& o) {
  if (name == "inertia") return sample_term("M", Quantity::inertia, [](double, double qdd) { return qdd; });
  if (name == "viscous") return sample_term("Fv", Quantity::viscous, [](double qd, double) { return qd; });
  if (name == "coulomb") return sample_term("Fc", Quantity::force, [](double qd, double) { return sign_of(qd); });
  if (name == "offset") return sample_term("offset", Quantity::force, [](double, double) { return 1.0; });
  if (name == "viscous_pos") return sample_term("Fv_pos", Quantity::viscous, [](double qd, double) { return qd > 0 ? qd : 0.0; });
  if (name == "coulomb_pos") return sample_term("Fc_pos", Quantity::force, [](double qd, double) { return qd > 0 ? 1.0 : 0.0; });
  if (name == "viscous_neg") return sample_term("Fv_neg", Quantity::viscous, [](double qd, double) { return qd < 0 ? qd : 0.0; });
  if (name == "coulomb_neg") return sample_term("Fc_neg", Quantity::force, [](double qd, double) { return qd < 0 ? -1.0 : 0.0; });
  if (name == "stribeck") {
    if (!(o.stribeck_vs > 0.0) || !(o.stribeck_delta > 0.0)) {
      throw std::invalid_argument("idim: stribeck_vs = " + detail::format_value(o.stribeck_vs, 6) + " m/s and stribeck_delta = " +
                                  detail::format_value(o.stribeck_delta, 6) + " must be positive for the 'stribeck' term");
    }
    const double vs = o.stribeck_vs, delta = o.stribeck_delta;
    return sample_term("Fs_minus_Fc", Quantity::force, [vs, delta](double qd, double) {
      return sign_of(qd) * std::exp(-std::pow(std::abs(qd / vs), delta));
    });
  }
  throw std::invalid_argument("idim: unknown term '" + name +
                              "'; known terms: inertia, viscous, coulomb, offset, asymmetric, viscous_pos, "
                              "coulomb_pos, viscous_neg, coulomb_neg, stribeck, load, temperature, ripple");
}

std::string model_name(const std::vector<IdimTerm>& terms, bool custom) {
  std::set<std::string> p;
  for (const auto& t : terms) p.insert(t.parameter);
  if (custom || p.count("Fs_minus_Fc")) return "idim-custom";
  if (p.count("Fc_pos") || p.count("Fv_pos")) return "coulomb-viscous-asymmetric";
  if (p.count("Fc") && p.count("Fv")) return "coulomb-viscous";
  if (p.count("Fc")) return "coulomb";
  if (p.count("Fv")) return "viscous";
  return "idim-custom";
}

Result error_result(Result r, std::string message) {
  r.status = ResultStatus::error;
  r.message = std::move(message);
  r.parameters.clear();
  return r;
}

}  // namespace

IdimRateDefaults idim_rate_defaults(double fs) {
  if (!(fs > 0) || !std::isfinite(fs))
    throw std::invalid_argument("idim: sample rate = " + detail::format_value(fs, 6) + " Hz must be a positive finite number");
  IdimRateDefaults d;
  // A rate within 0.1 % below 1 kHz is 1 kHz: a mean step with rounding, or the median step of a
  // jittered log put on a grid by --resample (1.0001 ms), gets exactly the recipe's 100 Hz and 10,
  // not 99.99 Hz and 9.
  constexpr double kRateTolerance = 1e-3;
  d.cutoff_hz = fs / 10.0 >= 100.0 * (1 - kRateTolerance) ? 100.0 : fs / 10.0;
  d.decimation = static_cast<int>(std::clamp(std::floor(fs / 100.0 * (1 + kRateTolerance)), 1.0, 10.0));
  d.skip = static_cast<Eigen::Index>(std::lround(5.0 * fs / d.cutoff_hz)) - 1;
  return d;
}

namespace {
// The measured condition `name` (load, temperature) that a term of `o` needs, checked: present,
// as long as time, finite.
void check_condition(const IdimData& d, const IdimOptions& o, const char* term, const Vec& v, const char* what) {
  if (!asks_for(o, term)) return;
  if (v.size() == 0) throw std::invalid_argument(where(d) + "the '" + term + "' term needs " + what);
  check_signal(d, v, term, d.time.size());
}

// `o` with the settings it leaves to the data filled in: the rate-dependent ones from the mean
// step dt (s), the temperature term's reference from the mean temperature over the used samples.
IdimOptions resolved(const IdimOptions& o, const IdimData& data, double dt) {
  check_condition(data, o, "load", data.load, "the load column (N or N m; --load COLUMN, Python load=array)");
  check_condition(data, o, "temperature", data.temperature,
                  "the temperature column (degC or K; --temperature COLUMN, Python temperature=array)");
  IdimOptions r = o;
  if (o.auto_cutoff || o.auto_decimation || o.auto_skip) {
    const IdimRateDefaults d = idim_rate_defaults(1.0 / dt);
    if (o.auto_cutoff) r.cutoff_hz = d.cutoff_hz;
    if (o.auto_decimation) r.decimation = d.decimation;
    if (o.auto_skip) r.skip = d.skip;
    r.auto_cutoff = r.auto_decimation = r.auto_skip = false;
  }
  if (asks_for(o, "temperature") && std::isnan(o.temperature_ref)) {
    const Eigen::Index n = data.temperature.size(), used = n - r.skip - r.skip_end;
    r.temperature_ref = used > 0 ? data.temperature.segment(r.skip, used).mean() : data.temperature.mean();
  }
  return r;
}
}  // namespace

std::vector<IdimTerm> idim_terms(const IdimOptions& options) {
  std::vector<IdimTerm> out;
  for (const auto& name : options.terms) {
    if (name == "asymmetric") {
      for (const char* n : {"viscous_pos", "coulomb_pos", "viscous_neg", "coulomb_neg"}) out.push_back(builtin(n, options));
    } else if (auto more = condition_terms(name, options); !more.empty()) {
      for (auto& t : more) out.push_back(std::move(t));
    } else {
      out.push_back(builtin(name, options));
    }
  }
  for (const auto& t : options.extra_terms) {
    if (!t.column && !t.fill) {
      throw std::invalid_argument("idim: extra term '" + t.parameter + "' has neither a column nor a fill function");
    }
    out.push_back(t);
  }
  std::set<std::string> seen;
  for (const auto& t : out) {
    if (!seen.insert(t.parameter).second) {
      throw std::invalid_argument("idim: parameter '" + t.parameter + "' appears twice in the terms");
    }
  }
  if (out.empty()) throw std::invalid_argument("idim: no terms; expected at least one (e.g. inertia, viscous, coulomb)");
  return out;
}

namespace {

// True when the regressors are built from the measured velocity (asked for, or automatic with
// no position); else from the position.
bool regressors_from_velocity(const IdimData& d, const IdimOptions& o) {
  return o.source == IdimSource::velocity || (o.source == IdimSource::automatic && d.position.size() == 0);
}

// IDIM's work buffers for n samples in the caller's workspace (identify/idim_workspace.hpp):
// the filter input with `pad` samples of odd extension each side (buffer 0), the velocity (1)
// and the acceleration (2); the columns of terms that fill a buffer take 3, 4, ...
constexpr std::size_t kFirstColumnBuffer = 3;
struct IdimBuffers {
  Eigen::Map<Vec> padded, qd, qdd;
  IdimBuffers(IdimWorkspace& w, Eigen::Index n, Eigen::Index pad)
      : padded(w.buffer(0, static_cast<std::size_t>(n + 2 * pad)).data(), n + 2 * pad),
        qd(w.buffer(1, static_cast<std::size_t>(n)).data(), n),
        qdd(w.buffer(2, static_cast<std::size_t>(n)).data(), n) {}
};

// One pass of steps 1-4 on options already resolved for the data's mean step dt (s); with
// `velocity`, also the filtered velocity at the fitted samples (the friction map's abscissa).
struct Pass {
  IdimRegression reg;
  bool from_velocity = false;
  Vec velocity;  // decimated like the columns; empty unless asked for
  std::optional<IdimKinematics> kinematics;  // views of the workspace, valid until it is used again
};

// Keeps the rows of the decimated columns `reduced` whose velocity (column `velocity_col`) is
// at least options.exclude_below in magnitude; records each kept row's raw sample and the count
// left out in `reg`.
void exclude_slow_rows(Eigen::MatrixXd& reduced, Eigen::Index velocity_col, const IdimOptions& options,
                       IdimRegression& reg) {
  if (!(options.exclude_below >= 0) || !std::isfinite(options.exclude_below))
    throw std::invalid_argument("idim: exclude_below = " + detail::format_value(options.exclude_below, 6) +
                                " must be a finite speed >= 0 (m/s or rad/s)");
  Eigen::Index kept = 0;
  for (Eigen::Index k = 0; k < reduced.rows(); ++k) {
    if (!(std::abs(reduced(k, velocity_col)) >= options.exclude_below)) continue;
    if (kept != k) reduced.row(kept) = reduced.row(k);
    reg.sample.push_back(options.skip + k * std::max(1, options.decimation));
    ++kept;
  }
  reg.excluded = reduced.rows() - kept;
  reduced.conservativeResize(kept, Eigen::NoChange);
}

Pass regression_pass(const IdimData& data, const IdimOptions& options, double dt, bool want_velocity_column,
                     IdimWorkspace& workspace) {
  Pass pass;
  IdimRegression& reg = pass.reg;
  reg.terms = idim_terms(options);
  const Eigen::Index n = data.time.size();
  reg.dt = dt;
  check_signal(data, data.force, "force", n);
  if (options.decimation < 1) {
    throw std::invalid_argument("idim: decimation = " + std::to_string(options.decimation) + " must be >= 1");
  }
  if (options.skip < 0 || options.skip_end < 0) {
    throw std::invalid_argument("idim: skip = " + std::to_string(options.skip) + " and skip_end = " +
                                std::to_string(options.skip_end) + " must be >= 0");
  }
  constexpr Eigen::Index kMinUsed = 64;  // decimate's padding needs 28 samples; ask for a few more
  if (n - options.skip - options.skip_end < kMinUsed * std::max(1, options.decimation) / 2 || n <= options.padlen) {
    throw std::invalid_argument(where(data) + std::to_string(n) + " samples are too few for skip = " +
                                std::to_string(options.skip) + ", skip_end = " + std::to_string(options.skip_end) +
                                ", padlen = " + std::to_string(options.padlen) +
                                " and decimation = " + std::to_string(options.decimation));
  }

  // 1-2: zero-phase low-pass and central differences, in the workspace.
  const TransferFunction lp = butter(options.filter_order, normalized_cutoff(options.cutoff_hz, reg.dt));
  const Vec* measured = nullptr;
  pass.from_velocity = regressors_from_velocity(data, options);
  if (pass.from_velocity && asks_for(options, "ripple"))
    throw std::invalid_argument(where(data) + "the 'ripple' term needs the position (the ripple repeats with position), "
                                "but the regressors are built from the velocity: give a position column, or --from position");
  if (options.source == IdimSource::position && data.position.size() == 0)
    throw std::invalid_argument(where(data) + "no position given; the regressors were asked to be built from the position");
  if (options.source == IdimSource::velocity && data.velocity.size() == 0)
    throw std::invalid_argument(where(data) + "no velocity given; the regressors were asked to be built from the velocity");
  if (!pass.from_velocity) {  // implies a position (automatic without one takes the velocity)
    check_signal(data, data.position, "position", n);
    measured = &data.position;
  } else if (data.velocity.size() > 0) {
    check_signal(data, data.velocity, "velocity", n);
    measured = &data.velocity;
  } else {
    throw std::invalid_argument(where(data) + "neither position nor velocity given; IDIM needs one of them");
  }
  const Eigen::Index pad = filtfilt_padlen(lp, FiltfiltOptions{options.padlen}, n);
  IdimBuffers work(workspace, n, pad);
  auto& padded = work.padded;
  auto& qd = work.qd;
  auto& qdd = work.qdd;
  padded.segment(pad, n) = *measured;
  filtfilt_in_place(lp, padded, pad);
  const auto filtered = padded.segment(pad, n);
  const bool from_position = !pass.from_velocity;
  if (from_position) gradient(filtered, reg.dt, qd);
  else qd = filtered;
  gradient(qd, reg.dt, qdd);
  using View = IdimKinematics::View;
  const auto condition = [n](const Vec& c) { return c.size() == n ? View(c.data(), n) : View(nullptr, 0); };
  const IdimKinematics& k = pass.kinematics.emplace(
      IdimKinematics{from_position ? View(filtered.data(), n) : View(nullptr, 0), View(qd.data(), n), View(qdd.data(), n),
                     condition(data.load), condition(data.temperature)});

  // 3-4: columns, drop the start, decimate.
  const Eigen::Index used = n - options.skip - options.skip_end;
  reg.max_speed = k.qd.segment(options.skip, used).cwiseAbs().maxCoeff();
  if (options.input_delay < 0 || options.input_delay >= n)
    throw std::invalid_argument("idim: input_delay = " + std::to_string(options.input_delay) + " samples must be >= 0 and below " +
                                std::to_string(n));
  // Column 0 the force, then one column per term; all decimated together, read in place.
  const Eigen::Index p = static_cast<Eigen::Index>(reg.terms.size());
  std::vector<Vec> columns;  // the terms' columns (and the delayed force), kept alive for the views
  columns.reserve(static_cast<std::size_t>(p + 1));
  ColumnViews views;
  if (options.input_delay > 0) {  // y(k) = force(k - delay); the first samples hold force(0)
    Vec& f = columns.emplace_back(used);
    for (Eigen::Index i = 0; i < used; ++i) f(i) = data.force[std::max<Eigen::Index>(options.skip + i - options.input_delay, 0)];
    views.emplace_back(f.data(), used);
  } else {
    views.emplace_back(data.force.data() + options.skip, used);
  }
  const Eigen::Index builtin_terms = p - static_cast<Eigen::Index>(options.extra_terms.size());  // extras come last
  for (Eigen::Index j = 0; j < p; ++j) {
    const auto& term = reg.terms[static_cast<std::size_t>(j)];
    // The built-in inertia and viscous columns are qdd and qd themselves: read in place.
    if (j < builtin_terms && (term.parameter == "M" || term.parameter == "Fv")) {
      views.emplace_back((term.parameter == "M" ? k.qdd : k.qd).data() + options.skip, used);
      continue;
    }
    if (term.fill) {
      const std::size_t index = kFirstColumnBuffer + static_cast<std::size_t>(j);
      Eigen::Map<Vec> column(workspace.buffer(index, static_cast<std::size_t>(n)).data(), n);
      term.fill(k, column);
      views.emplace_back(column.data() + options.skip, used);
      continue;
    }
    const Vec& column = columns.emplace_back(term.column(k));
    if (column.size() != n) {
      throw std::invalid_argument("idim: term '" + term.parameter + "' gave " + std::to_string(column.size()) +
                                  " samples; expected " + std::to_string(n));
    }
    views.emplace_back(column.data() + options.skip, used);
  }
  // The velocity for the friction map: the built-in viscous column is qd itself; without one,
  // qd joins the decimation as one more column.
  Eigen::Index velocity_col = -1;
  if (want_velocity_column || options.exclude_below > 0) {
    for (Eigen::Index j = 0; j < builtin_terms && velocity_col < 0; ++j)
      if (reg.terms[static_cast<std::size_t>(j)].parameter == "Fv") velocity_col = j + 1;
    if (velocity_col < 0) {
      views.emplace_back(k.qd.data() + options.skip, used);
      velocity_col = p + 1;
    }
  }
  const Eigen::Index ncols = static_cast<Eigen::Index>(views.size());
  Eigen::MatrixXd reduced;
  if (options.decimation == 1) {
    reduced.resize(used, ncols);
    for (Eigen::Index j = 0; j < ncols; ++j) reduced.col(j) = views[static_cast<std::size_t>(j)];
  } else {
    reduced = decimate_columns(views, options.decimation, workspace.filter());
  }
  if (options.exclude_below > 0) exclude_slow_rows(reduced, velocity_col, options, reg);
  else
    for (Eigen::Index k = 0; k < reduced.rows(); ++k) reg.sample.push_back(options.skip + k * std::max(1, options.decimation));
  reg.y = reduced.col(0);
  reg.X = reduced.middleCols(1, p);
  if (velocity_col >= 0) pass.velocity = reduced.col(velocity_col);
  return pass;
}

// The speed at or below which a pass has no motion at all: min_velocity, or for a position the
// rounding level of a constant record filtered and differentiated, m/s or rad/s.
double no_motion_speed(const IdimData& data, const IdimOptions& options, const Pass& pass) {
  const double floor = pass.from_velocity ? 0.0 : 1e-9 * data.position.cwiseAbs().maxCoeff() / pass.reg.dt;
  return std::max(options.min_velocity, floor);
}

}  // namespace

IdimRegression idim_regression(const IdimData& data, const IdimOptions& options) {
  IdimWorkspace workspace;
  return idim_regression(data, options, workspace);
}

IdimRegression idim_regression(const IdimData& data, const IdimOptions& options, IdimWorkspace& workspace) {
  const double dt = checked_step(data);
  return regression_pass(data, resolved(options, data, dt), dt, false, workspace).reg;
}

// The friction law the identified terms make (Fs = Fc + Fs_minus_Fc when the Stribeck term is
// present), validated; or none with a warning when the estimates break a law's rules.
void detail::attach_idim_law(Result& r, const IdimOptions& o, double vs) {
  auto has = [&](const char* n) { return r.find(n) != nullptr; };
  auto val = [&](const char* n) { return has(n) ? r.value(n) : 0.0; };
  const bool stribeck = has("Fs_minus_Fc");
  const double dF = val("Fs_minus_Fc");
  LawSpec spec;
  if (has("Fc_pos") && has("Fc_neg")) {
    spec.name = stribeck ? "stribeck-asymmetric" : "coulomb-viscous-asymmetric";
    for (const char* side : {"_pos", "_neg"}) {
      const std::string s(side);
      spec.scalars["Fc" + s] = val(("Fc" + s).c_str());
      spec.scalars["Fv" + s] = val(("Fv" + s).c_str());
      if (stribeck) {
        spec.scalars["Fs" + s] = val(("Fc" + s).c_str()) + dF;
        spec.scalars["vs" + s] = vs;
        spec.scalars["delta" + s] = o.stribeck_delta;
      }
    }
  } else if (has("Fc") || has("Fv")) {
    spec.name = stribeck ? "stribeck" : (has("Fc") && has("Fv") ? "coulomb-viscous" : has("Fc") ? "coulomb" : "viscous");
    if (has("Fc") || stribeck) spec.scalars["Fc"] = val("Fc");
    if (has("Fv") || stribeck) spec.scalars["Fv"] = val("Fv");
    if (stribeck) {
      spec.scalars["Fs"] = val("Fc") + dF;
      spec.scalars["vs"] = vs;
      spec.scalars["delta"] = o.stribeck_delta;
    }
  } else {
    return;  // no friction terms: nothing to simulate with
  }
  if (stribeck && dF < 0) {
    r.diagnostics.warnings.push_back("Fs_minus_Fc = " + detail::format_value(dF, 6) + " " + std::string(unit(Quantity::force, o.axis)) +
                                     " is negative: friction near zero speed is lower than Fc, so this is a regression "
                                     "model, not a stribeck law that can be simulated");
    return;
  }
  // The terms of the conditions are the law's effects (models/law_effects.hpp): a load-dependent
  // level, a temperature-dependent viscous coefficient about T_ref, a position ripple. load_gain
  // is the load itself acting on the axis, not friction: it stays a parameter.
  LawSpec with_effects = spec;
  if (has("mu_load")) with_effects.scalars["mu_load"] = val("mu_load");
  if (has("Fv_per_K")) {
    with_effects.scalars["T_ref"] = o.temperature_ref;
    with_effects.scalars["Fv_per_K"] = val("Fv_per_K");
  }
  if (has("ripple_sin_1")) {
    with_effects.scalars["ripple_period"] = o.ripple_period;
    for (int h = 1; h <= o.ripple_harmonics; ++h) {
      with_effects.arrays["ripple_a"].push_back(val(("ripple_sin_" + std::to_string(h)).c_str()));
      with_effects.arrays["ripple_b"].push_back(val(("ripple_cos_" + std::to_string(h)).c_str()));
    }
  }
  const bool effects = with_effects.scalars.size() != spec.scalars.size();
  try {
    FrictionLaw::from_spec(with_effects);
    r.law = with_effects;
  } catch (const std::invalid_argument& e) {
    if (!effects) {
      r.diagnostics.warnings.push_back(std::string("the estimates do not make a valid friction law to simulate: ") + e.what());
      return;
    }
    try {  // the velocity law alone, the conditions left to the parameters
      FrictionLaw::from_spec(spec);
      r.law = spec;
      r.diagnostics.warnings.push_back(std::string("the law is attached without the load, temperature and ripple "
                                                   "terms, which do not make valid effects of it: ") + e.what());
    } catch (const std::invalid_argument& e2) {
      r.diagnostics.warnings.push_back(std::string("the estimates do not make a valid friction law to simulate: ") + e2.what());
      return;
    }
  }
  if (r.model == "idim-custom" && r.find("M") != nullptr && !o.extra_terms.size()) r.model = spec.name;
}

namespace {

Result identify_idim_fixed(const IdimData& data, const IdimOptions& options, double dt, IdimWorkspace& workspace,
                           Vec* velocity = nullptr, std::vector<Eigen::Index>* sample = nullptr);

}  // namespace

// The table names only the fields an option sets (designated initializers).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
MethodInfo detail::idim_method_info() {
  const IdimOptions d;  // every default of the table is the struct's
  MethodInfo m;
  m.summary = "inverse dynamic model least squares on a trajectory";
  m.fit_signal = "drive force";
  m.fit_quantity = Quantity::force;
  m.options = {
      {.name = "terms", .type = OptionType::list, .default_value = d.terms,
       .help = "Regressors in column order: inertia, viscous, coulomb, offset, asymmetric (Fv_pos, Fc_pos, Fv_neg, "
               "Fc_neg; then leave out offset), each of viscous_pos, coulomb_pos, viscous_neg, coulomb_neg alone, "
               "stribeck (Fs_minus_Fc with --vs, --delta), load (load_gain, mu_load; needs --load), temperature "
               "(Fv_per_K; needs --temperature), ripple (ripple_sin_k, ripple_cos_k; needs --ripple-period); an "
               "unknown term is refused with the list"},
      {.name = "cutoff", .type = OptionType::number, .unit = "Hz",
       .help = "Position low-pass cut-off. Default from the sample rate fs: min(100 Hz, fs/10) (EMPS: 100 Hz at 1 kHz)",
       .min = 0, .min_open = true, .deprecated_keywords = {"cutoff_hz"}},
      {.name = "filter-order", .type = OptionType::integer, .default_value = static_cast<long long>(d.filter_order),
       .help = "Butterworth order of the low-pass", .min = 1},
      {.name = "padlen", .type = OptionType::integer, .default_value = static_cast<long long>(d.padlen),
       .help = "Samples of odd padding of the zero-phase low-pass", .min = 0},
      {.name = "decimate", .type = OptionType::integer,
       .help = "Keep one sample in N after the anti-alias filter. Default from fs: floor(fs/100 Hz), 1 to 10 (EMPS: 10)",
       .min = 1, .deprecated_keywords = {"decimation"}},
      {.name = "skip", .type = OptionType::integer,
       .help = "Samples dropped at the start (filter transient). Default from fs: five periods of the cut-off less "
               "one sample (EMPS: 49)",
       .min = 0},
      {.name = "skip-end", .type = OptionType::integer, .default_value = static_cast<long long>(d.skip_end),
       .help = "Samples dropped at the end (a record that ends in motion needs some)", .min = 0},
      {.name = "from", .type = OptionType::text,
       .help = "What the regressors are built from when the data has both: position (filtered, differentiated "
               "twice) or velocity (filtered like the position, differentiated once). Default: position, or "
               "velocity when only a velocity is given",
       .words = {"position", "velocity"}},
      {.name = "vs", .type = OptionType::number, .unit = "m/s", .rotary_unit = "rad/s", .default_value = d.stribeck_vs,
       .help = "Stribeck velocity of the stribeck term, or 'search' for the value that minimises the identification "
               "error (the best of a 40-point log grid from 1e-4 to 0.5 of the top speed, refined by a golden-section "
               "search)",
       .min = 0, .min_open = true, .words = {"search"},
       .expected_text = "a Stribeck velocity (m/s or rad/s) or 'search'", .deprecated_keywords = {"stribeck_vs"},
       .applies_if = {when_value("terms", {"stribeck"})}},
      {.name = "delta", .type = OptionType::number, .default_value = d.stribeck_delta,
       .help = "Stribeck exponent of the stribeck term", .min = 0, .min_open = true,
       .deprecated_keywords = {"stribeck_delta"}, .applies_if = {when_value("terms", {"stribeck"})}},
      {.name = "delay", .type = OptionType::integer, .unit = "samples", .default_value = static_cast<long long>(d.input_delay),
       .help = "Samples by which the applied force lags the recorded input (EMPS: 1, its controller output is "
               "applied one sample later)",
       .min = 0, .deprecated_keywords = {"input_delay"}},
      {.name = "min-velocity", .type = OptionType::number, .unit = "m/s", .rotary_unit = "rad/s",
       .default_value = d.min_velocity, .help = "No excitation when the largest |velocity| is not above this", .min = 0},
      {.name = "exclude-below", .type = OptionType::number, .unit = "m/s", .rotary_unit = "rad/s",
       .default_value = d.exclude_below,
       .help = "Leave out the samples (after decimation) whose filtered |velocity| is below this: near standstill "
               "the Coulomb term's sign follows noise and biases Fc; 0 keeps all",
       .min = 0},
      {.name = "max-condition", .type = OptionType::number, .default_value = d.max_condition,
       .help = "Largest condition number of the column-normalised regressor accepted", .min = 1},
      {.name = "load", .type = OptionType::column, .unit = "N", .rotary_unit = "N m",
       .help = "Column of the load force or torque the contact transmits, for the load term (Python: an array of "
               "the data's length)",
       .applies_if = {when_value("terms", {"load"})}},
      {.name = "temperature", .type = OptionType::column, .unit = "degC or K",
       .help = "Column of the contact's temperature (grease, gearbox), for the temperature term (Python: an array of "
               "the data's length)",
       .applies_if = {when_value("terms", {"temperature"})}},
      {.name = "temperature-ref", .type = OptionType::number, .unit = "degC or K",
       .help = "Reference temperature T_ref of the temperature term, in the temperature column's unit. Default: the "
               "mean temperature of the used samples (reported)",
       .applies_if = {when_value("terms", {"temperature"})}},
      {.name = "ripple-period", .type = OptionType::number, .unit = "m", .rotary_unit = "rad",
       .help = "Period P of the ripple term: the distance over which cogging or a screw's pitch repeats (required by "
               "the ripple term)",
       .min = 0, .min_open = true, .applies_if = {when_value("terms", {"ripple"})}},
      {.name = "ripple-harmonics", .type = OptionType::integer,
       .default_value = static_cast<long long>(d.ripple_harmonics),
       .help = "Harmonics K of the ripple term: parameters ripple_sin_1, ripple_cos_1, ... ripple_cos_K", .min = 1,
       .applies_if = {when_value("terms", {"ripple"})}},
      {.name = "validate", .type = OptionType::file,
       .help = "Second data file for a cross-test with the identified parameters (Python: a dict with time, force "
               "and position or velocity)"},
      {.name = "iv", .type = OptionType::flag, .default_value = false,
       .help = "IDIM-IV for a record taken in a closed loop: instruments from the model's own closed loop, "
               "simulated with the experiment's controller (--controller and its gains, or --scenario) and "
               "reference (--reference); removes the bias the loop's reaction to disturbances gives least squares"},
      {.name = "scenario", .type = OptionType::file,
       .help = "IDIM-IV: a scenario YAML of the experiment (examples/emps_closed_loop.yaml) whose controller section "
               "gives the controller (type, gains, limit, delay; EMPS pulses); its plant must be an axis. Read as "
               "validate reads it (its data file replaced by DATA, friction and M not used); the controller options "
               "given override its values (Python: a path, read with its own data file, or a Scenario)",
       .applies_if = {when_given("iv")}},
      {.name = "reference", .type = OptionType::column, .unit = "m", .rotary_unit = "rad",
       .help = "IDIM-IV: column of the closed loop's reference position (Python: an array of the data's length)",
       .applies_if = {when_given("iv")}},
      {.name = "feedforward", .type = OptionType::column, .unit = "N", .rotary_unit = "N m",
       .help = "IDIM-IV: column of the feedforward force the drive added to the controller's output (optional; "
               "Python: an array of the data's length)",
       .applies_if = {when_given("iv")}},
      {.name = "controller", .type = OptionType::text,
       .help = "IDIM-IV: the experiment's controller, sampled at the record's rate: pid (force = kp (r - q) + ki "
               "int(r - q) - kd qd + feedforward) or emps-pd (v = kp kv (r - q) - kv qd_m, force = drive-gain v; "
               "EMPS benchmark)",
       .words = {"pid", "emps-pd"}, .applies_if = {when_given("iv")},
       // Not given: the --scenario's controller.type (describe_controller records it).
       .taken_text = "iv_controller_type"},
      {.name = "kp", .type = OptionType::number,
       .units = {{when_value("controller", {"pid"}), "N/m", "N m/rad"}, {when_value("controller", {"emps-pd"}), "1/s", ""}},
       .help = "IDIM-IV: position gain (pid: N/m or N m/rad; emps-pd: the position loop's 1/s)", .min = 0, .scalar_name = true,
       .applies_if = {when_given("iv")}},
      {.name = "kd", .type = OptionType::number, .unit = "N s/m", .rotary_unit = "N m s/rad",
       .help = "IDIM-IV, pid: velocity feedback gain on the measured velocity. Default 0", .min = 0, .scalar_name = true,
       .applies_if = {when_given("iv")}},
      {.name = "ki", .type = OptionType::number, .unit = "N/(m s)", .rotary_unit = "N m/(rad s)",
       .help = "IDIM-IV, pid: integral gain. Default 0", .min = 0, .scalar_name = true,
       .applies_if = {when_given("iv")}},
      {.name = "kv", .type = OptionType::number, .unit = "V s/m", .rotary_unit = "V s/rad",
       .help = "IDIM-IV, emps-pd: velocity-loop gain (EMPS: kv of the data file, 243.45)", .min = 0, .scalar_name = true,
       .applies_if = {when_given("iv")}},
      {.name = "drive-gain", .type = OptionType::number, .unit = "N/V", .rotary_unit = "N m/V",
       .help = "IDIM-IV, emps-pd: force per volt of the controller's output (EMPS: gtau). Command line default: "
               "--gain",
       .min = 0, .min_open = true, .scalar_name = true, .applies_if = {when_given("iv")}},
      {.name = "control-limit", .type = OptionType::number,
       .units = {{when_value("controller", {"pid"}), "N", "N m"}, {when_value("controller", {"emps-pd"}), "V", ""}},
       .help = "IDIM-IV: saturation of the controller's output (pid: N or N m, default none; emps-pd: V, default "
               "10, the EMPS drive's)",
       .min = 0, .min_open = true, .scalar_name = true, .applies_if = {when_given("iv")}},
      {.name = "control-delay", .type = OptionType::integer, .unit = "samples",
       .help = "IDIM-IV: samples from computing the controller's output to applying it, 0 or 1 (default: pid 0, "
               "emps-pd 1)",
       .min = 0, .max = 1, .applies_if = {when_given("iv")}},
      {.name = "iv-iterations", .type = OptionType::integer, .default_value = static_cast<long long>(d.iv.max_iterations),
       .help = "IDIM-IV: largest number of iterations; not converged by then is an error", .min = 1,
       .applies_if = {when_given("iv")}},
      {.name = "iv-tolerance", .type = OptionType::number, .default_value = d.iv.tolerance,
       .help = "IDIM-IV: converged when no parameter's change moves the model force by more than this share of "
               "its norm",
       .min = 0, .min_open = true, .applies_if = {when_given("iv")}},
  };
  return m;
}
#pragma GCC diagnostic pop

namespace {
// The controller of --iv from the table's values over the scenario's controller (null: none), its
// sample period left to the record (IdimIvOptions::sample_at_record_rate); `sources` gets where
// each value came from. \throws InputError naming what is missing or contradicts the scenario.
Controller idim_iv_controller(const OptionValues& v, const IdimIvScenario* scenario,
                              std::map<std::string, std::string>& sources) {
  const auto missing = [](const std::string& what) {
    return InputError(errc::option_invalid,
                      "idim: --iv needs the experiment's controller: " + what +
                          " (Python: iv=True, controller=..., kp=..., and kd or kv, with reference=array; or scenario=)",
                      ErrorFields{.option = "--iv"});
  };
  // A gain still given by name was not resolved against a data file (a library caller's values).
  for (const char* name : {"kp", "kd", "ki", "kv", "drive-gain", "control-limit"})
    if (v.given(name) && std::isnan(v.number(name)))
      throw InputError(errc::option_invalid,
                       std::string("idim: --") + name + " '" + v.text(name) +
                           "': a scalar's name needs the data file to read it from (the command line reads the DATA "
                           "file's; Python: pass source=the Data from load())",
                       ErrorFields{.option = std::string("--") + name, .value = v.text(name)});
  const bool scenario_pid = scenario && std::holds_alternative<PidParams>(scenario->controller);
  const std::string scenario_kind = !scenario ? "" : scenario_pid ? "pid" : "emps-pd";
  const auto from_scenario = [&](const char* key) { return "scenario " + scenario->file + ": controller." + key; };
  std::string kind = v.text("controller");
  if (kind.empty()) {
    kind = scenario_kind;
    if (scenario) sources["controller"] = from_scenario("type");
  } else {
    if (scenario && kind != scenario_kind)
      throw InputError(errc::option_conflict,
                       "idim: --controller " + kind + " contradicts the scenario " + scenario->file +
                           ": its controller.type is " + scenario_kind +
                           "; leave --controller out to use the scenario's, or leave --scenario out",
                       ErrorFields{.file = scenario->file, .key = "controller.type", .option = "--controller", .value = kind});
    sources["controller"] = "--controller";
  }
  if (kind.empty())
    throw missing("give --controller pid with --kp N/m and --kd N s/m (optional --ki, --control-limit, "
                  "--feedforward COLUMN), or --controller emps-pd with --kp 1/s, --kv V s/m and --drive-gain N/V "
                  "(default --gain), or --scenario FILE with its controller; and --reference COLUMN, the reference "
                  "position");
  // Each value: the option when given, else the scenario's, else the default.
  const auto take = [&](const char* name, const char* key, double& field) {
    if (v.given(name)) {
      field = name == std::string("control-delay") ? static_cast<double>(v.integer(name)) : v.number(name);
      sources[name] = std::string("--") + name;
    } else {
      sources[name] = scenario ? from_scenario(key) : "default";
    }
  };
  const auto conflicts = [&](std::initializer_list<const char*> names, const char* other) {
    for (const char* name : names)
      if (v.given(name))
        throw InputError(errc::option_conflict, std::string("idim: --") + name + " belongs to --controller " + other + ", not " + kind,
                         ErrorFields{.option = std::string("--") + name});
  };
  if (kind == "pid") {
    if (!v.given("kp") && !scenario) throw missing("--controller pid needs --kp (N/m or N m/rad)");
    conflicts({"kv", "drive-gain"}, "emps-pd");
    PidParams p = scenario ? std::get<PidParams>(scenario->controller) : PidParams{};
    double delay = scenario ? p.delay : 0;
    take("kp", "Kp", p.Kp);
    take("kd", "Kd", p.Kd);
    take("ki", "Ki", p.Ki);
    take("control-limit", "limit", p.limit);
    take("control-delay", "delay", delay);
    if (scenario && !v.given("control-delay")) sources["control-delay"] = "default (a scenario's pid has none: 0)";
    p.delay = static_cast<int>(delay);
    if (!scenario) p.Ts = 1.0;  // the record's step, set by identify_idim
    return p;
  }
  if (!scenario && (!v.given("kp") || !v.given("kv")))
    throw missing("--controller emps-pd needs --kp (1/s) and --kv (V s/m or V s/rad)");
  if (!scenario && !v.given("drive-gain"))
    throw missing("--controller emps-pd needs --drive-gain (N/V or N m/V; the command line's default is --gain)");
  conflicts({"kd", "ki"}, "pid");
  EmpsPdParams p = scenario ? std::get<EmpsPdParams>(scenario->controller) : EmpsPdParams{};
  double delay = p.delay;
  take("kp", "kp", p.kp);
  take("kv", "kv", p.kv);
  take("drive-gain", "gtau", p.gtau);
  take("control-limit", "limit", p.limit);
  take("control-delay", "delay", delay);
  p.delay = static_cast<int>(delay);
  return p;
}
}  // namespace

IdimOptions make_idim_options(const OptionValues& v) { return make_idim_options(v, nullptr); }

IdimOptions make_idim_options(const OptionValues& v, const IdimIvScenario* scenario) {
  IdimOptions o;
  o.terms = v.list("terms");
  o.filter_order = static_cast<int>(v.integer("filter-order"));
  o.padlen = static_cast<Eigen::Index>(v.integer("padlen"));
  o.skip_end = static_cast<Eigen::Index>(v.integer("skip-end"));
  // Not given: chosen from the sample rate (idim_rate_defaults; the EMPS recipe at 1 kHz).
  o.auto_cutoff = !v.given("cutoff");
  o.auto_decimation = !v.given("decimate");
  o.auto_skip = !v.given("skip");
  if (v.given("cutoff")) o.cutoff_hz = v.number("cutoff");
  if (v.given("decimate")) o.decimation = static_cast<int>(v.integer("decimate"));
  if (v.given("skip")) o.skip = static_cast<Eigen::Index>(v.integer("skip"));
  const std::string from = v.text("from");
  o.source = from == "position" ? IdimSource::position : from == "velocity" ? IdimSource::velocity : IdimSource::automatic;
  if (v.text("vs") == "search") o.search_stribeck_vs = true;
  else o.stribeck_vs = v.number("vs");
  o.stribeck_delta = v.number("delta");
  o.input_delay = static_cast<Eigen::Index>(v.integer("delay"));
  o.min_velocity = v.number("min-velocity");
  o.exclude_below = v.number("exclude-below");
  o.max_condition = v.number("max-condition");
  if (v.given("temperature-ref")) o.temperature_ref = v.number("temperature-ref");
  if (v.given("ripple-period")) o.ripple_period = v.number("ripple-period");
  o.ripple_harmonics = static_cast<int>(v.integer("ripple-harmonics"));
  o.iv.max_iterations = static_cast<int>(v.integer("iv-iterations"));
  o.iv.tolerance = v.number("iv-tolerance");
  if (v.flag("iv")) {
    o.iv.enabled = true;
    o.iv.sample_at_record_rate = true;
    o.iv.controller = idim_iv_controller(v, scenario, o.iv.sources);
  } else {
    if (scenario && !v.given("scenario"))
      throw InputError(errc::option_conflict,
                       "idim: scenario= describes the controller for IDIM-IV, but iv=True is not given",
                       ErrorFields{.option = "scenario"});
    for (const char* name :
         {"controller", "scenario", "kp", "kd", "ki", "kv", "drive-gain", "control-limit", "control-delay"}) {
      if (!v.given(name)) continue;
      std::string keyword = name;
      std::replace(keyword.begin(), keyword.end(), '-', '_');
      throw InputError(errc::option_conflict,
                       std::string("idim: --") + name + " describes the controller for IDIM-IV, but --iv is not given (Python: " +
                           keyword + "= needs iv=True)",
                       ErrorFields{.option = std::string("--") + name});
    }
  }
  return o;
}

namespace {
// Is anything left in the residual? Residual checks against velocity, position and time
// (identify/adequacy.hpp), on the fitted (decimated) samples; the position is the recorded one
// at those samples.
void add_idim_adequacy(Result& r, const IdimData& data, const IdimOptions& o, const std::vector<Eigen::Index>& sample) {
  const auto& f = r.series.at("force");
  const auto& fm = r.series.at("force_model");
  std::vector<double> residual(f.size()), position;
  for (std::size_t i = 0; i < f.size(); ++i) residual[i] = f[i] - fm[i];
  if (data.position.size() > 0) {
    for (std::size_t k = 0; k < f.size(); ++k) position.push_back(data.position[sample[k]]);
  }
  if (residual.size() < kAdequacyMinSamples) return;
  AdequacyOptions ao;
  double ss = 0;
  for (double x : f) ss += x * x;
  ao.force_scale = std::sqrt(ss / static_cast<double>(f.size()));  // the drive force's rms
  add_adequacy(r, assess_residuals(r.series.at("velocity"), position, r.series.at("time"), residual,
                                   std::string(unit(Quantity::force, o.axis)),
                                   std::string(unit(Quantity::velocity, o.axis)), ao));
}
}  // namespace

namespace {

// What the attached law leaves to the parameters (it is the friction at zero load, at T_ref and
// without the ripple), and a viscous coefficient that the temperature term turns negative
// within the log's temperature range.
void describe_conditions(Result& r, const IdimData& data, const IdimOptions& o) {
  std::vector<std::string> carried;
  if (asks_for(o, "load")) carried.push_back("its levels grow by mu_load |load| (load_gain, the load acting on the axis, is not friction)");
  if (asks_for(o, "temperature"))
    carried.push_back("its viscous coefficient is Fv + Fv_per_K (T - T_ref), T_ref = " + detail::format_value(o.temperature_ref, 6));
  if (asks_for(o, "ripple")) carried.push_back("the position ripple ripple_a, ripple_b over ripple_period adds to it");
  if (carried.empty()) return;
  const bool with_effects = r.law && (r.law->scalars.count("mu_load") || r.law->scalars.count("T_ref") ||
                                      r.law->scalars.count("ripple_period"));
  std::string text = with_effects ? "the law carries the conditions: " : "the law leaves the conditions to the parameters: ";
  for (std::size_t i = 0; i < carried.size(); ++i) text += (i ? "; " : "") + carried[i];
  r.diagnostics.texts["law_conditions"] = text;
  if (asks_for(o, "temperature") && r.find("Fv") != nullptr) {
    const double fv = r.value("Fv"), per_k = r.value("Fv_per_K");
    for (const double t : {data.temperature.minCoeff(), data.temperature.maxCoeff()}) {
      const double at = fv + per_k * (t - o.temperature_ref);
      if (at < 0) {
        r.diagnostics.warnings.push_back(
            "the viscous coefficient Fv + Fv_per_K (T - T_ref) = " + detail::format_value(at, 6) + " " +
            std::string(unit(Quantity::viscous, o.axis)) + " is negative at T = " + detail::format_value(t, 6) +
            ", within the log's temperature range: the temperature term is not physical there (is the temperature "
            "confounded with the speed schedule? a warm-up run at constant speed separates them)");
        break;
      }
    }
  }
}

}  // namespace

// The Stribeck columns (idim_stribeck.hpp): one pass of the recipe, the Stribeck column rebuilt
// and decimated per trial into the workspace's buffer of that column.
struct detail::StribeckColumns::Impl {
  const IdimData& data;
  IdimWorkspace& workspace;
  IdimOptions options;
  Pass base;
  Eigen::Index j = -1;  // the Stribeck column (a built-in term: extras come after)
  bool usable = false;
  Impl(const IdimData& d, IdimWorkspace& w, const IdimOptions& o, double dt)
      : data(d), workspace(w), options(resolved(o, d, dt)), base(regression_pass(d, options, dt, false, w)) {}
};

detail::StribeckColumns::StribeckColumns(const IdimData& data, const IdimOptions& options, IdimWorkspace& workspace)
    : impl_(std::make_unique<Impl>(data, workspace, options, checked_step(data))) {
  const IdimRegression& reg = impl_->base.reg;
  for (std::size_t k = 0; k < reg.terms.size() && impl_->j < 0; ++k)
    if (reg.terms[k].parameter == "Fs_minus_Fc") impl_->j = static_cast<Eigen::Index>(k);
  if (impl_->j < 0) throw std::invalid_argument("idim: the vs search needs the 'stribeck' term among the terms");
  // A record without motion or force gives no fit at any vs: identify_idim_fixed says why.
  impl_->usable = reg.max_speed > no_motion_speed(data, impl_->options, impl_->base) && reg.y.cwiseAbs().maxCoeff() > 0.0;
}

detail::StribeckColumns::~StribeckColumns() = default;

const IdimOptions& detail::StribeckColumns::options() const { return impl_->options; }
const IdimRegression& detail::StribeckColumns::regression() const { return impl_->base.reg; }
bool detail::StribeckColumns::usable() const { return impl_->usable; }

const IdimRegression& detail::StribeckColumns::at(double vs) {
  Impl& m = *impl_;
  IdimRegression& reg = m.base.reg;
  const IdimOptions& options = m.options;
  const Eigen::Index n = m.data.time.size(), used = n - options.skip - options.skip_end;
  Eigen::Map<Vec> column(m.workspace.buffer(kFirstColumnBuffer + static_cast<std::size_t>(m.j), static_cast<std::size_t>(n)).data(), n);
  IdimOptions o = options;
  o.stribeck_vs = vs;
  builtin("stribeck", o).fill(*m.base.kinematics, column);
  const Vec all = options.decimation == 1
                      ? Vec(column.segment(options.skip, used))
                      : Vec(decimate_columns(ColumnViews{{column.data() + options.skip, used}}, options.decimation,
                                             m.workspace.filter()));
  // The rows the regression kept (exclude_below may have left some out): row k is raw sample
  // skip + k * decimation.
  for (Eigen::Index k = 0; k < reg.X.rows(); ++k)
    reg.X(k, m.j) = all((reg.sample[static_cast<std::size_t>(k)] - options.skip) / std::max(1, options.decimation));
  return reg;
}

double detail::StribeckColumns::error_percent(double vs) {
  const IdimRegression& reg = at(vs);
  std::vector<std::string> names;
  for (const auto& t : reg.terms) names.push_back(t.parameter);
  LeastSquaresOptions lso;
  lso.max_condition = impl_->options.max_condition;
  const LeastSquaresFit fit = linear_least_squares(reg.X, reg.y, names, lso);
  if (fit.refusal != LeastSquaresRefusal::none || !fit.theta.allFinite()) return std::numeric_limits<double>::infinity();
  const double e = 100.0 * std::sqrt(fit.residual.squaredNorm()) / reg.y.norm();
  return std::isfinite(e) ? e : std::numeric_limits<double>::infinity();
}

std::vector<double> detail::stribeck_vs_grid(double top_speed) {
  constexpr int kGrid = 40;
  std::vector<double> g;
  g.reserve(kGrid);
  for (int i = 0; i < kGrid; ++i) g.push_back(top_speed * std::pow(10.0, -4.0 + (4.0 - std::log10(2.0)) * i / (kGrid - 1)));
  return g;
}

// The identification residual alone chooses, never the cross-test.
double detail::searched_stribeck_vs(StribeckColumns& columns) {
  const double fallback = columns.options().stribeck_vs;
  if (!columns.usable()) return fallback;
  const std::vector<double> grid = stribeck_vs_grid(columns.regression().max_speed);
  double best = std::numeric_limits<double>::infinity();
  std::size_t at = 0;
  for (std::size_t i = 0; i < grid.size(); ++i)
    if (const double e = columns.error_percent(grid[i]); e < best) best = e, at = i;
  if (!std::isfinite(best)) return fallback;
  // Golden-section search on log vs between the best grid point's neighbours (30 steps shrink the
  // bracket of half a decade by 0.618^30, below 1e-6 of a decade).
  constexpr int kGoldenSteps = 30;
  const double phi = (std::sqrt(5.0) - 1) / 2;
  double a = std::log(grid[at > 0 ? at - 1 : at]), b = std::log(grid[std::min(at + 1, grid.size() - 1)]);
  double x1 = b - phi * (b - a), x2 = a + phi * (b - a);
  double f1 = columns.error_percent(std::exp(x1)), f2 = columns.error_percent(std::exp(x2));
  for (int it = 0; it < kGoldenSteps; ++it) {
    if (f1 < f2) b = x2, x2 = x1, f2 = f1, x1 = b - phi * (b - a), f1 = columns.error_percent(std::exp(x1));
    else a = x1, x1 = x2, f1 = f2, x2 = a + phi * (b - a), f2 = columns.error_percent(std::exp(x2));
  }
  const double refined = std::exp((a + b) / 2);
  return columns.error_percent(refined) < best ? refined : grid[at];
}


Result identify_idim(const IdimData& data, const IdimOptions& options) {
  IdimWorkspace workspace;  // the regressions of a vs search share it
  return identify_idim(data, options, workspace);
}

namespace {

Result identify_idim_unchecked(const IdimData& data, const IdimOptions& options_in, IdimWorkspace& workspace) {
  const double dt = checked_step(data);
  if (options_in.iv.enabled) detail::check_idim_iv_inputs(data, options_in);
  const IdimOptions options = resolved(options_in, data, dt);
  const auto terms = idim_terms(options);
  const bool has_stribeck = std::any_of(terms.begin(), terms.end(), [](const IdimTerm& t) { return t.parameter == "Fs_minus_Fc"; });
  IdimOptions o = options;
  if (options.search_stribeck_vs && has_stribeck) {
    detail::StribeckColumns columns(data, options, workspace);
    o.stribeck_vs = detail::searched_stribeck_vs(columns);
  }
  Vec v;  // the filtered velocity at the fitted samples, for the friction map
  std::vector<Eigen::Index> sample;  // the raw sample of each fitted row
  Result r = identify_idim_fixed(data, o, dt, workspace, &v, &sample);
  if (o.iv.enabled && r.ok()) detail::run_idim_iv(r, data, o, dt);
  if (has_stribeck) r.diagnostics.numbers["stribeck_vs"] = o.stribeck_vs;
  if (asks_for(o, "temperature")) r.diagnostics.numbers["temperature_ref"] = o.temperature_ref;
  if (asks_for(o, "ripple")) r.diagnostics.numbers["ripple_period"] = o.ripple_period;
  if (data.load.size() > 0 && !asks_for(o, "load"))
    r.diagnostics.warnings.push_back("a load column was given, but the terms do not include 'load': it is not used");
  if (data.temperature.size() > 0 && !asks_for(o, "temperature"))
    r.diagnostics.warnings.push_back("a temperature column was given, but the terms do not include 'temperature': it is not used");
  if (options.input_delay > 0) r.diagnostics.numbers["input_delay"] = static_cast<double>(options.input_delay);
  {
    auto& defaults = r.diagnostics.groups["defaults"];  // the settings chosen from the sample rate
    if (options_in.auto_cutoff) defaults["cutoff_hz"] = options.cutoff_hz;
    if (options_in.auto_decimation) defaults["decimation"] = options.decimation;
    if (options_in.auto_skip) defaults["skip"] = static_cast<double>(options.skip);
    if (defaults.empty()) r.diagnostics.groups.erase("defaults");
  }
  if (r.ok()) {
    detail::attach_idim_law(r, o, o.stribeck_vs);
    r.series["velocity"].assign(v.data(), v.data() + v.size());
    // The identified friction terms as a curve over +-max |v| (denser near 0, where Stribeck
    // terms bend), evaluated on the velocity itself, not on decimated columns.
    constexpr int kSide = 150;
    Vec grid(2 * kSide), zero = Vec::Zero(2 * kSide), curve = Vec::Zero(2 * kSide);
    const double top = v.cwiseAbs().maxCoeff();
    for (int i = 0; i < kSide; ++i) {
      const double a = top * std::pow((i + 1.0) / kSide, 2.0);
      grid(kSide - 1 - i) = -a;
      grid(kSide + i) = a;
    }
    const IdimKinematics k{IdimKinematics::View(nullptr, 0), IdimKinematics::View(grid.data(), grid.size()),
                           IdimKinematics::View(zero.data(), zero.size())};
    // The velocity terms only: a user's term may need the position; the ripple averages out over
    // position, the temperature term is 0 at T_ref, and the load term is taken at the mean load.
    IdimOptions ov = o;
    ov.extra_terms.clear();
    std::erase_if(ov.terms, [](const std::string& t) { return t == "load" || t == "temperature" || t == "ripple"; });
    for (const auto& t : idim_terms(ov))
      if (t.parameter != "M" && t.parameter != "offset") curve += r.value(t.parameter) * t.column(k);
    if (asks_for(o, "load")) curve += r.value("mu_load") * data.load.cwiseAbs().mean() * grid.unaryExpr([](double v) { return sign_of(v); });
    r.series["law_velocity"].assign(grid.data(), grid.data() + grid.size());
    r.series["law_force"].assign(curve.data(), curve.data() + curve.size());
    add_idim_adequacy(r, data, o, sample);
    describe_conditions(r, data, o);
  }
  return r;
}

}  // namespace

// Numbers or an error, never both (identify/finite_result.hpp): sums that overflow or underflow
// in double precision make an error, not an ok result with inf in its std or figures.
Result identify_idim(const IdimData& data, const IdimOptions& options, IdimWorkspace& workspace) {
  Result r = identify_idim_unchecked(data, options, workspace);
  detail::add_idim_condition_series(r, data, options);  // after IDIM-IV, which replaces the fit's series
  return finite_or_error(std::move(r));
}

namespace detail {

void set_idim_series(Result& r, const IdimData& data, const IdimRegression& reg, const Vec& theta, const IdimOptions& options) {
  const Eigen::Index p = reg.X.cols(), nobs = reg.X.rows();
  r.series.erase("time");
  const Vec model = reg.X * theta;
    auto& t = r.series["time"];
    for (Eigen::Index k = 0; k < nobs; ++k) t.push_back(data.time[reg.sample[static_cast<std::size_t>(k)]]);
    r.series["force"].assign(reg.y.data(), reg.y.data() + nobs);
    r.series["force_model"].assign(model.data(), model.data() + nobs);
    // The friction map: the force less the non-friction terms (inertia, offset, user terms)
    // against velocity, and the friction terms alone.
    Vec friction = reg.y, friction_model = Vec::Zero(nobs);
    for (Eigen::Index j = 0; j < p; ++j) {
      const std::string& name = reg.terms[static_cast<std::size_t>(j)].parameter;
      const bool is_friction = j < p - static_cast<Eigen::Index>(options.extra_terms.size()) && name != "M" &&
                               name != "offset" && name != "load_gain";
      if (is_friction) friction_model += reg.X.col(j) * theta(j);
      else friction -= reg.X.col(j) * theta(j);
    }
    r.series["friction"].assign(friction.data(), friction.data() + nobs);
    r.series["friction_model"].assign(friction_model.data(), friction_model.data() + nobs);
}

void add_idim_parameter_warnings(Result& r) {
  for (const auto& q : r.parameters) {
    constexpr double kPoorlyIdentified = 0.5;  // std above half the value: the estimate is not trustworthy
    if (q.flag.empty() && std::abs(q.std) > kPoorlyIdentified * std::abs(q.value)) {
      r.diagnostics.warnings.push_back(q.name + " = " + detail::format_value(q.value, 6) + " " + q.unit + " is poorly identified (std " +
                                       detail::format_value(q.std, 6) + ")");
    }
    // Fv_per_K may be negative (grease thins as it warms); the coefficients themselves may not.
    const bool must_be_positive = q.name == "M" || q.name == "mu_load" ||
                                  ((q.name.rfind("Fv", 0) == 0 || q.name.rfind("Fc", 0) == 0) && q.name != "Fv_per_K");
    if (must_be_positive && q.value < 0) {
      r.diagnostics.warnings.push_back(q.name + " = " + detail::format_value(q.value, 6) + " " + q.unit + " is negative: not physical");
    }
  }
}

}  // namespace detail

namespace {
// Standard deviations and correlation from the Newey-West covariance of the fit (identify/
// covariance.hpp), with the undetermined parameters of uncertainty.hpp's rules; std_ols the
// ordinary figure. The covariance used is named in the diagnostics.
void set_idim_uncertainty(Result& r, const Eigen::MatrixXd& X, const LeastSquaresFit& fit,
                          const std::vector<std::string>& names) {
  const HacCovariance hac = hac_covariance(X, fit.residual);
  set_uncertainty_from_sandwich(r, names, fit.information, hac.meat, fit.residual_variance);
  r.diagnostics.texts["covariance"] = hac.prewhitened ? "newey-west-prewhitened" : "newey-west";
  r.diagnostics.numbers["covariance_bandwidth"] = hac.bandwidth;
  r.diagnostics.numbers["covariance_rho"] = hac.rho;
}

// One identification at options resolved for the mean step dt (s); `velocity`, when given, gets
// the filtered velocity at the fitted samples.
Result identify_idim_fixed(const IdimData& data, const IdimOptions& options, double dt, IdimWorkspace& workspace,
                           Vec* velocity, std::vector<Eigen::Index>* sample) {
  Result r = new_result(method_info(MethodId::idim), "", options.axis);
  r.data_file = data.file;
  r.data_sha256 = data.sha256;
  const bool custom = !options.extra_terms.empty();
  Pass pass = regression_pass(data, options, dt, velocity != nullptr, workspace);
  if (velocity != nullptr) *velocity = std::move(pass.velocity);
  const IdimRegression& reg = pass.reg;
  r.model = model_name(reg.terms, custom);
  const Eigen::Index p = reg.X.cols(), nobs = reg.X.rows();
  r.diagnostics.numbers["dt"] = reg.dt;
  r.diagnostics.numbers["cutoff_hz"] = options.cutoff_hz;
  r.diagnostics.numbers["decimation"] = options.decimation;
  r.diagnostics.numbers["skipped_samples"] = static_cast<double>(options.skip);
  r.diagnostics.numbers["max_speed"] = reg.max_speed;
  if (options.exclude_below > 0) {
    r.diagnostics.numbers["exclude_below"] = options.exclude_below;
    r.diagnostics.numbers["excluded_samples"] = static_cast<double>(reg.excluded);
  }
  if (sample != nullptr) *sample = reg.sample;
  const bool from_velocity = pass.from_velocity;
  r.diagnostics.texts["regressors_from"] = from_velocity ? "velocity" : "position";

  if (nobs <= p) {
    return error_result(r, where(data) + std::to_string(nobs) + " samples after decimation" +
                               (reg.excluded > 0 ? " and exclude_below (" + std::to_string(reg.excluded) + " left out)" : "") +
                               " for " + std::to_string(p) + " parameters; expected more samples than parameters");
  }
  if (!(reg.max_speed > no_motion_speed(data, options, pass))) {
    return error_result(r, where(data) + "no excitation: the velocity never exceeds " + detail::format_value(options.min_velocity, 6) +
                               " (max |qd| = " + detail::format_value(reg.max_speed, 6) +
                               "); IDIM needs a trajectory that moves in both directions");
  }
  // A force that is zero throughout (a drive gain of 0, an unconnected channel) explains nothing.
  if (!(reg.y.cwiseAbs().maxCoeff() > 0.0)) {
    return error_result(r, where(data) + "the force is zero throughout (max |force| = 0" +
                               std::string(options.input_delay > 0 ? " after the delay" : "") +
                               "): check the force column or the drive gain; the data cannot give an answer");
  }
  std::vector<std::string> names;
  for (const auto& t : reg.terms) names.push_back(t.parameter);
  LeastSquaresOptions lso;
  lso.max_condition = options.max_condition;
  const LeastSquaresFit fit = linear_least_squares(reg.X, reg.y, names, lso);
  r.diagnostics.condition_number = fit.condition_number;
  // Column-normalised condition number: independent of units, the measure of identifiability.
  if (fit.condition_number_scaled > 0) r.diagnostics.numbers["condition_number_scaled"] = fit.condition_number_scaled;
  switch (fit.refusal) {
    case LeastSquaresRefusal::none: break;
    case LeastSquaresRefusal::no_excitation:  // a zero column: no motion in one direction, no acceleration
      return error_result(r, where(data) + fit.message + " (e.g. no motion, or none in that direction); rank-deficient regressors");
    case LeastSquaresRefusal::rank_deficient:
      return error_result(r, where(data) + fit.message + "; the trajectory does not excite the terms independently");
    case LeastSquaresRefusal::too_few_samples: return error_result(r, where(data) + fit.message);
  }
  const Vec& theta = fit.theta;
  const double ee = fit.residual.squaredNorm();
  const double s2 = fit.residual_variance;
  r.fit.relative_error_percent = 100.0 * std::sqrt(ee) / reg.y.norm();
  r.fit.rmse = fit.rmse;
  r.fit.samples = static_cast<std::size_t>(nobs);
  if (!theta.allFinite() || !std::isfinite(r.fit.relative_error_percent) || !std::isfinite(r.fit.rmse)) {
    return error_result(r, where(data) + "the least-squares fit gave figures that are not finite numbers; "
                               "the data cannot give an answer (check the force and motion columns)");
  }
  for (Eigen::Index j = 0; j < p; ++j) {
    const auto& t = reg.terms[static_cast<std::size_t>(j)];
    r.parameters.push_back({t.parameter, theta(j), 0.0, std::string(unit(t.quantity, options.axis)), ""});
  }
  // std from the Newey-West covariance over the determined parameters, std_ols = s sqrt(diag((X'X)^-1)).
  set_idim_uncertainty(r, reg.X, fit, names);
  detail::set_idim_series(r, data, reg, theta, options);
  r.diagnostics.numbers["residual_std"] = std::sqrt(s2);

  detail::add_idim_parameter_warnings(r);
  return r;
}

}  // namespace

ValidationFigures cross_test(const Result& identified, const IdimData& data, const IdimOptions& options) {
  IdimWorkspace workspace;
  return cross_test(identified, data, options, workspace);
}

ValidationFigures cross_test(const Result& identified, const IdimData& data, const IdimOptions& options,
                             IdimWorkspace& workspace) {
  if (!identified.ok()) {
    throw std::invalid_argument("cross_test: the identification failed (" + identified.message + "); nothing to test");
  }
  const double dt = checked_step(data);
  IdimOptions o = resolved(options, data, dt);
  if (const auto it = identified.diagnostics.numbers.find("stribeck_vs"); it != identified.diagnostics.numbers.end())
    o.stribeck_vs = it->second;  // the value the identification used (searched or given)
  if (const auto it = identified.diagnostics.numbers.find("temperature_ref"); it != identified.diagnostics.numbers.end())
    o.temperature_ref = it->second;  // the identification's reference, not this record's mean
  const IdimRegression reg = regression_pass(data, o, dt, false, workspace).reg;
  Vec theta(reg.X.cols());
  for (std::size_t j = 0; j < reg.terms.size(); ++j) theta(static_cast<Eigen::Index>(j)) = identified.value(reg.terms[j].parameter);
  const Vec e = reg.y - reg.X * theta;
  ValidationFigures v;
  v.file = data.file;
  v.sha256 = data.sha256;
  v.relative_error_percent = 100.0 * e.norm() / reg.y.norm();
  v.rmse = std::sqrt(e.squaredNorm() / static_cast<double>(e.size()));
  v.samples = static_cast<std::size_t>(e.size());
  {  // figure signals, sampled as the identification's (see identify_idim_fixed)
    const Vec model = reg.X * theta;
    auto& t = v.series["time"];
    for (Eigen::Index k = 0; k < e.size(); ++k) t.push_back(data.time[reg.sample[static_cast<std::size_t>(k)]]);
    v.series["force"].assign(reg.y.data(), reg.y.data() + reg.y.size());
    v.series["force_model"].assign(model.data(), model.data() + model.size());
  }
  return v;
}

}  // namespace frictionlab
