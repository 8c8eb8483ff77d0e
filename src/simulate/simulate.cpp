#include "frictionlab/cancellation.hpp"
#include "frictionlab/error.hpp"
#include "frictionlab/models/parameter.hpp"
#include "frictionlab/plants/backlash_axis.hpp"
#include "frictionlab/simulate/closed_loop.hpp"
#include "frictionlab/simulate/simulate.hpp"
#include "frictionlab/simulate/output_size.hpp"
#include "simulate/stiff_system.hpp"
#include "small_vector.hpp"
#include "step_interpolant.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <sstream>
#include <exception>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include <unistd.h>

namespace frictionlab {

const char* solver_mode_name(SolverMode mode) {
  switch (mode) {
    case SolverMode::automatic: return "auto";
    case SolverMode::hybrid: return "hybrid";
    case SolverMode::stiff: return "stiff";
    case SolverMode::fixed_step: return "fixed-step";
  }
  return "?";
}

double output_rows(const SimulationOptions& o) { return std::floor(o.duration * o.output_rate * (1.0 + 1e-12) + 1e-9) + 1.0; }

double output_bytes(const SimulationOptions& o, int law_states) {
  // time and one contact's nine columns (position ... stuck, drive), then the caller's extras.
  return output_rows(o) * (10.0 + std::max(law_states, 0)) * static_cast<double>(sizeof(double));
}

double max_output_bytes() { return memory_budget(); }

namespace {

// A static law that holds a stuck contact at some condition: a breakaway level > 0 at T_ref and no
// load, or levels that a load or a temperature can raise above 0.
bool has_stiction(const FrictionLaw& law) {
  if (law.is_dynamic()) return false;
  if (law.breakaway_positive() > 0.0 || law.breakaway_negative() > 0.0) return true;
  const LawEffects& e = law.effects();
  return (e.load && e.load->mu_static > 0) || (e.temperature && e.temperature->Fc_per_K != 0);
}

void check_options(const SimulationOptions& o, SolverMode mode) {
  auto positive = [](const char* name, double v, const char* unit) {
    if (!(std::isfinite(v) && v > 0))
      throw std::invalid_argument(std::string("simulation option ") + name + " = " + detail::format_value(v) + " must be > 0 (" + unit + ")");
  };
  positive("duration", o.duration, "s");
  positive("output_rate", o.output_rate, "Hz");
  if (!std::isfinite(o.initial_position) || !std::isfinite(o.initial_velocity))
    throw std::invalid_argument("simulation option initial position/velocity must be finite, got " +
                                detail::format_value(o.initial_position) + ", " + detail::format_value(o.initial_velocity));
  for (const auto* list : {&o.initial_positions, &o.initial_velocities})
    for (double v : *list)
      if (!std::isfinite(v))
        throw std::invalid_argument("simulation option initial_positions/initial_velocities must be finite, got " + detail::format_value(v));
  if (mode == SolverMode::fixed_step) {
    positive("dt", o.dt, "s");
    const double ratio = 1.0 / (o.output_rate * o.dt);
    if (ratio < 1.0 - 1e-9 || std::abs(ratio - std::round(ratio)) > 1e-6 * ratio)
      throw std::invalid_argument("simulation option dt = " + detail::format_value(o.dt) + " s must divide the output period 1/output_rate = " +
                                  detail::format_value(1.0 / o.output_rate) + " s a whole number of times");
  } else {
    positive("rtol", o.rtol, "relative");
    positive("atol", o.atol, "absolute, state units");
    if (!(std::isfinite(o.max_step) && o.max_step >= 0))
      throw std::invalid_argument("simulation option max_step = " + detail::format_value(o.max_step) + " must be >= 0 (s; 0 = no limit)");
  }
  if (o.max_steps <= 0)
    throw std::invalid_argument("simulation option max_steps = " + std::to_string(o.max_steps) + " must be > 0");
}

// Refuses, before anything is allocated, an output larger than the memory there is.
void check_output_size(const SimulationOptions& o, int law_states) {
  char rows[32];
  std::snprintf(rows, sizeof rows, "%.3g", output_rows(o));
  check_memory(output_bytes(o, law_states),
               "simulation options duration = " + detail::format_value(o.duration) + " s and output_rate = " +
                   detail::format_value(o.output_rate) + " Hz give " + rows + " output rows",
               {.key = "duration", .value = detail::format_value(o.duration)});
}

// Refuses, before the run, more steps than the work budget: output rows, fixed steps (duration /
// dt) and controller samples (duration / Ts) each count one work unit.
void check_steps(const SimulationOptions& o, SolverMode mode, double Ts) {
  const double rows = output_rows(o);
  check_work(rows, "output rows", "simulation options duration = " + detail::format_value(o.duration) + " s and output_rate = " + detail::format_value(o.output_rate) + " Hz", {.key = "duration", .value = detail::format_value(o.duration)});
  if (mode == SolverMode::fixed_step)
    check_work(o.duration / o.dt, "fixed steps", "simulation options duration = " + detail::format_value(o.duration) + " s and dt = " + detail::format_value(o.dt) + " s", {.key = "solver.dt", .value = detail::format_value(o.dt)});
  if (Ts > 0) {
    // The sample instants are listed before the run (the corners of the step schedule): about
    // 48 bytes each, with the sort's pairs and the vectors' growth.
    const std::string what = "duration = " + detail::format_value(o.duration) + " s at the plant's sample period Ts = " + detail::format_value(Ts) + " s";
    const ErrorFields fields{.key = "Ts", .value = detail::format_value(Ts)};
    check_work(o.duration / Ts, "controller samples", what, fields);
    check_memory(48.0 * o.duration / Ts, what + " (" + detail::format_value(std::floor(o.duration / Ts)) + " sample instants)", fields);
  }
}

// Numbers or an error, never both: a run whose columns hold an inf or NaN (a parameter beyond
// what double arithmetic holds, plant.Kb: 1e308 giving inf voltages) is refused, not returned.
// The temperature column is NaN by definition for a contact without a temperature effect.
void check_finite(const Trajectory& tr) {
  const std::vector<std::string> names = tr.names();
  for (const std::string& name : names) {
    if (name == "temperature" || (name.size() > 12 && name.compare(name.size() - 12, 12, ".temperature") == 0)) continue;
    const std::vector<double>& c = tr.column(name);
    for (std::size_t i = 0; i < c.size(); ++i)
      if (!std::isfinite(c[i]))
        throw InputError(errc::output_not_finite,
                         "the simulation's column '" + name + "' is " + detail::format_value(c[i]) + " at t = " +
                             detail::format_value(tr.time[i]) +
                             " s: a parameter or input beyond what the model can compute in double precision; "
                             "expected values that keep every force, voltage and state finite",
                         {.column = name, .value = detail::format_value(c[i])});
  }
}

// Output times: k / rate for k = 0..N, N = floor(duration * rate) (with a little slack so that
// duration = 2.0, rate = 100 gives 201 rows despite rounding).
std::size_t last_row(const SimulationOptions& o) {
  return static_cast<std::size_t>(std::floor(o.duration * o.output_rate * (1.0 + 1e-12) + 1e-9));
}

// Owns the SUNDIALS objects of one run.
struct Sundials {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr;
  N_Vector abstol = nullptr;
  N_Vector dky = nullptr;  // work vector of the StepInterpolant
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  void* mem = nullptr;
  Sundials() {
    if (SUNContext_Create(nullptr, &ctx) != 0) throw std::runtime_error("SUNDIALS: could not create a context");
  }
  ~Sundials() {
    if (mem) CVodeFree(&mem);
    if (LS) SUNLinSolFree(LS);
    if (A) SUNMatDestroy(A);
    if (abstol) N_VDestroy(abstol);
    if (dky) N_VDestroy(dky);
    if (y) N_VDestroy(y);
    if (ctx) SUNContext_Free(&ctx);
  }
  Sundials(const Sundials&) = delete;
  Sundials& operator=(const Sundials&) = delete;
};

// The state index of a backlash axis's motor position, the plant's own or a PID loop's inner
// plant's (a loop's states start with its plant's), or -1 for any other plant.
int motor_position_state(const Plant& plant) {
  const Plant* p = &plant;
  if (const auto* loop = dynamic_cast<const ClosedLoop*>(p)) p = &loop->inner();
  const auto* b = dynamic_cast<const BacklashAxis*>(p);
  return b ? b->motor_state() : -1;
}

class Engine {
 public:
  // `laws[k]` is contact k's law (never null: its Contact::law or `law`); the plant's contacts
  // were checked by the caller.
  Engine(const Plant& plant, const FrictionLaw& law, std::span<const FrictionLaw* const> laws,
         std::span<const InputSignal> inputs, const SimulationOptions& o, SolverMode mode)
      : plant_(plant), single_(dynamic_cast<const SingleContactPlant*>(&plant)), inputs_(inputs), o_(o), mode_(mode) {
    np_ = plant.num_states();
    nc_ = plant.num_contacts();
    ne_ = plant.num_events();
    kinematic_ = plant.kinematic();
    int z = np_;
    bool all_dynamic = true;
    for (int k = 0; k < nc_; ++k) {
      const Contact c = plant.contact(k);
      Body b;
      b.law = laws[static_cast<std::size_t>(k)];
      b.pos = c.position;
      b.vel = c.velocity;
      const bool dynamic = b.law->is_dynamic();
      all_dynamic = all_dynamic && dynamic;
      b.nz = dynamic ? b.law->num_states() : 0;
      b.z = z;
      z += b.nz;
      if (!o.environments.empty()) {
        b.env = &o.environments[static_cast<std::size_t>(k)];
        if (b.env->empty()) b.env = nullptr;
      }
      b.cond = b.env != nullptr || b.law->has_effects();
      b.fbp = dynamic ? 0.0 : b.law->breakaway_positive();
      b.fbn = dynamic ? 0.0 : b.law->breakaway_negative();
      // Hybrid modes only where stiction exists and the velocity is not imposed.
      b.hybrid = mode == SolverMode::hybrid && has_stiction(*b.law) && !kinematic_;
      hybrid_ = hybrid_ || b.hybrid;
      bodies_.push_back(b);
    }
    // Thermal states after every law state: one per contact with a thermal model.
    for (Body& b : bodies_)
      if (b.env && b.env->thermal) b.temp = z++;
    n_ = z;
    nz_ = n_ - np_;
    for (const Body& b : bodies_) any_cond_ = any_cond_ || b.cond;
    nroots_ = (hybrid_ ? 2 * nc_ : 0) + ne_;
    scratch_.assign(static_cast<std::size_t>(n_), 0.0);
    y_row_.assign(static_cast<std::size_t>(n_), 0.0);
    u_.assign(inputs.size(), InputValue{});
    // Constant inputs are evaluated once, here (the default input of a plant that has none).
    constant_inputs_ =
        std::all_of(inputs.begin(), inputs.end(), [](const InputSignal& in) { return in.shape == InputShape::constant; });
    if (constant_inputs_)
      for (std::size_t i = 0; i < u_.size(); ++i) u_[i] = inputs[i].at(0.0);
    // Contacts with conditions take the general paths (one_ false): the 1-DOF forms know no load,
    // temperature or ripple.
    one_ = single_ != nullptr && nc_ == 1 && inputs.size() == 1 && !any_cond_;
    force_.assign(static_cast<std::size_t>(nc_), 0.0);
    friction_.assign(static_cast<std::size_t>(nc_), 0.0);
    signals_.assign(static_cast<std::size_t>(nc_), PlantSignals{});
    found_.assign(static_cast<std::size_t>(std::max(nroots_, 1)), 0);
    g_prev_.assign(static_cast<std::size_t>(ne_), 0.0);
    g_now_.assign(static_cast<std::size_t>(ne_), 0.0);
    for (int e = 0; e < ne_; ++e) any_guard_ = any_guard_ || plant.guard_event(e);
    // The states that are no contact's position or velocity (integrated by explicit Euler in
    // fixed-step mode, unless the plant's fixed_step_update rewrites them).
    for (int i = 0; i < np_; ++i) {
      bool motion = false;
      for (const Body& b : bodies_) motion = motion || b.pos == i || b.vel == i;
      if (!motion) extras_.push_back(i);
    }
    sample_period_ = plant.sample_period();
    motor_ = motor_position_state(plant);
    if (nz_ > 0 && all_dynamic && !any_cond_ && mode != SolverMode::fixed_step) {
      system_.emplace(plant, law);
      if (!system_->has_jacobian()) system_.reset();
    }
  }

  Trajectory run() {
    Trajectory tr;
    const std::size_t rows = last_row(o_) + 1;
    // Each column reserves its rows up front: the run appends without reallocating.
    const auto column = [rows] {
      std::vector<double> c;
      c.reserve(rows);
      return c;
    };
    tr.time = column();
    tr.others.resize(static_cast<std::size_t>(nc_ - 1));
    for (int k = 0; k < nc_; ++k) {
      ContactColumns& c = column_set(tr, k);
      for (auto* col : {&c.position, &c.velocity, &c.friction, &c.applied, &c.current, &c.voltage, &c.reference, &c.stuck})
        *col = column();
      c.drive = column();
      if (bodies_[static_cast<std::size_t>(k)].env) c.load = column(), c.temperature = column();
      c.law_state.resize(static_cast<std::size_t>(bodies_[static_cast<std::size_t>(k)].nz));
      for (auto& col : c.law_state) col = column();
      tr.contact_names.push_back(plant_.contact(k).name);
    }
    if (motor_ >= 0) tr.motor_position = column();
    if (mode_ == SolverMode::fixed_step) {
      run_fixed(tr, rows);
      tr.stats.solver = "fixed-step";
    } else {
      run_cvode(tr, rows);
      tr.stats.solver = hybrid_ ? "hybrid" : "stiff";
    }
    return tr;
  }

 private:
  enum class Mode { free, stuck, slide_pos, slide_neg };

  // One friction contact: where it lives in y, its law and its hybrid mode.
  struct Body {
    const FrictionLaw* law = nullptr;
    int pos = 0, vel = 1;  // state indices
    int z = 0, nz = 0;     // its law states y[z .. z + nz)
    double fbp = 0.0, fbn = 0.0;  // breakaway levels (static laws)
    bool hybrid = false;   // has stuck/sliding modes
    Mode mode = Mode::free;
    double stuck_position = 0.0;
    const ContactEnvironment* env = nullptr;  // its load and temperature, or null
    bool cond = false;     // its friction depends on conditions (effects or an environment)
    int temp = -1;         // state index of its temperature (thermal model), or -1
  };

  static ContactColumns& column_set(Trajectory& tr, int k) {
    return k == 0 ? static_cast<ContactColumns&>(tr) : tr.others[static_cast<std::size_t>(k - 1)];
  }

  // ---- physics -------------------------------------------------------------------------------

  // The hot paths (right-hand side, root functions, output rows) are compiled twice: One = true
  // for a 1-DOF plant (one contact, one input, a SingleContactPlant; one_ says which applies),
  // with no loop over contacts or inputs and no test of the plant's kind; One = false for any
  // plant. Every other caller takes the general form.

  // Number of contacts, a constant for a 1-DOF plant.
  template <bool One>
  [[gnu::always_inline]] std::size_t contacts() const {
    if constexpr (One) return 1;
    return bodies_.size();
  }

  // The inputs at t into u_; nothing when they are all constant (evaluated once, in the constructor).
  template <bool One = false>
  [[gnu::always_inline]] void eval_inputs(double t) {
    if (constant_inputs_) return;
    if constexpr (One) {
      u_[0] = inputs_[0].at(t);
    } else {
      for (std::size_t i = 0; i < u_.size(); ++i) u_[i] = inputs_[i].at(t);
    }
  }

  // The plant's methods at the evaluated inputs u_. A 1-DOF plant is called through its scalar
  // methods: one virtual call per evaluation instead of two (the span forwarders), on the
  // engine's hottest path.
  template <bool One = false>
  [[gnu::always_inline]] void plant_applied(double t, std::span<const double> x) {
    if (One || single_) {
      force_[0] = single_->applied(t, x, u_[0]);
    } else {
      plant_.applied(t, x, u_, force_);
    }
  }
  template <bool One = false>
  [[gnu::always_inline]] void plant_derivatives(double t, std::span<const double> x, std::span<double> dx) {
    if (One || single_) {
      single_->derivatives(t, x, u_[0], friction_[0], dx);
    } else {
      plant_.derivatives(t, x, u_, friction_, dx);
    }
  }
  template <bool One = false>
  [[gnu::always_inline]] void plant_signals(double t, std::span<const double> x) {
    if (One || single_) {
      signals_[0] = single_->signals(t, x, u_[0]);
    } else {
      plant_.signals(t, x, u_, signals_);
    }
  }

  void set_mode(Body& b, Mode m) {
    stuck_count_ += (m == Mode::stuck) - (b.mode == Mode::stuck);
    b.mode = m;
  }

  // Sliding force of body b in direction s, with the one-sided limit at v -> 0 from that side
  // when v has not (or no longer) the sign s: keeps the right-hand side smooth over the step that
  // finds v = 0.
  static double slide_force(const Body& b, double v, int s) {
    if (v * s > 0) return b.law->sliding(v);
    // 1e-300 is far below any velocity scale (vs, dv, table points), so this is the limit value.
    return b.law->sliding(s * 1e-300);
  }
  // The same at conditions c, the law's part only (no ripple).
  static double slide_force(const Body& b, double v, int s, const Conditions& c) {
    return b.law->sliding(v * s > 0 ? v : s * 1e-300, c);
  }

  // The conditions of body b at time t, effective plant state x and integrator state y: its
  // position, its load (the environment's source; 0 without) and its temperature (its thermal
  // state, the environment's fixed value, or none = the law's T_ref).
  Conditions conditions(const Body& b, double t, std::span<const double> x, const double* y) const {
    Conditions c;
    c.position = x[static_cast<std::size_t>(b.pos)];
    if (b.env) {
      c.load = b.env->load.at(t, x);
      if (b.temp >= 0) {
        c.temperature = y[b.temp];
      } else {
        c.temperature = b.env->temperature_at(t);
      }
    }
    return c;
  }

  // The effective plant state: y itself, or a copy in scratch_ with the frozen positions and zero
  // velocities of stuck bodies, or the imposed velocity of a velocity drive. Inputs evaluated.
  template <bool One = false>
  [[gnu::always_inline]] std::span<const double> effective_state(const double* y) {
    if (stuck_count_ == 0 && !kinematic_) return {y, static_cast<std::size_t>(np_)};
    std::copy(y, y + np_, scratch_.begin());  // the plant's states (law states are read from y)
    if (stuck_count_ > 0)
      for (std::size_t k = 0; k < contacts<One>(); ++k) {
        const Body& b = bodies_[k];
        if (b.mode == Mode::stuck) {
          scratch_[static_cast<std::size_t>(b.pos)] = b.stuck_position;
          scratch_[static_cast<std::size_t>(b.vel)] = 0.0;
        }
      }
    if (kinematic_) scratch_[1] = u_[0].value;
    return {scratch_.data(), static_cast<std::size_t>(np_)};
  }

  // Friction on body b at effective state x (y for law states); force_ holds the applied forces
  // when a body is stuck.
  [[gnu::always_inline]] double friction_of(const Body& b, double t, std::span<const double> x, const double* y) const {
    if (b.cond) return friction_with_conditions(b, t, x, y);
    const double v = x[static_cast<std::size_t>(b.vel)];
    switch (b.mode) {
      case Mode::stuck: return force_[static_cast<std::size_t>(&b - bodies_.data())];
      case Mode::slide_pos: return slide_force(b, v, 1);
      case Mode::slide_neg: return slide_force(b, v, -1);
      case Mode::free: break;
    }
    if (b.nz > 0) return b.law->force(std::span<const double>(y + b.z, static_cast<std::size_t>(b.nz)), v);
    return b.law->sliding(v);
  }

  // friction_of for a body with conditions: the law at its conditions plus the ripple at its
  // position (a stuck body's friction is the applied force, which includes the ripple's share).
  double friction_with_conditions(const Body& b, double t, std::span<const double> x, const double* y) const {
    const double v = x[static_cast<std::size_t>(b.vel)];
    if (b.mode == Mode::stuck) return force_[static_cast<std::size_t>(&b - bodies_.data())];
    const Conditions c = conditions(b, t, x, y);
    const double r = b.law->ripple(c.position);
    switch (b.mode) {
      case Mode::slide_pos: return slide_force(b, v, 1, c) + r;
      case Mode::slide_neg: return slide_force(b, v, -1, c) + r;
      default: break;
    }
    if (b.nz > 0) return b.law->force(std::span<const double>(y + b.z, static_cast<std::size_t>(b.nz)), v, c) + r;
    return b.law->sliding(v, c) + r;
  }

  // The signals of body b's environment that are inputs of the run (a load over time, a
  // temperature log), null where it has none: their corners and step limits are the run's too.
  static std::array<const InputSignal*, 2> condition_signals(const Body& b) {
    if (!b.env) return {nullptr, nullptr};
    return {b.env->load.signal ? &*b.env->load.signal : nullptr, b.env->temperature_log ? &*b.env->temperature_log : nullptr};
  }

  // The breakaway levels of body b (positive, negative) at time t and effective state x.
  std::pair<double, double> levels(const Body& b, double t, std::span<const double> x, const double* y) const {
    if (!b.cond) return {b.fbp, b.fbn};
    const Conditions c = conditions(b, t, x, y);
    return {b.law->breakaway_positive(c), b.law->breakaway_negative(c)};
  }
  // The ripple force on body b at effective state x (0 without a ripple).
  double ripple_of(const Body& b, std::span<const double> x) const {
    return b.cond ? b.law->ripple(x[static_cast<std::size_t>(b.pos)]) : 0.0;
  }

  // Calls f(std::true_type{}) for a 1-DOF plant, else f(std::false_type{}): picks the compiled
  // form of a hot path.
  template <class F>
  [[gnu::always_inline]] void in_form(F&& f) {
    if (one_) {
      f(std::true_type{});
    } else {
      f(std::false_type{});
    }
  }

  void rhs(double t, const double* y, double* dy) {
    in_form([&](auto one) { rhs_t<decltype(one)::value>(t, y, dy); });
  }
  template <bool One>
  void rhs_t(double t, const double* y, double* dy) {
    eval_inputs<One>(t);
    const auto x = effective_state<One>(y);
    std::span<double> dx(dy, static_cast<std::size_t>(np_));
    if (stuck_count_ > 0) plant_applied<One>(t, x);
    for (std::size_t k = 0; k < contacts<One>(); ++k) friction_[k] = friction_of(bodies_[k], t, x, y);
    plant_derivatives<One>(t, x, dx);
    for (std::size_t k = 0; k < contacts<One>(); ++k) {
      const Body& b = bodies_[k];
      if (b.mode == Mode::stuck) {
        dx[static_cast<std::size_t>(b.pos)] = 0.0;
        dx[static_cast<std::size_t>(b.vel)] = 0.0;
      } else if (b.nz > 0) {
        const std::span<const double> z(y + b.z, static_cast<std::size_t>(b.nz));
        const std::span<double> dz(dy + b.z, static_cast<std::size_t>(b.nz));
        if (b.cond) {
          b.law->derivative(z, x[static_cast<std::size_t>(b.vel)], dz, conditions(b, t, x, y));
        } else {
          b.law->derivative(z, x[static_cast<std::size_t>(b.vel)], dz);
        }
      }
      if (b.temp >= 0) {
        // Heated by the velocity law's power (the ripple's share is conservative); 0 while stuck.
        const double v = b.mode == Mode::stuck ? 0.0 : x[static_cast<std::size_t>(b.vel)];
        const double P = (friction_[k] - ripple_of(b, x)) * v;
        dy[b.temp] = b.env->thermal->rate(y[b.temp], P);
      }
    }
  }

  // Root functions: two per contact when any contact has hybrid modes (stuck: applied minus each
  // breakaway level; sliding: v; no modes: constant), then the plant's own.
  void roots(double t, const double* y, double* g) {
    in_form([&](auto one) { roots_t<decltype(one)::value>(t, y, g); });
  }
  template <bool One>
  void roots_t(double t, const double* y, double* g) {
    // Sliding bodies need only their velocity: the inputs and the plant are evaluated only when a
    // body is stuck or the plant has event functions (most root evaluations happen while sliding).
    if (stuck_count_ == 0 && ne_ == 0) {
      for (std::size_t k = 0; k < contacts<One>(); ++k) {
        const Body& b = bodies_[k];
        g[2 * k] = b.hybrid ? y[b.vel] : 1.0;
        g[2 * k + 1] = 1.0;  // unused in a sliding mode
      }
      return;
    }
    eval_inputs<One>(t);
    const auto x = effective_state<One>(y);
    if (hybrid_) {
      if (stuck_count_ > 0) plant_applied<One>(t, x);
      for (std::size_t k = 0; k < contacts<One>(); ++k) {
        const Body& b = bodies_[k];
        if (b.mode == Mode::stuck && b.cond) {
          // The levels at the current load and temperature, against the applied force less the ripple.
          const auto [fbp, fbn] = levels(b, t, x, y);
          const double a = force_[k] - ripple_of(b, x);
          g[2 * k] = a - fbp;
          g[2 * k + 1] = a + fbn;
        } else if (b.mode == Mode::stuck) {
          g[2 * k] = force_[k] - b.fbp;
          g[2 * k + 1] = force_[k] + b.fbn;
        } else {
          g[2 * k] = b.hybrid ? x[static_cast<std::size_t>(b.vel)] : 1.0;
          g[2 * k + 1] = 1.0;  // unused in a sliding mode
        }
      }
    }
    if (ne_ > 0) {
      // Guards (a force between bodies) may depend on the friction: it is computed for them.
      if (any_guard_)
        for (std::size_t k = 0; k < contacts<One>(); ++k) friction_[k] = friction_of(bodies_[k], t, x, y);
      plant_.events(t, x, u_, friction_, std::span<double>(g + (hybrid_ ? 2 * nc_ : 0), static_cast<std::size_t>(ne_)));
    }
  }

  // An exception must not unwind through CVODE's C frames: the callbacks catch it, report an
  // unrecoverable failure (-1) and the exception is rethrown, as it was, once CVode returns.
  template <class F>
  static int guarded(void* user, F&& f) {
    auto* self = static_cast<Engine*>(user);
    try {
      f(self);
      return 0;
    } catch (...) {
      self->callback_exception_ = std::current_exception();
      return -1;
    }
  }
  // CVODE's vectors here are all serial ones (clones of sd_.y): NV_DATA_S reads their data
  // pointer in place, where N_VGetArrayPointer is a call through the vector's operations, on
  // every callback.
  static int rhs_cb(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
    return guarded(user, [&](Engine* self) { self->rhs(t, NV_DATA_S(y), NV_DATA_S(ydot)); });
  }
  static int roots_cb(sunrealtype t, N_Vector y, sunrealtype* g, void* user) {
    return guarded(user, [&](Engine* self) { self->roots(t, NV_DATA_S(y), g); });
  }
  // The analytic Newton matrix (dense, column-major) of the free motion with dynamic laws.
  static int jac_cb(sunrealtype t, N_Vector y, N_Vector /*fy*/, SUNMatrix J, void* user, N_Vector, N_Vector,
                    N_Vector) {
    return guarded(user, [&](Engine* self) {
      const auto n = static_cast<std::size_t>(self->n_);
      self->eval_inputs(t);
      self->system_->jacobian(t, std::span<const double>(NV_DATA_S(y), n), Inputs(self->u_),
                              std::span<double>(SM_DATA_D(J), n * n));
    });
  }
  static void error_cb(int code, const char* module, const char* function, char* msg, void* user) {
    if (code < 0) {
      auto* self = static_cast<Engine*>(user);
      self->error_ = std::string(module) + " " + function + ": " + msg;
    }
  }

  // One output row from the integrator state y at time t. Flattened (every call it makes that can
  // be inlined is): it runs once per output row, and the compiler otherwise leaves each column's
  // push_back and the input's evaluation as calls.
  void record(Trajectory& tr, double t, const double* y) {
    if (one_) {
      record_one(tr, t, y);
    } else {
      record_all(tr, t, y);
    }
  }

  // A 1-DOF plant's row, into the batch of the trajectory's own columns (law states straight into
  // theirs): the plant's scalar methods into locals, no per-contact tables.
  [[gnu::flatten]] void record_one(Trajectory& tr, double t, const double* y) {
    eval_inputs<true>(t);
    const auto x = effective_state<true>(y);
    const Body& b = bodies_[0];
    const InputValue& u = u_[0];
    double a = single_->applied(t, x, u);
    PlantSignals s = single_->signals(t, x, u);
    const double v = x[static_cast<std::size_t>(b.vel)];
    double f;
    switch (b.mode) {
      case Mode::stuck: f = a; break;
      case Mode::slide_pos: f = slide_force(b, v, 1); break;
      case Mode::slide_neg: f = slide_force(b, v, -1); break;
      case Mode::free:
      default:
        f = b.nz > 0 ? b.law->force(std::span<const double>(y + b.z, static_cast<std::size_t>(b.nz)), v) : b.law->sliding(v);
    }
    if (kinematic_) a += f, s.drive += f;  // the drive supplies the friction too
    batch_.add({t, x[static_cast<std::size_t>(b.pos)], v, f, a, s.current, s.voltage, s.reference, s.drive,
                b.mode == Mode::stuck ? 1.0 : 0.0});
    for (int i = 0; i < b.nz; ++i) tr.law_state[static_cast<std::size_t>(i)].push_back(y[b.z + i]);
    if (motor_ >= 0) tr.motor_position.push_back(x[static_cast<std::size_t>(motor_)]);
    if (batch_.full()) batch_.flush(tr);
  }

  // Rows of a 1-DOF trajectory gathered kRows at a time and appended to its columns with one
  // insert per column: a push_back per column and row (a capacity check and a size update each)
  // cost as much as the rest of recording a row.
  class RowBatch {
   public:
    // time, position, velocity, friction, applied, current, voltage, reference, drive, stuck
    static constexpr std::size_t kColumns = 10;
    static constexpr std::size_t kRows = 256;
    [[gnu::always_inline]] void add(const std::array<double, kColumns>& row) {
      for (std::size_t c = 0; c < kColumns; ++c) rows_[c][n_] = row[c];
      ++n_;
    }
    bool full() const { return n_ == kRows; }
    // Appends the gathered rows to tr's own columns (call once more at the end of a run).
    void flush(Trajectory& tr) {
      std::vector<double>* columns[kColumns] = {&tr.time,    &tr.position, &tr.velocity,  &tr.friction, &tr.applied,
                                                &tr.current, &tr.voltage,  &tr.reference, &tr.drive,    &tr.stuck};
      for (std::size_t c = 0; c < kColumns; ++c) columns[c]->insert(columns[c]->end(), rows_[c], rows_[c] + n_);
      n_ = 0;
    }

   private:
    double rows_[kColumns][kRows];
    std::size_t n_ = 0;
  };

  [[gnu::flatten]] void record_all(Trajectory& tr, double t, const double* y) {
    eval_inputs(t);
    const auto x = effective_state(y);
    plant_applied(t, x);
    plant_signals(t, x);
    tr.time.push_back(t);
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
      const Body& b = bodies_[k];
      const double f = friction_of(b, t, x, y);
      double a = force_[k];
      PlantSignals& s = signals_[k];
      if (kinematic_) a += f, s.drive += f;  // the drive supplies the friction too
      push_row(column_set(tr, static_cast<int>(k)), x[static_cast<std::size_t>(b.pos)], x[static_cast<std::size_t>(b.vel)], f, a,
               s, b.mode == Mode::stuck ? 1.0 : 0.0, y + b.z, b.nz);
      if (b.env) push_conditions(column_set(tr, static_cast<int>(k)), b, t, x, y);
    }
    if (motor_ >= 0) tr.motor_position.push_back(x[static_cast<std::size_t>(motor_)]);
  }

  // The load and temperature columns of a body with an environment.
  void push_conditions(ContactColumns& c, const Body& b, double t, std::span<const double> x, const double* y) const {
    const Conditions cond = conditions(b, t, x, y);
    c.load.push_back(cond.load);
    const auto& te = b.law->effects().temperature;
    c.temperature.push_back(cond.temperature ? *cond.temperature : te ? te->T_ref : std::numeric_limits<double>::quiet_NaN());
  }

  static void push_row(ContactColumns& c, double position, double velocity, double friction, double applied,
                       const PlantSignals& s, double stuck, const double* z, int nz) {
    c.position.push_back(position);
    c.velocity.push_back(velocity);
    c.friction.push_back(friction);
    c.applied.push_back(applied);
    c.current.push_back(s.current);
    c.voltage.push_back(s.voltage);
    c.reference.push_back(s.reference);
    c.drive.push_back(s.drive);
    c.stuck.push_back(stuck);
    for (int i = 0; i < nz; ++i) c.law_state[static_cast<std::size_t>(i)].push_back(z[i]);
  }

  // ---- hybrid mode logic ---------------------------------------------------------------------

  // Pins every stuck body of y at its frozen position with zero velocity.
  void pin_stuck(double* y) const {
    if (stuck_count_ == 0) return;
    for (const Body& b : bodies_)
      if (b.mode == Mode::stuck) {
        y[b.pos] = b.stuck_position;
        y[b.vel] = 0.0;
      }
  }

  // The applied force on body k at time t with it at rest (y[vel] = 0, written) at its own
  // position; the other bodies as they are (the stuck ones pinned). By the plant's contract it
  // does not depend on any friction, so each body is decided on its own.
  double applied_at_rest(std::size_t k, double t, double* y) {
    eval_inputs(t);
    y[bodies_[k].vel] = 0.0;
    const auto x = effective_state(y);
    if (x.data() != scratch_.data()) std::copy(x.begin(), x.end(), scratch_.begin());
    scratch_[static_cast<std::size_t>(bodies_[k].vel)] = 0.0;
    plant_applied(t, std::span<const double>(scratch_.data(), static_cast<std::size_t>(np_)));
    return force_[k];
  }

  // Decides the mode of body k at rest at time t (start, after a stop, after an input jump or a
  // controller sample), and records the switch it makes.
  void settle_at_rest(Trajectory& tr, std::size_t k, double t, double* y, bool from_stuck, int previous_dir) {
    Body& b = bodies_[k];
    if (from_stuck) y[b.pos] = b.stuck_position;
    const double a = applied_at_rest(k, t, y);
    // A body with conditions: its levels at the load and temperature now, against the applied
    // force less the ripple at its position (scratch_ holds the state at rest).
    double fbp = b.fbp, fbn = b.fbn, push = a;
    if (b.cond) {
      const std::span<const double> xr(scratch_.data(), static_cast<std::size_t>(np_));
      std::tie(fbp, fbn) = levels(b, t, xr, y);
      push = a - ripple_of(b, xr);
    }
    Mode next;
    if (push > fbp) {
      next = Mode::slide_pos;
    } else if (push < -fbn) {
      next = Mode::slide_neg;
    } else {
      next = Mode::stuck;
    }
    const int contact = static_cast<int>(k);
    if (next == Mode::stuck) {
      b.stuck_position = y[b.pos];
      if (!from_stuck && previous_dir != 0) tr.switches.push_back({t, SwitchKind::stick, y[b.pos], a, 0, contact});
    } else {
      const int dir = next == Mode::slide_pos ? 1 : -1;
      if (from_stuck) {
        y[b.pos] = b.stuck_position;
        tr.switches.push_back({t, SwitchKind::breakaway, y[b.pos], a, dir, contact});
      } else if (previous_dir != 0) {
        tr.switches.push_back({t, SwitchKind::reversal, y[b.pos], a, dir, contact});
      }
    }
    set_mode(b, next);
  }

  // Every stuck body decided again (after an input corner, a sample or a plant event).
  void settle_stuck(Trajectory& tr, double t, double* y) {
    if (stuck_count_ == 0) return;
    for (std::size_t k = 0; k < bodies_.size(); ++k)
      if (bodies_[k].mode == Mode::stuck) settle_at_rest(tr, k, t, y, true, 0);
  }

  void set_root_directions() {
    dirs_.assign(static_cast<std::size_t>(nroots_), 0);
    if (hybrid_) {
      for (std::size_t k = 0; k < bodies_.size(); ++k) {
        int* d = dirs_.data() + 2 * k;
        switch (bodies_[k].mode) {
          case Mode::stuck: d[0] = 1, d[1] = -1; break;
          case Mode::slide_pos: d[0] = -1, d[1] = 0; break;
          case Mode::slide_neg: d[0] = 1, d[1] = 0; break;
          case Mode::free: d[0] = 0, d[1] = 0; break;
        }
      }
    }
    // A guard of the plant's mode counts only when it falls through zero.
    const std::size_t first_event = hybrid_ ? 2 * bodies_.size() : 0;
    for (int e = 0; e < ne_; ++e)
      if (plant_.guard_event(e)) dirs_[first_event + static_cast<std::size_t>(e)] = -1;
    CVodeSetRootDirection(sd_.mem, dirs_.data());
  }

  void restart(double t) {
    accumulate_stats();
    if (CVodeReInit(sd_.mem, t, sd_.y) != CV_SUCCESS) fail(t, "CVodeReInit failed");
    if (nroots_ > 0) set_root_directions();
    stop_set_ = -1.0;
    interpolant_->reset();
    ++restarts_;
  }

  void accumulate_stats() {
    long nst = 0, nfe = 0, nfe_jac = 0;
    CVodeGetNumSteps(sd_.mem, &nst);
    CVodeGetNumRhsEvals(sd_.mem, &nfe);
    CVodeGetNumLinRhsEvals(sd_.mem, &nfe_jac);
    steps_ += nst;
    rhs_evals_ += nfe;
    jacobian_rhs_evals_ += nfe_jac;
  }

  [[noreturn]] void fail(double t, const std::string& why) {
    throw std::runtime_error("simulation failed at t = " + detail::format_value(t) + " s: " + why);
  }

  // Initial state: each contact's position and velocity from the options (a velocity drive: its
  // input), then the plant's extras from them and the inputs at t = 0 (so a controller's or an
  // observer's states start consistent with the measurement and the reference), law states 0.
  void initial_state(double* y) {
    std::fill(y, y + n_, 0.0);
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
      y[bodies_[k].pos] = o_.initial_positions.empty() ? o_.initial_position : o_.initial_positions[k];
      y[bodies_[k].vel] = o_.initial_velocities.empty() ? o_.initial_velocity : o_.initial_velocities[k];
    }
    eval_inputs(0.0);
    if (kinematic_) y[1] = u_[0].value;
    plant_.initial_extras(std::span<double>(y, static_cast<std::size_t>(np_)), u_);
    for (const Body& b : bodies_)
      if (b.temp >= 0) y[b.temp] = b.env->thermal->T0.value_or(b.env->thermal->T_ambient);
  }

  void run_cvode(Trajectory& tr, std::size_t rows) {
    const auto n = static_cast<sunindextype>(n_);
    sd_.y = N_VNew_Serial(n, sd_.ctx);
    sd_.abstol = N_VNew_Serial(n, sd_.ctx);
    sd_.dky = N_VNew_Serial(n, sd_.ctx);
    if (!sd_.y || !sd_.abstol || !sd_.dky) throw std::runtime_error("SUNDIALS: out of memory");
    detail::use_small_vector_ops(sd_.dky);
    interpolant_.emplace(sd_.dky);
    detail::use_small_vector_ops(sd_.y);  // before CVodeInit: its clones copy the operations
    double* y = N_VGetArrayPointer(sd_.y);
    double* atol = N_VGetArrayPointer(sd_.abstol);

    initial_state(y);
    for (int i = 0; i < np_; ++i) atol[i] = o_.atol;
    for (const Body& b : bodies_) {
      if (b.nz == 0) continue;
      std::vector<double> zs(static_cast<std::size_t>(b.nz));
      b.law->steady_state(1.0, zs);
      double scale = 0.0;
      for (double z : zs) scale = std::max(scale, std::abs(z));
      if (!(scale > 0)) scale = 1.0;
      for (int i = b.z; i < b.z + b.nz; ++i) atol[i] = o_.atol * scale;
    }
    // A temperature resolved as finely, relative to its size, as a position of 1 m.
    for (const Body& b : bodies_)
      if (b.temp >= 0) atol[b.temp] = o_.atol * std::max(1.0, std::abs(b.env->thermal->T_ambient));

    if (sample_period_ > 0) {
      eval_inputs(0.0);
      plant_.sample(0.0, std::span<double>(y, static_cast<std::size_t>(np_)), u_);
    }
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
      Body& b = bodies_[k];
      if (!b.hybrid) continue;
      if (y[b.vel] > 0) {
        set_mode(b, Mode::slide_pos);
      } else if (y[b.vel] < 0) {
        set_mode(b, Mode::slide_neg);
      } else {
        settle_at_rest(tr, k, 0.0, y, false, 0);
      }
    }
    if (any_guard_) settle_after_jump(tr, 0.0, y);

    sd_.mem = CVodeCreate(CV_BDF, sd_.ctx);
    if (!sd_.mem) throw std::runtime_error("SUNDIALS: CVodeCreate failed");
    CVodeSetErrHandlerFn(sd_.mem, &Engine::error_cb, this);
    if (CVodeInit(sd_.mem, &Engine::rhs_cb, 0.0, sd_.y) != CV_SUCCESS) fail(0.0, "CVodeInit: " + error_);
    CVodeSetUserData(sd_.mem, this);
    if (CVodeSVtolerances(sd_.mem, o_.rtol, sd_.abstol) != CV_SUCCESS) fail(0.0, "tolerances: " + error_);
    sd_.A = SUNDenseMatrix(n, n, sd_.ctx);
    sd_.LS = SUNLinSol_Dense(sd_.y, sd_.A, sd_.ctx);
    if (!sd_.A || !sd_.LS || CVodeSetLinearSolver(sd_.mem, sd_.LS, sd_.A) != CV_SUCCESS)
      fail(0.0, "dense linear solver: " + error_);
    // Free motion with dynamic laws (the stiff case): exact Jacobian instead of n extra
    // right-hand sides per Newton matrix, and no difference-quotient noise in it.
    // It is cheap (a few states), so it is refreshed at every Newton matrix update instead of
    // every 51 steps: Newton then converges at once after a slip starts, and fewer steps fail
    // (Canudas presliding took 891 steps instead of 2763, stick-slip 4477 instead of 5493).
    if (system_ && !hybrid_) {
      CVodeSetJacFn(sd_.mem, &Engine::jac_cb);
      CVodeSetJacEvalFrequency(sd_.mem, 1);
    }
    CVodeSetMaxNumSteps(sd_.mem, o_.max_steps);
    double hmax = o_.max_step;
    for (const InputSignal& in : inputs_)
      if (in.max_step() > 0) hmax = hmax > 0 ? std::min(hmax, in.max_step()) : in.max_step();
    for (const Body& b : bodies_)
      for (const InputSignal* signal : condition_signals(b))
        if (signal && signal->max_step() > 0) hmax = hmax > 0 ? std::min(hmax, signal->max_step()) : signal->max_step();
    if (hmax > 0) CVodeSetMaxStep(sd_.mem, hmax);
    if (nroots_ > 0) {
      if (CVodeRootInit(sd_.mem, nroots_, &Engine::roots_cb) != CV_SUCCESS) fail(0.0, "CVodeRootInit: " + error_);
      set_root_directions();
      CVodeSetNoInactiveRootWarn(sd_.mem);
    }

    // Corners of the inputs and, for a sampled controller, its sample instants k Ts (flagged).
    std::vector<double> corners;
    std::vector<char> is_sample;
    merge_corners(corners, is_sample);
    std::size_t next_corner = 0;
    const double rate = o_.output_rate;
    auto close = [](double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b)); };

    record(tr, 0.0, y);
    double t = 0.0;
    double last_switch_time = -1.0;
    int switches_without_progress = 0;
    for (std::size_t k = 1; k < rows; ++k) {
      if (k % 4096 == 0) throw_if_cancelled();  // rows read from an interpolant call no solver
      double tout = std::min(static_cast<double>(k) / rate, o_.duration);
      // Rows inside the step already taken come from its interpolant, without a CVode call.
      // Only without root functions (CVode checks roots up to each output time) and before
      // the next corner (whose handling must precede its row).
      if (nroots_ == 0 && (next_corner >= corners.size() || tout < corners[next_corner]) &&
          interpolant_->eval(sd_.mem, tout, y_row_.data())) {
        t = tout;
        record(tr, tout, y_row_.data());
        continue;
      }
      while (!close(t, tout)) {
        // Corners already behind t are skipped, but a sample instant never is (a root located
        // within rounding of it must not swallow the controller update).
        while (next_corner < corners.size() && corners[next_corner] <= t + 1e-12 * std::max(1.0, t)) {
          if (is_sample[next_corner]) {
            take_sample(tr, corners[next_corner], y);
            restart(t);
          }
          ++next_corner;
        }
        const double tstop = next_corner < corners.size() ? corners[next_corner] : o_.duration;
        if (tstop != stop_set_) {
          CVodeSetStopTime(sd_.mem, tstop);
          stop_set_ = tstop;
        }
        throw_if_cancelled();
        double tret = t;
        const int flag = CVode(sd_.mem, tout, sd_.y, &tret, CV_NORMAL);
        if (flag < 0 && callback_exception_) std::rethrow_exception(callback_exception_);
        if (flag < 0) fail(tret, error_.empty() ? "CVODE error " + std::to_string(flag) : error_);
        if (steps_ > o_.max_steps) fail(tret, "more than max_steps = " + std::to_string(o_.max_steps) + " steps");
        t = tret;
        if (flag == CV_ROOT_RETURN) {
          // Zeno guard: a switch that does not let time move on means the model cannot decide.
          if (t - last_switch_time <= 1e-13 * std::max(1.0, std::abs(t))) {
            if (++switches_without_progress > 50)
              fail(t, "mode switches without progress (stuck/slide decision undecidable at this state)");
          } else {
            switches_without_progress = 0;
          }
          last_switch_time = t;
          handle_root(tr, t, y);
          restart(t);
        } else {
          if (flag != CV_TSTOP_RETURN) t = tout;
          // At a corner of the input (reached as a stop time, or as an output time that coincides
          // with it): restart from the exact state; an input jump may break a stuck body loose.
          if (next_corner < corners.size() && close(t, corners[next_corner])) {
            const bool sample_now = is_sample[next_corner] != 0;
            const double t_corner = corners[next_corner];  // exact: t may be an output time rounded apart
            ++next_corner;
            if (sample_now) {
              take_sample(tr, t_corner, y);
            } else {
              settle_after_jump(tr, t, y);
            }
            restart(t);
          }
        }
      }
      record(tr, tout, y);
    }
    if (one_) batch_.flush(tr);
    accumulate_stats();
    tr.stats.steps = steps_;
    tr.stats.rhs_evaluations = rhs_evals_;
    tr.stats.jacobian_rhs_evaluations = jacobian_rhs_evals_;
    tr.stats.restarts = restarts_;
  }

  // Input corners in (0, duration) and sample instants k Ts (k >= 1) of a sampled controller, in
  // time order; equal times (as the table of a data input sampled on the same grid) merge.
  void merge_corners(std::vector<double>& corners, std::vector<char>& is_sample) const {
    std::vector<std::pair<double, char>> all;
    for (const InputSignal& in : inputs_)
      for (double c : in.breakpoints(0.0, o_.duration)) all.emplace_back(c, 0);
    for (const Body& b : bodies_)  // a load's and a temperature log's corners too
      for (const InputSignal* signal : condition_signals(b))
        if (signal)
          for (double c : signal->breakpoints(0.0, o_.duration)) all.emplace_back(c, 0);
    if (sample_period_ > 0) {
      for (long k = 1;; ++k) {
        const double ts = static_cast<double>(k) * sample_period_;  // same product as a table built as k * dt
        // The instant at the end is included, so the last output row has its controller update.
        if (!(ts <= o_.duration * (1.0 + 1e-12))) break;
        all.emplace_back(ts, 1);
      }
    }
    std::sort(all.begin(), all.end());
    for (const auto& [time, flag] : all) {
      if (!corners.empty() && std::abs(corners.back() - time) <= 1e-12 * std::max(1.0, time)) {
        is_sample.back() = static_cast<char>(is_sample.back() | flag);
      } else {
        corners.push_back(time);
        is_sample.push_back(flag);
      }
    }
  }

  // The controller update at the sample instant t = k Ts (exactly that product, so a data input
  // tabulated at k dt gives its sample k); a stuck body may break loose under the new output.
  void take_sample(Trajectory& tr, double t, double* y) {
    pin_stuck(y);
    eval_inputs(t);
    plant_.sample(t, std::span<double>(y, static_cast<std::size_t>(np_)), u_);
    settle_after_jump(tr, t, y);
  }

  // After a jump of the inputs or of the plant's discrete states at t (an input corner, a
  // controller sample): a guard the jump made negative (engaged bodies that now pull apart) fires
  // at once, as no root finder sees a guard that starts negative; stuck bodies are decided again.
  void settle_after_jump(Trajectory& tr, double t, double* y) {
    if (any_guard_) {
      pin_stuck(y);
      remember_velocities(y);
      after_plant_events(tr, t, y);
    } else {
      settle_stuck(tr, t, y);
    }
  }

  void handle_root(Trajectory& tr, double t, double* y) {
    CVodeGetRootInfo(sd_.mem, found_.data());
    pin_stuck(y);
    const std::size_t first_event = hybrid_ ? 2 * bodies_.size() : 0;
    bool plant_found = false;
    for (int e = 0; e < ne_; ++e) plant_found = plant_found || found_[first_event + static_cast<std::size_t>(e)] != 0;
    // A plant's guard event (a backlash separating) changes the applied force that decides a
    // stuck body: when both come at one instant, the stuck body is decided after the plant's
    // events (after_plant_events), at the force of the plant's new mode.
    const bool stuck_after_events = any_guard_ && plant_found;
    if (hybrid_) {
      for (std::size_t k = 0; k < bodies_.size(); ++k) {
        if (!found_[2 * k] && !found_[2 * k + 1]) continue;
        Body& b = bodies_[k];
        if (b.mode == Mode::stuck && stuck_after_events) continue;
        if (b.mode == Mode::stuck) {
          // breakaway: the applied force reached a level
          const double a = applied_at_rest(k, t, y);
          y[b.pos] = b.stuck_position;
          y[b.vel] = 0.0;
          const int dir = found_[2 * k] != 0 ? 1 : -1;
          set_mode(b, dir > 0 ? Mode::slide_pos : Mode::slide_neg);
          tr.switches.push_back({t, SwitchKind::breakaway, y[b.pos], a, dir, static_cast<int>(k)});
        } else {
          const int dir = b.mode == Mode::slide_pos ? 1 : -1;
          y[b.vel] = 0.0;  // the velocity reached zero: exactly zero from now on
          settle_at_rest(tr, k, t, y, false, dir);
        }
      }
    }
    bool any_event = false;
    remember_velocities(y);
    for (int e = 0; e < ne_; ++e) {
      if (!found_[first_event + static_cast<std::size_t>(e)]) continue;
      eval_inputs(t);
      plant_.on_event(t, std::span<double>(y, static_cast<std::size_t>(np_)), u_, e);
      tr.plant_events.push_back({t, e});
      any_event = true;
    }
    // The plant's discrete states changed (and, at an impact, a contact's velocity): each body's
    // mode is decided again, then the applied force on a stuck body may have jumped.
    if (any_event) after_plant_events(tr, t, y);
  }

  // After the plant's events at t: a contact whose velocity an impact changed takes the mode of
  // its new velocity, and a guard that is negative in the mode the plant entered fires at once
  // (an engagement whose bodies would pull apart separates at the same instant); then stuck
  // bodies are decided again under the new applied force.
  void after_plant_events(Trajectory& tr, double t, double* y) {
    for (int round = 0;; ++round) {
      follow_velocity_jumps(tr, t, y);
      if (!any_guard_ || round == kMaxGuardRounds) break;
      const std::vector<int> negative = negative_guards(t, y);
      if (negative.empty()) break;
      remember_velocities(y);
      for (int e : negative) {
        plant_.on_event(t, std::span<double>(y, static_cast<std::size_t>(np_)), u_, e);
        tr.plant_events.push_back({t, e});
      }
    }
    settle_stuck(tr, t, y);
  }

  // The plant's guards that are negative (below rounding) at state y and time t.
  std::vector<int> negative_guards(double t, double* y) {
    pin_stuck(y);
    eval_inputs(t);
    const auto x = effective_state(y);
    if (stuck_count_ > 0) plant_applied(t, x);
    for (std::size_t k = 0; k < bodies_.size(); ++k) friction_[k] = friction_of(bodies_[k], t, x, y);
    plant_.events(t, x, u_, friction_, g_now_);
    std::vector<int> out;
    for (int e = 0; e < ne_; ++e)
      if (plant_.guard_event(e) && g_now_[static_cast<std::size_t>(e)] < 0) out.push_back(e);
    return out;
  }

  // A contact whose velocity the plant set at an event leaves a mode that no longer matches it: a
  // stuck body struck into motion slides, a sliding one struck to the other direction slides
  // that way, one struck to rest is decided at rest.
  void follow_velocity_jumps(Trajectory& tr, double t, double* y) {
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
      Body& b = bodies_[k];
      const double v = y[b.vel];
      if (!b.hybrid || v == velocities_before_[k]) continue;  // no impact on this body
      const int contact = static_cast<int>(k);
      if (b.mode == Mode::stuck) {
        if (v == 0.0) continue;
        y[b.pos] = b.stuck_position;
        set_mode(b, v > 0 ? Mode::slide_pos : Mode::slide_neg);
        tr.switches.push_back({t, SwitchKind::impact, y[b.pos], applied_now(k, t, y), v > 0 ? 1 : -1, contact});
      } else if (b.mode == Mode::slide_pos || b.mode == Mode::slide_neg) {
        const int dir = b.mode == Mode::slide_pos ? 1 : -1;
        if (v * dir > 0) continue;
        if (v == 0.0) {
          settle_at_rest(tr, k, t, y, false, dir);
        } else {
          set_mode(b, v > 0 ? Mode::slide_pos : Mode::slide_neg);
          tr.switches.push_back({t, SwitchKind::impact, y[b.pos], applied_now(k, t, y), -dir, contact});
        }
      }
    }
  }
  // Each contact's velocity before the plant's events, to tell which an impact changed.
  void remember_velocities(const double* y) {
    velocities_before_.resize(bodies_.size());
    for (std::size_t k = 0; k < bodies_.size(); ++k) velocities_before_[k] = y[bodies_[k].vel];
  }
  // The applied force on body k at state y and time t.
  double applied_now(std::size_t k, double t, double* y) {
    eval_inputs(t);
    plant_applied(t, effective_state(y));
    return force_[k];
  }

  // ---- fixed-step --------------------------------------------------------------------------

  // The plant's events in fixed-step mode: checked after each step, on_event at the first step
  // where g[k] changed sign (what a controller sampled at 1/dt sees).
  void fixed_events(Trajectory& tr, double t, std::vector<double>& x) {
    plant_.events(t, x, u_, friction_, g_now_);
    for (int e = 0; e < ne_; ++e) {
      const auto i = static_cast<std::size_t>(e);
      const bool up = g_prev_[i] < 0 && g_now_[i] >= 0;
      if ((up && !plant_.guard_event(e)) || (g_prev_[i] > 0 && g_now_[i] <= 0)) {
        plant_.on_event(t, x, u_, e);
        tr.plant_events.push_back({t, e});
      }
    }
    plant_.events(t, x, u_, friction_, g_prev_);
  }

  void run_fixed(Trajectory& tr, std::size_t rows) {
    const double dt = o_.dt;
    const long per_row = std::lround(1.0 / (o_.output_rate * dt));
    std::vector<double> y(static_cast<std::size_t>(n_), 0.0), dx(static_cast<std::size_t>(np_), 0.0);
    initial_state(y.data());
    std::span<double> x(y.data(), static_cast<std::size_t>(np_));
    bool any_static = false;
    for (const Body& b : bodies_) any_static = any_static || b.nz == 0;
    long per_sample = 0;  // steps per controller sample (sampled plants)
    if (sample_period_ > 0) {
      const double ratio = sample_period_ / dt;
      per_sample = std::lround(ratio);
      if (per_sample < 1 || std::abs(ratio - static_cast<double>(per_sample)) > 1e-6 * ratio)
        throw std::invalid_argument("simulation option dt = " + detail::format_value(dt) + " s must divide the controller's sample period " +
                                    detail::format_value(sample_period_) + " s a whole number of times");
      eval_inputs(0.0);
      plant_.sample(0.0, x, u_);
    }
    if (ne_ > 0) {
      eval_inputs(0.0);
      plant_.events(0.0, x, u_, friction_, g_prev_);
    }
    // The plant's own fixed-step update: the state and inputs at each step's start are kept for it.
    const bool own_update = plant_.has_fixed_step_update();
    std::vector<double> before;
    std::vector<InputValue> u_before;
    if (own_update) {
      before.reserve(static_cast<std::size_t>(np_));
      u_before.reserve(u_.size());
    }
    long step = 0;
    for (std::size_t k = 0; k < rows; ++k) {
      // Advance to the row's step count, then record the state there.
      const long target = static_cast<long>(k) * per_row;
      for (; step < target;) {
        if (step % 4096 == 0) throw_if_cancelled();
        const double t = static_cast<double>(step) * dt;
        eval_inputs(t);
        if (kinematic_) x[1] = u_[0].value;
        if (own_update) before.assign(x.begin(), x.end());
        if (any_static) plant_applied(t, x);
        for (std::size_t c = 0; c < bodies_.size(); ++c) {
          const Body& b = bodies_[c];
          const double v = x[static_cast<std::size_t>(b.vel)];
          if (b.cond) {
            const Conditions cd = conditions(b, t, x, y.data());
            const double r = b.law->ripple(cd.position);
            friction_[c] = b.nz > 0 ? b.law->step(std::span<double>(y.data() + b.z, static_cast<std::size_t>(b.nz)), v, dt, cd) + r
                                    : b.law->force(v, force_[c], cd);  // ripple included
            if (b.temp >= 0)  // explicit Euler, as the plant's other states
              y[static_cast<std::size_t>(b.temp)] += dt * b.env->thermal->rate(y[static_cast<std::size_t>(b.temp)], (friction_[c] - r) * v);
          } else if (b.nz > 0) {
            // the law's exact update at constant v over the sample
            friction_[c] = b.law->step(std::span<double>(y.data() + b.z, static_cast<std::size_t>(b.nz)), v, dt);
          } else {
            friction_[c] = b.law->force(v, force_[c]);  // stiction only at v == 0 exactly (or in Karnopp's band)
          }
        }
        plant_derivatives(t, x, dx);
        for (const Body& b : bodies_) {
          const auto p = static_cast<std::size_t>(b.pos), v = static_cast<std::size_t>(b.vel);
          if (kinematic_) {
            x[p] += dt * u_[0].value;
          } else {
            x[v] += dt * dx[v];  // symplectic Euler: new velocity, then position with it
            x[p] += dt * x[v];
          }
        }
        for (int i : extras_) x[static_cast<std::size_t>(i)] += dt * dx[static_cast<std::size_t>(i)];
        ++step;
        if (own_update) {
          // The plant's own rule for some of its states (a compensator's exact update), from the
          // state and inputs at the step's start.
          u_before.assign(u_.begin(), u_.end());
          const double t_end = static_cast<double>(step) * dt;
          eval_inputs(t_end);
          plant_.fixed_step_update(t_end, dt, before, u_before, x, u_);
        }
        if (per_sample > 0 && step % per_sample == 0) {
          const double ts = static_cast<double>(step / per_sample) * sample_period_;
          eval_inputs(ts);
          plant_.sample(ts, x, u_);
        }
        if (ne_ > 0) {
          const double ts = static_cast<double>(step) * dt;
          eval_inputs(ts);
          fixed_events(tr, ts, y);
        }
      }
      const double t = static_cast<double>(step) * dt;
      eval_inputs(t);
      if (kinematic_) x[1] = u_[0].value;
      plant_applied(t, x);
      plant_signals(t, x);
      tr.time.push_back(static_cast<double>(k) / o_.output_rate);
      for (std::size_t c = 0; c < bodies_.size(); ++c) {
        const Body& b = bodies_[c];
        const double v = x[static_cast<std::size_t>(b.vel)];
        double f;
        if (b.cond) {
          const Conditions cd = conditions(b, t, x, y.data());
          f = b.nz > 0 ? b.law->force(std::span<const double>(y.data() + b.z, static_cast<std::size_t>(b.nz)), v, cd) +
                             b.law->ripple(cd.position)
                       : b.law->force(v, force_[c], cd);
        } else {
          f = b.nz > 0 ? b.law->force(std::span<const double>(y.data() + b.z, static_cast<std::size_t>(b.nz)), v)
                       : b.law->force(v, force_[c]);
        }
        double a = force_[c];
        PlantSignals& s = signals_[c];
        if (kinematic_) a += f, s.drive += f;
        push_row(column_set(tr, static_cast<int>(c)), x[static_cast<std::size_t>(b.pos)], v, f, a, s,
                 v == 0.0 && !kinematic_ && b.nz == 0 ? 1.0 : 0.0, y.data() + b.z, b.nz);
        if (b.env) push_conditions(column_set(tr, static_cast<int>(c)), b, t, x, y.data());
      }
      if (motor_ >= 0) tr.motor_position.push_back(x[static_cast<std::size_t>(motor_)]);
    }
    tr.stats.steps = step;
    tr.stats.rhs_evaluations = step;
  }

  const Plant& plant_;
  const SingleContactPlant* single_;  // the plant as a 1-DOF one, or null
  bool one_ = false;             // 1-DOF plant: the One = true forms of the hot paths
  bool constant_inputs_ = false;  // every input constant: u_ evaluated once
  std::span<const InputSignal> inputs_;
  const SimulationOptions& o_;
  SolverMode mode_;
  int np_ = 2, nz_ = 0, n_ = 2, nc_ = 1, ne_ = 0;
  int nroots_ = 0;  // root functions: 2 per contact when hybrid_, then the plant's ne_
  std::vector<Body> bodies_;
  std::vector<int> extras_;  // plant states that are no contact's position or velocity
  int stuck_count_ = 0;      // bodies in Mode::stuck
  bool hybrid_ = false;      // some body has hybrid modes
  int motor_ = -1;           // state index of a backlash axis's motor position, or -1
  bool any_cond_ = false;    // some body's friction depends on conditions (load, temperature, ripple)
  bool kinematic_ = false;   // the plant imposes the velocity (plant_.kinematic(), asked once)
  bool any_guard_ = false;   // some plant event is a guard (Plant::guard_event)
  std::vector<double> velocities_before_;  // each contact's velocity before the plant's events
  // Rounds of guards fired at one instant before the engine goes on (an impact, then the
  // separation it cannot hold, then nothing more).
  static constexpr int kMaxGuardRounds = 4;
  double sample_period_ = 0.0;  // s; > 0 for a plant with a sampled controller
  std::vector<InputValue> u_;       // the inputs at the time being evaluated
  std::vector<double> force_;       // applied force on each contact
  std::vector<double> friction_;    // friction on each contact
  std::vector<PlantSignals> signals_;
  RowBatch batch_;  // rows of a 1-DOF plant not yet in the trajectory (record_one)
  std::vector<int> found_, dirs_;   // root information and directions (nroots_)
  std::vector<double> g_prev_, g_now_;  // plant event functions (fixed-step mode)
  std::vector<double> scratch_;
  Sundials sd_;
  std::optional<StiffSystem> system_;  // dynamic laws with a plant that has an analytic Jacobian
  std::string error_;
  std::exception_ptr callback_exception_;  // what a callback threw (see guarded)
  double stop_set_ = -1.0;
  std::optional<detail::StepInterpolant> interpolant_;  // rows inside the last step (stiff mode)
  std::vector<double> y_row_;   // n: the state of an interpolated row
  long steps_ = 0, rhs_evals_ = 0, jacobian_rhs_evals_ = 0, restarts_ = 0;
};

}  // namespace

SolverMode resolve_solver_mode(const FrictionLaw& law, SolverMode requested) {
  switch (requested) {
    case SolverMode::automatic:
      return has_stiction(law) ? SolverMode::hybrid : SolverMode::stiff;
    case SolverMode::hybrid:
      if (law.is_dynamic())
        throw std::invalid_argument("solver.mode = hybrid does not fit the dynamic law '" + law.name() +
                                    "'; valid modes for it: auto, stiff, fixed-step");
      return SolverMode::hybrid;
    case SolverMode::stiff:
      if (has_stiction(law))
        throw std::invalid_argument("solver.mode = stiff does not fit the law '" + law.name() +
                                    "' (it has a breakaway level of " + detail::format_value(law.breakaway_positive()) +
                                    "; stiction needs the hybrid engine); valid modes for it: auto, hybrid, fixed-step");
      return SolverMode::stiff;
    case SolverMode::fixed_step:
      return SolverMode::fixed_step;
  }
  return requested;
}

SolverMode resolve_solver_mode(std::span<const FrictionLaw* const> laws, SolverMode requested) {
  if (requested == SolverMode::automatic) {
    for (const FrictionLaw* l : laws)
      if (has_stiction(*l)) return SolverMode::hybrid;
    return SolverMode::stiff;
  }
  for (const FrictionLaw* l : laws) resolve_solver_mode(*l, requested);
  return requested;
}

namespace {

// Each contact's law, after checking the plant's contacts: state indices in range and not shared,
// distinct non-empty names when there are several, a velocity drive with one contact.
std::vector<const FrictionLaw*> contact_laws(const Plant& plant, const FrictionLaw& law) {
  const int nc = plant.num_contacts(), np = plant.num_states();
  const std::string who = "plant '" + plant.type() + "'";
  if (nc < 1) throw std::invalid_argument(who + " declares " + std::to_string(nc) + " contacts; it needs at least 1");
  if (plant.kinematic() && nc != 1)
    throw std::invalid_argument(who + " imposes its velocity with " + std::to_string(nc) + " contacts; a velocity drive has 1");
  std::vector<const FrictionLaw*> laws;
  std::vector<char> used(static_cast<std::size_t>(std::max(np, 0)), 0);
  std::vector<std::string> names;
  for (int k = 0; k < nc; ++k) {
    const Contact c = plant.contact(k);
    for (int index : {c.position, c.velocity}) {
      if (index < 0 || index >= np)
        throw std::invalid_argument(who + ": contact " + std::to_string(k) + " has state index " + std::to_string(index) +
                                    " outside 0.." + std::to_string(np - 1));
      if (used[static_cast<std::size_t>(index)]++)
        throw std::invalid_argument(who + ": state " + std::to_string(index) + " is the position or velocity of two contacts");
    }
    if (nc > 1) {
      if (c.name.empty()) throw std::invalid_argument(who + ": contact " + std::to_string(k) + " has no name (several contacts need names)");
      if (std::find(names.begin(), names.end(), c.name) != names.end())
        throw std::invalid_argument(who + ": two contacts are named '" + c.name + "'");
      names.push_back(c.name);
    }
    laws.push_back(c.law ? c.law : &law);
  }
  return laws;
}

}  // namespace

Trajectory simulate(const Plant& plant, const FrictionLaw& law, std::span<const InputSignal> inputs,
                    const SimulationOptions& options) {
  if (static_cast<int>(inputs.size()) != plant.num_inputs())
    throw std::invalid_argument("simulate: plant '" + plant.type() + "' takes " + std::to_string(plant.num_inputs()) +
                                " inputs; " + std::to_string(inputs.size()) + " given");
  const std::vector<const FrictionLaw*> laws = contact_laws(plant, law);
  const SolverMode mode = laws.size() == 1 ? resolve_solver_mode(*laws[0], options.mode) : resolve_solver_mode(std::span<const FrictionLaw* const>(laws), options.mode);
  check_options(options, mode);
  const auto nc = laws.size();
  for (const auto* list : {&options.initial_positions, &options.initial_velocities})
    if (!list->empty() && list->size() != nc)
      throw std::invalid_argument("simulation option initial_" + std::string(list == &options.initial_positions ? "positions" : "velocities") +
                                  " has " + std::to_string(list->size()) + " entries; plant '" + plant.type() + "' has " +
                                  std::to_string(nc) + " contacts");
  if (!options.environments.empty()) {
    if (options.environments.size() != nc)
      throw std::invalid_argument("simulation option environments has " + std::to_string(options.environments.size()) +
                                  " entries; plant '" + plant.type() + "' has " + std::to_string(nc) + " contacts");
    for (const ContactEnvironment& e : options.environments) e.validate();
  }
  int extra_columns = 9 * static_cast<int>(nc - 1);  // other contacts' columns, then the law states
  for (const FrictionLaw* l : laws) extra_columns += l->is_dynamic() ? l->num_states() : 0;
  check_output_size(options, extra_columns);
  check_steps(options, mode, plant.sample_period());
  if (inputs.size() == 1) {
    inputs[0].validate();
  } else {
    for (std::size_t i = 0; i < inputs.size(); ++i) inputs[i].validate("input " + std::to_string(i));
  }
  Engine engine(plant, law, laws, inputs, options, mode);
  Trajectory tr = engine.run();
  check_finite(tr);
  return tr;
}

Trajectory simulate(const Plant& plant, const FrictionLaw& law, const InputSignal& input,
                    const SimulationOptions& options) {
  return simulate(plant, law, std::span<const InputSignal>(&input, 1), options);
}

Trajectory simulate(const Scenario& scenario) {
  if (!scenario.plant) throw std::invalid_argument("scenario: no plant given");
  const Plant& plant = *scenario.plant;
  if (scenario.inputs.empty()) return simulate(plant, scenario.law, scenario.input, scenario.options);
  if (static_cast<int>(scenario.inputs.size()) != plant.num_inputs())
    throw std::invalid_argument("scenario: plant '" + plant.type() + "' takes " + std::to_string(plant.num_inputs()) +
                                " inputs; scenario.inputs has " + std::to_string(scenario.inputs.size()));
  return simulate(plant, scenario.law, std::span<const InputSignal>(scenario.inputs), scenario.options);
}

}  // namespace frictionlab
