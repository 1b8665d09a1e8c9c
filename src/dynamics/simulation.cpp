#include "poinsot/dynamics/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/dynamics/flip_events.hpp"
#include "poinsot/so3/projection.hpp"

namespace poinsot::dynamics {
namespace {

/// Worst invariant errors against the initial values.
class InvariantTracker {
 public:
  InvariantTracker(const RigidBody& body, const TorqueModel& torque, const State& initial)
      : body_(body), g_(torque.gravity_space()) {
    track_energy_ = torque.is_zero() || torque.is_gravity();
    track_L_ = torque.is_zero();
    E0_ = total_energy(body, initial, g_);
    L0_ = angular_momentum_space(body, initial);
    L0_norm_ = L0_.norm();
  }
  void record(const State& s, InvariantErrors& e) const {
    if (track_energy_) {
      const double E = total_energy(body_, s, g_);
      e.energy_rel_max = std::max(e.energy_rel_max, std::abs(E - E0_) / std::max(std::abs(E0_), 1e-300));
    }
    if (track_L_ && L0_norm_ > 0.0) {
      const Vec3 L = angular_momentum_space(body_, s);
      e.L_space_rel_max = std::max(e.L_space_rel_max, (L - L0_).norm() / L0_norm_);
      e.L_norm_rel_max = std::max(e.L_norm_rel_max, std::abs(L.norm() - L0_norm_) / L0_norm_);
    }
    e.orthogonality_max = std::max(e.orthogonality_max, so3::orthogonality_error(s.R_space_body));
  }
  /// The energy error alone, from ω: the body is torque-free (no potential energy), so this is record()'s
  /// energy bit for bit, kinetic_energy(body, s) = ½ ωᵀJω.
  void record_free_energy(const Vec3& omega_body, InvariantErrors& e) const {
    const double E = 0.5 * omega_body.dot(body_.inertia() * omega_body);
    e.energy_rel_max = std::max(e.energy_rel_max, std::abs(E - E0_) / std::max(std::abs(E0_), 1e-300));
  }

 private:
  const RigidBody& body_;
  Vec3 g_;
  bool track_energy_ = false;
  bool track_L_ = false;
  double E0_ = 0.0;
  Vec3 L0_ = Vec3::Zero();
  double L0_norm_ = 0.0;
};

[[noreturn]] void throw_non_finite(const Integrator& integrator, double t, const Vec3& omega_body,
                                   long long step) {
  throw ComputationFailed(fmt::format(
      "simulate: {} produced a non-finite state at step {} (t = {} s): omega_body = {} rad/s; expected "
      "finite values (a smaller step or a tighter tolerance?)",
      integrator.name(), step, t, format_vector(omega_body)));
}

void require_finite_state(const Integrator& integrator, const State& s, long long step) {
  if (std::isfinite(s.time) && s.R_space_body.allFinite() && s.omega_body.allFinite()) return;
  throw_non_finite(integrator, s.time, s.omega_body, step);
}

struct DenseContext {
  const Integrator* integrator;
  const FlipDetector* flips;
};

double dense_component(double t, const void* ctx) {
  const auto& c = *static_cast<const DenseContext*>(ctx);
  return c.flips->component(c.integrator->dense_output(t));
}

/// The per-step checks of a torque-free body inside Integrator::advance, from ω alone: a finite ω, the energy
/// error, and the flips, located as the step-by-step loop locates them (the dense output of the step, or the
/// cubic Hermite interpolant of s from its values and rates at both ends). The last step of an advance ends
/// at the interval's end time e exactly (the driver's time, not the sum of the steps). The attitude's checks
/// (finite R, L_space, |L|, RᵀR = I) run on the State at the end of the advance.
class FreeStepChecks final : public StepWatcher {
 public:
  FreeStepChecks(const Integrator& integrator, const InvariantTracker& invariants, const FlipDetector& flips,
                 bool locate, SimulationResult& result)
      : integrator_(integrator), invariants_(invariants), flips_(flips), locate_(locate), result_(result) {}

  /// Before an advance of n steps from `s` ending at time e (s).
  void begin(const State& s, long long n, double e) {
    n_ = n;
    e_ = e;
    t0_ = s.time;
    w0_ = s.omega_body;
    c0_ = flips_.component(s.omega_body);
    failed_ = false;
    done_ = 0;
  }
  bool failed() const { return failed_; }
  /// The steps of the current advance seen so far, and the time (s) the last of them reached.
  long long steps_done() const { return done_; }
  double time() const { return t0_; }

  void after_step(long long k, double time, const Vec3& omega_body) override {
    const double t = k == n_ - 1 ? e_ : time;
    if (!(std::isfinite(t) && omega_body.allFinite())) {
      failed_ = true;
      throw_non_finite(integrator_, t, omega_body, result_.steps + k + 1);
    }
    invariants_.record_free_energy(omega_body, result_.errors);
    if (locate_) {
      const double c1 = flips_.component(omega_body);
      if (FlipDetector::sign_change(c0_, c1)) {
        if (integrator_.has_dense_output()) {
          const DenseContext dense{&integrator_, &flips_};
          result_.flip_times.push_back(locate_sign_change(&dense_component, &dense, t0_, t, c0_, c1));
        } else {
          result_.flip_times.push_back(FlipDetector::hermite_root(t0_, t, c0_, c1, flips_.free_rate(w0_),
                                                                  flips_.free_rate(omega_body)));
        }
      }
      c0_ = c1;
    }
    t0_ = t;
    w0_ = omega_body;
    done_ = k + 1;
  }

 private:
  const Integrator& integrator_;
  const InvariantTracker& invariants_;
  const FlipDetector& flips_;
  bool locate_;
  SimulationResult& result_;
  long long n_ = 0;
  double e_ = 0.0;
  double t0_ = 0.0;
  Vec3 w0_ = Vec3::Zero();
  double c0_ = 0.0;
  bool failed_ = false;
  long long done_ = 0;
};

/// One call of simulate(): what persists between the steps (the state, the samples' times, the invariants,
/// the flip detector, the result) and the two step loops, adaptive (samples from the dense output) and fixed
/// (steps that land on the samples).
class SimulationRun {
 public:
  SimulationRun(const RigidBody& body, std::shared_ptr<const TorqueModel> torque, const State& initial,
                Integrator& integrator, const SimulationOptions& options, const Observer& observer,
                std::chrono::steady_clock::time_point wall_start)
      : torque_(std::move(torque)),
        integrator_(integrator),
        options_(options),
        observer_(observer),
        wall_start_(wall_start),
        invariants_(body, *torque_, initial),
        flips_(body, torque_),
        locate_(options.locate_flips && flips_.applicable()),
        breaks_(torque_->breakpoints()),
        dense_{&integrator, &flips_},
        s_(initial),
        t0_(initial.time),
        // Samples at t0 + i·sample_dt for i = 0..n−1 and t_end (a last sample closer than 1e-9·sample_dt to
        // t_end is t_end itself).
        n_intervals_(static_cast<long long>(std::ceil((options.t_end - t0_) / options.sample_dt - 1e-9))) {
    result_.flip_times.reserve(64);
    invariants_.record(s_, result_.errors);
  }

  SimulationResult run() {
    if (!emit(s_)) return finish();
    return integrator_.is_adaptive() ? run_adaptive() : run_fixed();
  }

 private:
  double sample_time(long long i) const {
    return i >= n_intervals_ ? options_.t_end : t0_ + static_cast<double>(i) * options_.sample_dt;
  }

  /// Hands a sample to the observer; false (and the result marked interrupted) when it asks to stop.
  bool emit(const State& x) {
    if (observer_ && !observer_(x)) {
      result_.interrupted = true;
      return false;
    }
    return true;
  }

  SimulationResult finish() {
    result_.final_state = s_;
    result_.wall_time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start_).count();
    return result_;
  }

  /// The torque's breakpoints (a tabulated torque's jumps and kinks): no step straddles one, and the torque
  /// is told where each step starts (TorqueModel::enter_interval), so that stages at a breakpoint see one
  /// piece. The first breakpoint after t before `limit`, else `limit`.
  double next_stop(double t, double limit) const {
    const auto it = std::upper_bound(breaks_.begin(), breaks_.end(), t);
    return it != breaks_.end() && *it < limit ? *it : limit;
  }

  StepResult take_step(State& x, double h) {
    torque_->enter_interval(x.time);
    try {
      const StepResult r = integrator_.step(x, h);
      ++result_.steps;
      result_.rejected_steps += r.rejected;
      return r;
    } catch (const ComputationFailed& e) {
      throw ComputationFailed(fmt::format("simulate: {} failed at step {} (t = {} s): {}", integrator_.name(),
                                          result_.steps + 1, x.time, e.what()));
    }
  }

  /// After every step from `prev` to the state: a finite state, the invariant errors, and a flip located
  /// inside the step by root finding on the dense output, or on a cubic Hermite interpolant for methods
  /// without one.
  void after_step(const State& prev) {
    require_finite_state(integrator_, s_, result_.steps);
    invariants_.record(s_, result_.errors);
    if (!locate_) return;
    const double c0 = flips_.component(prev);
    const double c1 = flips_.component(s_);
    if (!FlipDetector::sign_change(c0, c1)) return;
    result_.flip_times.push_back(
        integrator_.has_dense_output()
            ? locate_sign_change(&dense_component, &dense_, prev.time, s_.time, c0, c1)
            : FlipDetector::hermite_root(prev.time, s_.time, c0, c1, flips_.rate(prev), flips_.rate(s_)));
  }

  /// Adaptive methods: the steps the controller proposes, cut at the breakpoints and at t_end; the samples
  /// from the dense output.
  SimulationResult run_adaptive() {
    long long next = 1;  // index of the next sample
    double h = integrator_.nominal_step() > 0.0 ? integrator_.nominal_step() : options_.sample_dt;
    while (s_.time < options_.t_end) {
      const State prev = s_;
      const double stop = next_stop(s_.time, options_.t_end);
      const double remaining = stop - s_.time;
      const bool last = h >= remaining;
      const StepResult r = take_step(s_, last ? remaining : h);
      const bool reached = last && r.dt_taken == remaining;
      if (reached) s_.time = stop;
      // A step cut short at a breakpoint says nothing against the step proposed before it.
      h = reached ? std::max(h, r.dt_next) : r.dt_next;
      after_step(prev);
      while (next <= n_intervals_ && sample_time(next) <= s_.time) {
        const double ts = sample_time(next);
        ++next;
        if (!emit(ts == s_.time ? s_ : integrator_.dense_output(ts))) return finish();
      }
    }
    return finish();
  }

  /// Fixed-step methods: each sample interval is cut into n equal steps of at most the nominal step, so that
  /// samples land exactly on the sample times (no interpolation of the samples). A torque-free body is
  /// advanced one sample interval at a time (Integrator::advance: no conversion to a State between the
  /// steps), its per-step checks made from ω by FreeStepChecks. With a torque every step ends in a State,
  /// since the torque and its flip rate depend on the attitude.
  SimulationResult run_fixed() {
    const double h_nominal = integrator_.nominal_step();
    const bool free = torque_->is_zero();
    FreeStepChecks checks(integrator_, invariants_, flips_, locate_, result_);
    // A sample interval holding breakpoints is cut at them first.
    for (long long next = 1; next <= n_intervals_; ++next) {
      const double b = sample_time(next);
      while (s_.time < b) {
        const double a = s_.time;
        const double e = next_stop(a, b);
        const long long n = h_nominal > 0.0
                                ? std::max(1LL, static_cast<long long>(std::ceil((e - a) / h_nominal - 1e-9)))
                                : 1;
        const double hh = (e - a) / static_cast<double>(n);
        if (free) {
          advance_free(checks, n, hh, e);
          continue;
        }
        for (long long k = 0; k < n; ++k) {
          const State prev = s_;
          take_step(s_, hh);
          if (k == n - 1) s_.time = e;
          after_step(prev);
        }
      }
      if (!emit(s_)) return finish();
    }
    return finish();
  }

  /// n steps of hh to `end` of a torque-free body through Integrator::advance.
  void advance_free(FreeStepChecks& checks, long long n, double hh, double end) {
    checks.begin(s_, n, end);
    try {
      const StepResult r = integrator_.advance(s_, hh, n, &checks);
      result_.rejected_steps += r.rejected;
    } catch (const ComputationFailed& err) {
      if (checks.failed()) throw;
      throw ComputationFailed(fmt::format("simulate: {} failed at step {} (t = {} s): {}", integrator_.name(),
                                          result_.steps + checks.steps_done() + 1, checks.time(),
                                          err.what()));
    }
    result_.steps += n;
    s_.time = end;
    require_finite_state(integrator_, s_, result_.steps);
    invariants_.record(s_, result_.errors);
  }

  std::shared_ptr<const TorqueModel> torque_;
  Integrator& integrator_;
  const SimulationOptions& options_;
  const Observer& observer_;
  std::chrono::steady_clock::time_point wall_start_;
  const InvariantTracker invariants_;
  const FlipDetector flips_;
  const bool locate_;
  const std::vector<double> breaks_;
  const DenseContext dense_;
  SimulationResult result_;
  State s_;
  const double t0_;
  const long long n_intervals_;
};

}  // namespace

SimulationResult simulate(const RigidBody& body, std::shared_ptr<const TorqueModel> torque,
                          const State& initial, Integrator& integrator, const SimulationOptions& options,
                          const Observer& observer) {
  const auto wall_start = std::chrono::steady_clock::now();
  if (!torque) torque = TorqueModel::none();
  validate_state(initial, "simulate: initial state");
  require_finite("simulate: t_end (s)", options.t_end);
  if (!(options.t_end > initial.time)) {
    throw InvalidInput(fmt::format("simulate: t_end = {} s; expected a time after the initial t = {} s",
                                   options.t_end, initial.time));
  }
  require_positive("simulate: sample_dt", options.sample_dt, "s");
  return SimulationRun(body, std::move(torque), initial, integrator, options, observer, wall_start).run();
}

}  // namespace poinsot::dynamics
