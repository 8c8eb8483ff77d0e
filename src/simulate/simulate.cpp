#include "frictionlab/models/parameter.hpp"
#include "frictionlab/simulate/simulate.hpp"
#include "frictionlab/simulate/output_size.hpp"
#include "frictionlab/simulate/stiff_system.hpp"
#include "column_pool.hpp"
#include "small_vector.hpp"
#include "step_interpolant.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <sstream>
#include <exception>
#include <stdexcept>
#include <string>
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
  return output_rows(o) * (9.0 + std::max(law_states, 0)) * static_cast<double>(sizeof(double));
}

double max_output_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return 1024.0 * 1024.0 * 1024.0;
  return 0.5 * static_cast<double>(pages) * static_cast<double>(page);
}

std::string format_bytes(double bytes) {
  static const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000.0 && u < 6) bytes /= 1000.0, ++u;
  char buf[64];
  std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : "%.3g %s", bytes, units[u]);
  return buf;
}

namespace {

bool has_stiction(const FrictionLaw& law) {
  return !law.is_dynamic() && (law.breakaway_positive() > 0.0 || law.breakaway_negative() > 0.0);
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
  const double need = output_bytes(o, law_states), limit = max_output_bytes();
  if (!(need <= limit)) {
    char rows[32];
    std::snprintf(rows, sizeof rows, "%.3g", output_rows(o));
    throw std::invalid_argument("simulation options duration = " + detail::format_value(o.duration) + " s and output_rate = " +
                                detail::format_value(o.output_rate) + " Hz give " + rows + " output rows, which need " +
                                format_bytes(need) + " of memory; the limit is half this machine's memory, " +
                                format_bytes(limit) + ": shorten the duration or lower the output rate");
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

class Engine {
 public:
  Engine(const Plant& plant, const FrictionLaw& law, const InputSignal& input, const SimulationOptions& o,
         SolverMode mode)
      : plant_(plant), law_(law), input_(input), o_(o), mode_(mode) {
    np_ = plant.num_states();
    nz_ = law.is_dynamic() ? law.num_states() : 0;
    n_ = np_ + nz_;
    fbp_ = law.is_dynamic() ? 0.0 : law.breakaway_positive();
    fbn_ = law.is_dynamic() ? 0.0 : law.breakaway_negative();
    scratch_.assign(static_cast<std::size_t>(n_), 0.0);
    y_row_.assign(static_cast<std::size_t>(n_), 0.0);
    // Hybrid modes only where stiction exists and the velocity is not imposed.
    kinematic_ = plant.kinematic();
    hybrid_ = mode == SolverMode::hybrid && has_stiction(law) && !kinematic_;
    sample_period_ = plant.sample_period();
    if (nz_ > 0 && mode != SolverMode::fixed_step) {
      system_.emplace(plant, law);
      if (!system_->has_jacobian()) system_.reset();
    }
  }

  Trajectory run() {
    Trajectory tr;
    const std::size_t rows = last_row(o_) + 1;
    // Columns come from this thread's pool of recycled ones (see column_pool.hpp).
    for (auto* c : {&tr.time, &tr.position, &tr.velocity, &tr.friction, &tr.applied, &tr.current, &tr.voltage,
                    &tr.reference, &tr.stuck})
      *c = detail::take_column(rows);
    tr.drive = detail::take_column(rows, detail::Shelf::side);
    tr.law_state.resize(static_cast<std::size_t>(nz_));
    for (auto& c : tr.law_state) c = detail::take_column(rows);
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

  // ---- physics -------------------------------------------------------------------------------

  // One-contact calls of the plant's span-based interface.
  double applied1(double t, std::span<const double> x, const InputValue& in) const {
    double f = 0.0;
    plant_.applied(t, x, Inputs(&in, 1), std::span<double>(&f, 1));
    return f;
  }
  void deriv1(double t, std::span<const double> x, const InputValue& in, double friction, std::span<double> dx) const {
    plant_.derivatives(t, x, Inputs(&in, 1), std::span<const double>(&friction, 1), dx);
  }
  PlantSignals signals1(double t, std::span<const double> x, const InputValue& in) const {
    PlantSignals s;
    plant_.signals(t, x, Inputs(&in, 1), std::span<PlantSignals>(&s, 1));
    return s;
  }
  void sample1(double t, std::span<double> x, const InputValue& in) const { plant_.sample(t, x, Inputs(&in, 1)); }

  // Sliding force in direction s, with the one-sided limit at v -> 0 from that side when v has
  // not (or no longer) the sign s: keeps the right-hand side smooth over the step that finds v = 0.
  double slide_force(double v, int s) const {
    if (v * s > 0) return law_.sliding(v);
    // 1e-300 is far below any velocity scale (vs, dv, table points), so this is the limit value.
    return law_.sliding(s * 1e-300);
  }

  // The effective plant state: y itself, or a copy in scratch_ with the frozen position and zero
  // velocity while stuck, or the imposed velocity of a velocity drive.
  std::span<const double> effective_state(double t, const double* y, const InputValue& in) {
    if (mode_now_ != Mode::stuck && !kinematic_) return {y, static_cast<std::size_t>(np_)};
    std::copy(y, y + n_, scratch_.begin());
    if (mode_now_ == Mode::stuck) {
      scratch_[0] = stuck_position_;
      scratch_[1] = 0.0;
    }
    if (kinematic_) scratch_[1] = in.value;
    (void)t;
    return {scratch_.data(), static_cast<std::size_t>(np_)};
  }

  void rhs(double t, const double* y, double* dy) {
    const InputValue in = input_.at(t);
    const auto x = effective_state(t, y, in);
    std::span<double> dx(dy, static_cast<std::size_t>(np_));
    const double v = x[1];
    switch (mode_now_) {
      case Mode::stuck: {
        const double a = applied1(t, x, in);
        deriv1(t, x, in, a, dx);
        dx[0] = 0.0;
        dx[1] = 0.0;
        break;
      }
      case Mode::slide_pos:
      case Mode::slide_neg:
        deriv1(t, x, in, slide_force(v, mode_now_ == Mode::slide_pos ? 1 : -1), dx);
        break;
      case Mode::free:
        if (nz_ > 0) {
          std::span<const double> z(y + np_, static_cast<std::size_t>(nz_));
          const double f = law_.force(z, v);
          deriv1(t, x, in, f, dx);
          law_.derivative(z, v, std::span<double>(dy + np_, static_cast<std::size_t>(nz_)));
        } else {
          deriv1(t, x, in, law_.sliding(v), dx);
        }
        break;
    }
  }

  void roots(double t, const double* y, double* g) {
    const InputValue in = input_.at(t);
    const auto x = effective_state(t, y, in);
    if (mode_now_ == Mode::stuck) {
      const double a = applied1(t, x, in);
      g[0] = a - fbp_;
      g[1] = a + fbn_;
    } else {
      g[0] = y[1];
      g[1] = 1.0;  // unused in a sliding mode
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
  static int rhs_cb(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
    return guarded(user, [&](Engine* self) { self->rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot)); });
  }
  static int roots_cb(sunrealtype t, N_Vector y, sunrealtype* g, void* user) {
    return guarded(user, [&](Engine* self) { self->roots(t, N_VGetArrayPointer(y), g); });
  }
  // The analytic Newton matrix (dense, column-major) of the free motion with a dynamic law.
  static int jac_cb(sunrealtype t, N_Vector y, N_Vector /*fy*/, SUNMatrix J, void* user, N_Vector, N_Vector,
                    N_Vector) {
    return guarded(user, [&](Engine* self) {
      const auto n = static_cast<std::size_t>(self->n_);
      self->system_->jacobian(t, std::span<const double>(N_VGetArrayPointer(y), n), self->input_.at(t),
                              std::span<double>(SM_DATA_D(J), n * n));
    });
  }
  static void error_cb(int code, const char* module, const char* function, char* msg, void* user) {
    if (code < 0) {
      auto* self = static_cast<Engine*>(user);
      self->error_ = std::string(module) + " " + function + ": " + msg;
    }
  }

  // One output row from the integrator state y at time t.
  void record(Trajectory& tr, double t, const double* y, bool stuck_flag) {
    const InputValue in = input_.at(t);
    const auto x = effective_state(t, y, in);
    double a = applied1(t, x, in);
    double f = 0.0;
    switch (mode_now_) {
      case Mode::stuck: f = a; break;
      case Mode::slide_pos: f = slide_force(x[1], 1); break;
      case Mode::slide_neg: f = slide_force(x[1], -1); break;
      case Mode::free:
        f = nz_ > 0 ? law_.force(std::span<const double>(y + np_, static_cast<std::size_t>(nz_)), x[1])
                    : law_.sliding(x[1]);
        break;
    }
    PlantSignals s = signals1(t, x, in);
    if (kinematic_) a += f, s.drive += f;  // the drive supplies the friction too
    tr.time.push_back(t);
    tr.position.push_back(x[0]);
    tr.velocity.push_back(x[1]);
    tr.friction.push_back(f);
    tr.applied.push_back(a);
    tr.current.push_back(s.current);
    tr.voltage.push_back(s.voltage);
    tr.reference.push_back(s.reference);
    tr.drive.push_back(s.drive);
    tr.stuck.push_back(stuck_flag ? 1.0 : 0.0);
    for (int i = 0; i < nz_; ++i) tr.law_state[static_cast<std::size_t>(i)].push_back(y[np_ + i]);
  }

  // ---- hybrid mode logic ---------------------------------------------------------------------

  // The applied force at time t with y taken as a stuck state at its own position.
  double applied_at_rest(double t, double* y) {
    const InputValue in = input_.at(t);
    y[1] = 0.0;
    std::copy(y, y + n_, scratch_.begin());
    scratch_[1] = 0.0;
    return applied1(t, std::span<const double>(scratch_.data(), static_cast<std::size_t>(np_)), in);
  }

  // Decides the mode of a body at rest at time t (start, after a stop, after an input jump).
  // Returns the switch kind if it slides, and records it.
  void settle_at_rest(Trajectory& tr, double t, double* y, bool from_stuck, int previous_dir) {
    if (from_stuck) y[0] = stuck_position_;
    const double a = applied_at_rest(t, y);
    Mode next;
    if (a > fbp_) {
      next = Mode::slide_pos;
    } else if (a < -fbn_) {
      next = Mode::slide_neg;
    } else {
      next = Mode::stuck;
    }
    const bool was_stuck = from_stuck;
    if (next == Mode::stuck) {
      stuck_position_ = y[0];
      if (!was_stuck && previous_dir != 0) tr.switches.push_back({t, SwitchKind::stick, y[0], a, 0});
    } else {
      const int dir = next == Mode::slide_pos ? 1 : -1;
      if (was_stuck) {
        y[0] = stuck_position_;
        tr.switches.push_back({t, SwitchKind::breakaway, y[0], a, dir});
      } else if (previous_dir != 0) {
        tr.switches.push_back({t, SwitchKind::reversal, y[0], a, dir});
      }
    }
    mode_now_ = next;
  }

  void set_root_directions() {
    int dirs[2] = {1, -1};
    if (mode_now_ == Mode::slide_pos) {
      dirs[0] = -1;
      dirs[1] = 0;
    } else if (mode_now_ == Mode::slide_neg) {
      dirs[0] = 1;
      dirs[1] = 0;
    }
    CVodeSetRootDirection(sd_.mem, dirs);
  }

  void restart(double t) {
    accumulate_stats();
    if (CVodeReInit(sd_.mem, t, sd_.y) != CV_SUCCESS) fail(t, "CVodeReInit failed");
    if (hybrid_) set_root_directions();
    stop_set_ = -1.0;
    interpolant_->reset();
    ++restarts_;
  }

  void accumulate_stats() {
    long nst = 0, nfe = 0;
    CVodeGetNumSteps(sd_.mem, &nst);
    CVodeGetNumRhsEvals(sd_.mem, &nfe);
    steps_ += nst;
    rhs_evals_ += nfe;
  }

  [[noreturn]] void fail(double t, const std::string& why) {
    throw std::runtime_error("simulation failed at t = " + detail::format_value(t) + " s: " + why);
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

    // Initial state.
    std::fill(y, y + n_, 0.0);
    plant_.initial_extras(std::span<double>(y, static_cast<std::size_t>(np_)));
    y[0] = o_.initial_position;
    y[1] = kinematic_ ? input_.at(0.0).value : o_.initial_velocity;
    for (int i = 0; i < np_; ++i) atol[i] = o_.atol;
    if (nz_ > 0) {
      std::vector<double> zs(static_cast<std::size_t>(nz_));
      law_.steady_state(1.0, zs);
      double scale = 0.0;
      for (double z : zs) scale = std::max(scale, std::abs(z));
      if (!(scale > 0)) scale = 1.0;
      for (int i = np_; i < n_; ++i) atol[i] = o_.atol * scale;
    }

    mode_now_ = Mode::free;
    if (sample_period_ > 0) sample1(0.0, std::span<double>(y, static_cast<std::size_t>(np_)), input_.at(0.0));
    if (hybrid_) {
      if (o_.initial_velocity > 0) {
        mode_now_ = Mode::slide_pos;
      } else if (o_.initial_velocity < 0) {
        mode_now_ = Mode::slide_neg;
      } else {
        settle_at_rest(tr, 0.0, y, false, 0);
      }
    }

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
    // Free motion with a dynamic law (the stiff case): exact Jacobian instead of n extra
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
    if (input_.max_step() > 0) hmax = hmax > 0 ? std::min(hmax, input_.max_step()) : input_.max_step();
    if (hmax > 0) CVodeSetMaxStep(sd_.mem, hmax);
    if (hybrid_) {
      if (CVodeRootInit(sd_.mem, 2, &Engine::roots_cb) != CV_SUCCESS) fail(0.0, "CVodeRootInit: " + error_);
      set_root_directions();
      CVodeSetNoInactiveRootWarn(sd_.mem);
    }

    // Corners of the input and, for a sampled controller, its sample instants k Ts (flagged).
    std::vector<double> corners;
    std::vector<char> is_sample;
    merge_corners(corners, is_sample);
    std::size_t next_corner = 0;
    const double rate = o_.output_rate;
    auto close = [](double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b)); };

    record(tr, 0.0, y, mode_now_ == Mode::stuck);
    double t = 0.0;
    double last_switch_time = -1.0;
    int switches_without_progress = 0;
    for (std::size_t k = 1; k < rows; ++k) {
      double tout = std::min(static_cast<double>(k) / rate, o_.duration);
      // Rows inside the step already taken come from its interpolant, without a CVode call.
      // Only without root functions (CVode checks roots up to each output time) and before
      // the next corner (whose handling must precede its row).
      if (!hybrid_ && (next_corner >= corners.size() || tout < corners[next_corner]) &&
          interpolant_->eval(sd_.mem, tout, y_row_.data())) {
        t = tout;
        record(tr, tout, y_row_.data(), false);
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
            } else if (mode_now_ == Mode::stuck) {
              settle_at_rest(tr, t, y, true, 0);
            }
            restart(t);
          }
        }
      }
      record(tr, tout, y, mode_now_ == Mode::stuck);
    }
    accumulate_stats();
    tr.stats.steps = steps_;
    tr.stats.rhs_evaluations = rhs_evals_;
    tr.stats.restarts = restarts_;
  }

  // Input corners in (0, duration) and sample instants k Ts (k >= 1) of a sampled controller, in
  // time order; equal times (as the table of a data input sampled on the same grid) merge.
  void merge_corners(std::vector<double>& corners, std::vector<char>& is_sample) const {
    std::vector<std::pair<double, char>> all;
    for (double c : input_.breakpoints(0.0, o_.duration)) all.emplace_back(c, 0);
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
    if (mode_now_ == Mode::stuck) {
      y[0] = stuck_position_;
      y[1] = 0.0;
    }
    sample1(t, std::span<double>(y, static_cast<std::size_t>(np_)), input_.at(t));
    if (mode_now_ == Mode::stuck) settle_at_rest(tr, t, y, true, 0);
  }

  void handle_root(Trajectory& tr, double t, double* y) {
    int found[2] = {0, 0};
    CVodeGetRootInfo(sd_.mem, found);
    if (mode_now_ == Mode::stuck) {
      // breakaway: the applied force reached a level
      const double a = applied_at_rest(t, y);
      y[0] = stuck_position_;
      y[1] = 0.0;
      const int dir = found[0] != 0 ? 1 : -1;
      mode_now_ = dir > 0 ? Mode::slide_pos : Mode::slide_neg;
      tr.switches.push_back({t, SwitchKind::breakaway, y[0], a, dir});
    } else {
      const int dir = mode_now_ == Mode::slide_pos ? 1 : -1;
      y[1] = 0.0;  // the velocity reached zero: exactly zero from now on
      settle_at_rest(tr, t, y, false, dir);
    }
  }

  // ---- fixed-step --------------------------------------------------------------------------

  void run_fixed(Trajectory& tr, std::size_t rows) {
    const double dt = o_.dt;
    const long per_row = std::lround(1.0 / (o_.output_rate * dt));
    std::vector<double> x(static_cast<std::size_t>(np_), 0.0), dx(x.size(), 0.0), z(static_cast<std::size_t>(nz_), 0.0);
    plant_.initial_extras(x);
    x[0] = o_.initial_position;
    x[1] = kinematic_ ? input_.at(0.0).value : o_.initial_velocity;
    mode_now_ = Mode::free;
    long per_sample = 0;  // steps per controller sample (sampled plants)
    if (sample_period_ > 0) {
      const double ratio = sample_period_ / dt;
      per_sample = std::lround(ratio);
      if (per_sample < 1 || std::abs(ratio - static_cast<double>(per_sample)) > 1e-6 * ratio)
        throw std::invalid_argument("simulation option dt = " + detail::format_value(dt) + " s must divide the controller's sample period " +
                                    detail::format_value(sample_period_) + " s a whole number of times");
      sample1(0.0, x, input_.at(0.0));
    }
    long step = 0;
    for (std::size_t k = 0; k < rows; ++k) {
      // Advance to the row's step count, then record the state there.
      const long target = static_cast<long>(k) * per_row;
      for (; step < target;) {
        const double t = static_cast<double>(step) * dt;
        const InputValue in = input_.at(t);
        if (kinematic_) x[1] = in.value;
        const double v = x[1];
        double f;
        if (nz_ > 0) {
          f = law_.step(z, v, dt);  // the law's exact update at constant v over the sample
        } else {
          const double a = applied1(t, x, in);
          f = law_.force(v, a);  // stiction only at v == 0 exactly (or in Karnopp's band)
        }
        deriv1(t, x, in, f, dx);
        if (kinematic_) {
          x[0] += dt * in.value;
        } else {
          x[1] += dt * dx[1];  // symplectic Euler: new velocity, then position with it
          x[0] += dt * x[1];
        }
        for (int i = 2; i < np_; ++i) x[static_cast<std::size_t>(i)] += dt * dx[static_cast<std::size_t>(i)];
        ++step;
        if (per_sample > 0 && step % per_sample == 0) {
          const double ts = static_cast<double>(step / per_sample) * sample_period_;
          sample1(ts, x, input_.at(ts));
        }
      }
      const double t = static_cast<double>(step) * dt;
      const InputValue in = input_.at(t);
      if (kinematic_) x[1] = in.value;
      double a = applied1(t, x, in);
      double f;
      if (nz_ > 0) {
        f = law_.force(std::span<const double>(z), x[1]);
      } else {
        f = law_.force(x[1], a);
      }
      PlantSignals s = signals1(t, x, in);
      if (kinematic_) a += f, s.drive += f;
      tr.time.push_back(static_cast<double>(k) / o_.output_rate);
      tr.position.push_back(x[0]);
      tr.velocity.push_back(x[1]);
      tr.friction.push_back(f);
      tr.applied.push_back(a);
      tr.current.push_back(s.current);
      tr.voltage.push_back(s.voltage);
      tr.reference.push_back(s.reference);
      tr.drive.push_back(s.drive);
      tr.stuck.push_back(x[1] == 0.0 && !kinematic_ && !law_.is_dynamic() ? 1.0 : 0.0);
      for (int i = 0; i < nz_; ++i) tr.law_state[static_cast<std::size_t>(i)].push_back(z[static_cast<std::size_t>(i)]);
    }
    tr.stats.steps = step;
    tr.stats.rhs_evaluations = step;
  }

  const Plant& plant_;
  const FrictionLaw& law_;
  const InputSignal& input_;
  const SimulationOptions& o_;
  SolverMode mode_;
  int np_ = 2, nz_ = 0, n_ = 2;
  double fbp_ = 0.0, fbn_ = 0.0;
  bool hybrid_ = false;
  bool kinematic_ = false;  // the plant imposes the velocity (plant_.kinematic(), asked once)
  double sample_period_ = 0.0;  // s; > 0 for a plant with a sampled controller
  Mode mode_now_ = Mode::free;
  double stuck_position_ = 0.0;
  std::vector<double> scratch_;
  Sundials sd_;
  std::optional<StiffSystem> system_;  // dynamic law with a plant that has an analytic Jacobian
  std::string error_;
  std::exception_ptr callback_exception_;  // what a callback threw (see guarded)
  double stop_set_ = -1.0;
  std::optional<detail::StepInterpolant> interpolant_;  // rows inside the last step (stiff mode)
  std::vector<double> y_row_;   // n: the state of an interpolated row
  long steps_ = 0, rhs_evals_ = 0, restarts_ = 0;
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

Trajectory simulate(const Plant& plant, const FrictionLaw& law, const InputSignal& input,
                    const SimulationOptions& options) {
  const SolverMode mode = resolve_solver_mode(law, options.mode);
  check_options(options, mode);
  check_output_size(options, law.is_dynamic() ? law.num_states() : 0);
  input.validate();
  Engine engine(plant, law, input, options, mode);
  return engine.run();
}

Trajectory simulate(const Scenario& scenario) {
  if (!scenario.plant) throw std::invalid_argument("scenario: no plant given");
  return simulate(*scenario.plant, scenario.law, scenario.input, scenario.options);
}

}  // namespace frictionlab
