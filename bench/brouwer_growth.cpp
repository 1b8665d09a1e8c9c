// The growth of the round-off in the invariants of the fixed-step integrators (Brouwer's law).
//
// Run: build/release/bench/brouwer_growth [--max-steps N] [--members M] [--seed S] [--fit-from N0]
//                                         [--dt H] [--methods dlm,rattle,mb-rattle,mb-rk4]
//
// For each fixed-step method that keeps an invariant to round-off (the single-body registry's dlm and
// rattle, rk4 aside: its truncation error dominates; the multibody RATTLE and projected RK4 on one free
// body), an ensemble of M slightly perturbed initial conditions of the body J = diag(1, 2, 3) kg·m²,
// ω0 = (0.01, 2, 0.01) rad/s + δ (|δᵢ| ≤ 1e-3 rad/s), R0 = exp(j(ε)) (|εᵢ| ≤ 1e-3 rad), is integrated with
// dt = 1 ms (--dt). At N = 10³, 10^3.5, ..., max-steps steps it records the invariant errors of every member
// — relative kinetic energy |T − T₀|/T₀, relative space momentum |L − L₀|/|L₀|, relative |L| (the Casimir)
// and ‖RᵀR − I‖_F — and prints their root mean square over the ensemble. A random walk of the rounding gives
// an RMS growing like √N (Brouwer's law), a bias of the rounding like N: the exponent p of RMS ∝ N^p is
// fitted by least squares on log RMS against log N over the checkpoints N ≥ fit-from.
//
// The invariants a method does not keep to round-off (DLM's energy: an O(h²) oscillation; the projected
// RK4's energy and momenta: its O(h⁴) truncation error, which --dt tells from rounding) are printed, marked
// "(method)", without claim. RATTLE, single-body or multibody, keeps the free body's energy exactly.
// Deterministic: the ensemble is drawn from a fixed-seed SplitMix64 (tests/support/splitmix_draws.hpp, the
// generator of the round-off growth tests).
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "growth_exponent.hpp"
#include "poinsot/dynamics/integrator.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/multibody/methods.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot/so3/projection.hpp"
#include "splitmix_draws.hpp"

namespace {

using poinsot::Mat3;
using poinsot::Vec3;

const Vec3 kMoments(1.0, 2.0, 3.0);
const Vec3 kOmega0(0.01, 2.0, 0.01);

// One sample of the invariants of a state.
struct Invariants {
  double energy;
  Vec3 L_space;
  double R_orthogonality;
};

// The errors of one member at one checkpoint, relative to its initial invariants.
struct Errors {
  double energy, L_space, L_norm, orthogonality;
};

Errors errors(const Invariants& now, const Invariants& start) {
  const double L0 = start.L_space.norm();
  return {std::abs(now.energy - start.energy) / start.energy, (now.L_space - start.L_space).norm() / L0,
          std::abs(now.L_space.norm() - L0) / L0, now.R_orthogonality};
}

// A method under measurement: reset(member) sets up its perturbed initial state, advance(n) takes n steps,
// sample() returns the invariants of the current state.
class Run {
 public:
  virtual ~Run() = default;
  virtual void reset(const Mat3& R0, const Vec3& omega0) = 0;
  virtual void advance(long n) = 0;
  virtual Invariants sample() const = 0;
};

class SingleBodyRun final : public Run {
 public:
  SingleBodyRun(std::string_view method, double dt)
      : body_(poinsot::dynamics::RigidBody::from_principal_moments(kMoments)), method_(method), dt_(dt) {}
  void reset(const Mat3& R0, const Vec3& omega0) override {
    poinsot::dynamics::IntegratorOptions o;
    o.dt = dt_;
    integrator_ = poinsot::dynamics::make_integrator(method_, body_, nullptr, o);
    state_ = {};
    state_.R_space_body = R0;
    state_.omega_body = omega0;
  }
  void advance(long n) override {
    for (long k = 0; k < n; ++k)
      integrator_->step(state_, dt_);
  }
  Invariants sample() const override {
    return {poinsot::dynamics::kinetic_energy(body_, state_),
            poinsot::dynamics::angular_momentum_space(body_, state_),
            poinsot::so3::orthogonality_error(state_.R_space_body)};
  }

 private:
  poinsot::dynamics::RigidBody body_;
  std::string method_;
  double dt_;
  std::unique_ptr<poinsot::dynamics::Integrator> integrator_;
  poinsot::dynamics::State state_;
};

class FreeBodyMultibodyRun final : public Run {
 public:
  FreeBodyMultibodyRun(poinsot::multibody::MultibodyMethod method, double dt) : method_(method), dt_(dt) {
    system_.add_body_from_inertia("body", 1.0, kMoments.asDiagonal());
  }
  void reset(const Mat3& R0, const Vec3& omega0) override {
    const auto& info = poinsot::multibody::multibody_method_info(method_);
    integrator_ = info.make(system_, dt_, info.order);
    state_ = {};
    state_.bodies.resize(1);
    state_.bodies[0].R_space_body = R0;
    state_.bodies[0].omega_body = omega0;
  }
  void advance(long n) override {
    for (long k = 0; k < n; ++k)
      integrator_->step(state_);
  }
  Invariants sample() const override {
    return {poinsot::multibody::kinetic_energy(system_, state_),
            poinsot::multibody::angular_momentum(system_, state_),
            poinsot::so3::orthogonality_error(state_.bodies[0].R_space_body)};
  }

 private:
  poinsot::multibody::System system_;
  poinsot::multibody::MultibodyMethod method_;
  double dt_;
  std::unique_ptr<poinsot::multibody::MultibodyIntegrator> integrator_;
  poinsot::multibody::State state_;
};

struct MethodCase {
  std::string name;
  // Which of (energy, L_space, |L|, RᵀR) the method keeps to round-off.
  bool keeps[4];
};

std::unique_ptr<Run> make_run(const std::string& name, double dt) {
  using poinsot::multibody::MultibodyMethod;
  if (name == "mb-rattle") return std::make_unique<FreeBodyMultibodyRun>(MultibodyMethod::rattle, dt);
  if (name == "mb-rk4") return std::make_unique<FreeBodyMultibodyRun>(MultibodyMethod::projected_rk4, dt);
  return std::make_unique<SingleBodyRun>(name, dt);
}

[[noreturn]] void usage(const char* message) {
  std::fprintf(stderr,
               "brouwer_growth: %s\nusage: brouwer_growth [--max-steps N] [--members M] [--seed S] "
               "[--fit-from N0] [--dt H] [--methods dlm,rattle,mb-rattle,mb-rk4]\n",
               message);
  std::exit(2);
}

double number_arg(int& i, int argc, char** argv) {
  if (i + 1 >= argc) usage("an option is missing its value");
  char* end = nullptr;
  const double v = std::strtod(argv[++i], &end);
  if (*end != '\0' || !(v > 0.0)) usage("expected a positive number after an option");
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  double max_steps = 1e6, fit_from = 1e4, dt = 1e-3;
  int members = 20;
  std::uint64_t seed = 20;
  std::string methods = "dlm,rattle,mb-rattle,mb-rk4";
  for (int i = 1; i < argc; ++i) {
    const std::string_view a = argv[i];
    if (a == "--max-steps") {
      max_steps = number_arg(i, argc, argv);
    } else if (a == "--members") {
      members = static_cast<int>(number_arg(i, argc, argv));
    } else if (a == "--seed") {
      seed = static_cast<std::uint64_t>(number_arg(i, argc, argv));
    } else if (a == "--dt") {
      dt = number_arg(i, argc, argv);
    } else if (a == "--fit-from") {
      fit_from = number_arg(i, argc, argv);
    } else if (a == "--methods" && i + 1 < argc) {
      methods = argv[++i];
    } else {
      usage("unknown option");
    }
  }
  if (max_steps < 1e3 || max_steps > 1e10) usage("--max-steps must lie in [1e3, 1e10]");
  if (dt > 0.1) usage("--dt must be at most 0.1 s (the body turns at ~2 rad/s)");

  // Checkpoints at half decades from 10³.
  std::vector<long> checkpoints;
  for (double e = 3.0; std::pow(10.0, e) <= max_steps * (1 + 1e-12); e += 0.5)
    checkpoints.push_back(std::lround(std::pow(10.0, e)));

  std::vector<MethodCase> cases;
  for (std::size_t p = 0; p <= methods.size();) {
    const std::size_t q = std::min(methods.find(',', p), methods.size());
    const std::string name = methods.substr(p, q - p);
    p = q + 1;
    if (name == "dlm") {
      cases.push_back({name, {false, true, true, true}});
    } else if (name == "rattle") {
      cases.push_back({name, {true, true, true, true}});
    } else if (name == "mb-rattle") {
      cases.push_back({name, {true, true, true, true}});
    } else if (name == "mb-rk4") {
      cases.push_back({name, {false, false, false, true}});
    } else {
      usage("unknown method (expected dlm, rattle, mb-rattle, mb-rk4)");
    }
  }

  std::printf(
      "# Brouwer growth: J = diag(1, 2, 3) kg m^2, omega0 = (0.01, 2, 0.01) rad/s, dt = %g s, %d members, "
      "seed %llu\n",
      dt, members, static_cast<unsigned long long>(seed));
  const char* labels[4] = {"energy", "L_space", "|L|", "RtR-I"};
  for (const MethodCase& mc : cases) {
    const auto t_start = std::chrono::steady_clock::now();
    std::vector<std::vector<double>> sum_sq(4, std::vector<double>(checkpoints.size(), 0.0));
    poinsot::test::SplitMixDraws rng{seed};
    auto run = make_run(mc.name, dt);
    for (int m = 0; m < members; ++m) {
      const Mat3 R0 = poinsot::so3::exp(rng.vec(1e-3));
      const Vec3 omega0 = kOmega0 + rng.vec(1e-3);
      run->reset(R0, omega0);
      const Invariants start = run->sample();
      long done = 0;
      for (std::size_t c = 0; c < checkpoints.size(); ++c) {
        run->advance(checkpoints[c] - done);
        done = checkpoints[c];
        const Errors e = errors(run->sample(), start);
        const double v[4] = {e.energy, e.L_space, e.L_norm, e.orthogonality};
        for (int k = 0; k < 4; ++k)
          sum_sq[static_cast<std::size_t>(k)][c] += v[k] * v[k];
      }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
    std::printf("\n## %s  (%.1f s, %.0f ns/step)\n%-12s", mc.name.c_str(), seconds,
                1e9 * seconds / (static_cast<double>(members) * static_cast<double>(checkpoints.back())),
                "N");
    for (int k = 0; k < 4; ++k)
      std::printf(" %14s", labels[k]);
    std::printf("\n");
    std::vector<double> x;
    std::vector<std::vector<double>> rms(4);
    for (std::size_t c = 0; c < checkpoints.size(); ++c) {
      std::printf("%-12ld", checkpoints[c]);
      const bool fitted = static_cast<double>(checkpoints[c]) >= fit_from * (1 - 1e-12);
      for (std::size_t k = 0; k < 4; ++k) {
        const double r = std::sqrt(sum_sq[k][c] / members);
        std::printf(" %14.3e", r);
        if (fitted) rms[k].push_back(r);
      }
      if (fitted) x.push_back(static_cast<double>(checkpoints[c]));
      std::printf("\n");
    }
    std::printf("%-12s", "exponent");
    for (std::size_t k = 0; k < 4; ++k) {
      const double p = poinsot::test::growth_exponent(x, rms[k]);
      std::printf(" %6.2f%-8s", p, mc.keeps[k] ? "" : "(method)");
    }
    std::printf("\n");
    std::fflush(stdout);
  }
  return 0;
}
