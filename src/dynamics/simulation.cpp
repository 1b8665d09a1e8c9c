#include "poinsot/dynamics/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

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

  const InvariantTracker invariants(body, *torque, initial);
  const FlipDetector flips(body, torque);
  const bool locate = options.locate_flips && flips.applicable();
  SimulationResult result;
  result.flip_times.reserve(64);
  State s = initial;
  invariants.record(s, result.errors);

  const double t0 = initial.time;
  const double span = options.t_end - t0;
  // Samples at t0 + i·sample_dt for i = 0..n−1 and t_end (a last sample closer than 1e-9·sample_dt to
  // t_end is t_end itself).
  const auto n_intervals = static_cast<long long>(std::ceil(span / options.sample_dt - 1e-9));
  const auto sample_time = [&](long long i) {
    return i >= n_intervals ? options.t_end : t0 + static_cast<double>(i) * options.sample_dt;
  };
  const auto emit = [&](const State& x) {
    if (observer && !observer(x)) {
      result.interrupted = true;
      return false;
    }
    return true;
  };
  const auto finish = [&]() {
    result.final_state = s;
    result.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    return result;
  };
  // The torque's breakpoints (a tabulated torque's jumps and kinks): no step straddles one, and the torque is
  // told where each step starts (TorqueModel::enter_interval), so that stages at a breakpoint see one piece.
  const std::vector<double> breaks = torque->breakpoints();
  const auto next_stop = [&](double t, double limit) {
    const auto it = std::upper_bound(breaks.begin(), breaks.end(), t);
    return it != breaks.end() && *it < limit ? *it : limit;
  };
  const auto take_step = [&](State& x, double h) {
    torque->enter_interval(x.time);
    try {
      const StepResult r = integrator.step(x, h);
      ++result.steps;
      result.rejected_steps += r.rejected;
      return r;
    } catch (const ComputationFailed& e) {
      throw ComputationFailed(fmt::format("simulate: {} failed at step {} (t = {} s): {}", integrator.name(),
                                          result.steps + 1, x.time, e.what()));
    }
  };
  const DenseContext dense{&integrator, &flips};
  // After every step from `prev` to s: a finite state, the invariant errors, and a flip located inside the
  // step by root finding on the dense output, or on a cubic Hermite interpolant for methods without one.
  const auto after_step = [&](const State& prev) {
    require_finite_state(integrator, s, result.steps);
    invariants.record(s, result.errors);
    if (!locate) return;
    const double c0 = flips.component(prev);
    const double c1 = flips.component(s);
    if (!FlipDetector::sign_change(c0, c1)) return;
    result.flip_times.push_back(
        integrator.has_dense_output()
            ? locate_sign_change(&dense_component, &dense, prev.time, s.time, c0, c1)
            : FlipDetector::hermite_root(prev.time, s.time, c0, c1, flips.rate(prev), flips.rate(s)));
  };

  if (!emit(s)) return finish();
  long long next = 1;  // index of the next sample

  if (integrator.is_adaptive()) {
    double h = integrator.nominal_step() > 0.0 ? integrator.nominal_step() : options.sample_dt;
    while (s.time < options.t_end) {
      const State prev = s;
      const double stop = next_stop(s.time, options.t_end);
      const double remaining = stop - s.time;
      const bool last = h >= remaining;
      const StepResult r = take_step(s, last ? remaining : h);
      const bool reached = last && r.dt_taken == remaining;
      if (reached) s.time = stop;
      // A step cut short at a breakpoint says nothing against the step proposed before it.
      h = reached ? std::max(h, r.dt_next) : r.dt_next;
      after_step(prev);
      while (next <= n_intervals && sample_time(next) <= s.time) {
        const double ts = sample_time(next);
        ++next;
        if (!emit(ts == s.time ? s : integrator.dense_output(ts))) return finish();
      }
    }
    return finish();
  }

  // Fixed-step methods: each sample interval is cut into n equal steps of at most the nominal step, so that
  // samples land exactly on the sample times (no interpolation of the samples).
  const double h_nominal = integrator.nominal_step();
  // A torque-free body is advanced one sample interval at a time (Integrator::advance: no conversion to a
  // State between the steps), its per-step checks made from ω by FreeStepChecks. With a torque every step
  // ends in a State, since the torque and its flip rate depend on the attitude.
  const bool free = torque->is_zero();
  FreeStepChecks checks(integrator, invariants, flips, locate, result);
  // A sample interval holding breakpoints is cut at them first.
  for (; next <= n_intervals; ++next) {
    const double b = sample_time(next);
    while (s.time < b) {
      const double a = s.time;
      const double e = next_stop(a, b);
      const long long n =
          h_nominal > 0.0 ? std::max(1LL, static_cast<long long>(std::ceil((e - a) / h_nominal - 1e-9))) : 1;
      const double hh = (e - a) / static_cast<double>(n);
      if (free) {
        checks.begin(s, n, e);
        try {
          const StepResult r = integrator.advance(s, hh, n, &checks);
          result.rejected_steps += r.rejected;
        } catch (const ComputationFailed& err) {
          if (checks.failed()) throw;
          throw ComputationFailed(fmt::format("simulate: {} failed at step {} (t = {} s): {}",
                                              integrator.name(), result.steps + checks.steps_done() + 1,
                                              checks.time(), err.what()));
        }
        result.steps += n;
        s.time = e;
        require_finite_state(integrator, s, result.steps);
        invariants.record(s, result.errors);
        continue;
      }
      for (long long k = 0; k < n; ++k) {
        const State prev = s;
        take_step(s, hh);
        if (k == n - 1) s.time = e;
        after_step(prev);
      }
    }
    if (!emit(s)) return finish();
  }
  return finish();
}

}  // namespace poinsot::dynamics
