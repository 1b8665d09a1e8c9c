// The growth of the round-off in the invariants of the fixed-step integrators (Brouwer's law).
//
// Run: build/release/bench/brouwer_growth [--max-steps N] [--members M] [--seed S] [--fit-from N0]
//                                         [--dt H] [--methods dlm,rattle,mb-rattle,mb-rk4]
//                                         [--threads T] [--checkpoint FILE] [--signed]
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
// generator of the round-off growth tests), all members' initial conditions before any is integrated, and the
// sums over the ensemble are taken in member order, so the output does not depend on --threads (members run
// in parallel, one thread each).
//
// --signed also prints, at every checkpoint, the ensemble mean of the signed relative errors of the energy
// and of |L| with its standard error (sample standard deviation / √M), in units of ε = 2⁻⁵², and the mean
// divided by N: the bias a step. A random walk leaves a mean that is zero within its standard error, which
// shrinks like 1/√M; a bias b a step gives a mean b·N. Over M members and N steps the bias shows at
// b·√(M·N)/(RMS/√N) standard errors, long before it dominates the RMS (the RMS grows like b·N only once
// b·N exceeds the walk's spread): 100 members at 10⁶ steps show a bias of 3e-20 a step at about 3.5 σ,
// where 20 members need 10⁸ steps for the RMS to bend. Not with --checkpoint (lines of earlier programs hold
// unsigned errors).
//
// Long campaigns (10⁹ steps is 2·10¹⁰ steps a method, CPU hours) survive interruption with --checkpoint FILE:
// every finished member appends one line (method, seed, dt, checkpoints, its errors in hexadecimal floating
// point, so exactly) with a single write; a run with the same FILE and settings reads those lines back and
// integrates only the members still missing. A line cut short by a kill is not read (it lacks its end
// marker). A member's own run is not resumable: an interruption loses at most the members in progress.
#include <fcntl.h>
#include <unistd.h>
#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <string_view>
#include <thread>
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

// The errors of one member at one checkpoint, relative to its initial invariants; those of the energy and of
// |L| signed (a bias of the rounding shows in their ensemble mean).
struct Errors {
  double energy, L_space, L_norm, orthogonality;
};

Errors errors(const Invariants& now, const Invariants& start) {
  const double L0 = start.L_space.norm();
  return {(now.energy - start.energy) / start.energy, (now.L_space - start.L_space).norm() / L0,
          (now.L_space.norm() - L0) / L0, now.R_orthogonality};
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
               "[--fit-from N0] [--dt H] [--methods dlm,rattle,mb-rattle,mb-rk4] [--threads T] "
               "[--checkpoint FILE] [--signed]\n",
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

// The errors of one member at every checkpoint: errors[c][k], k over (energy, L_space, |L|, RᵀR).
using MemberErrors = std::vector<std::array<double, 4>>;

// What identifies a run in a checkpoint file: a line is reused only if all of it matches.
std::string run_key(const std::string& method, std::uint64_t seed, double dt,
                    const std::vector<long>& checkpoints) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s %llu %a %zu %ld", method.c_str(), static_cast<unsigned long long>(seed),
                dt, checkpoints.size(), checkpoints.back());
  return buf;
}

// One finished member as a checkpoint line: "<key> m <member> <4 values per checkpoint, %a> end\n".
std::string checkpoint_line(const std::string& key, int member, const MemberErrors& e) {
  std::string line = key + " m " + std::to_string(member);
  char buf[40];
  for (const auto& at : e)
    for (double v : at) {
      std::snprintf(buf, sizeof buf, " %a", v);
      line += buf;
    }
  return line + " end\n";
}

// The members of run `key` already in the checkpoint file (an absent file holds none); lines of other runs,
// and a line cut short, are skipped.
std::vector<MemberErrors> read_checkpoint(const std::string& path, const std::string& key, int members,
                                          std::size_t n_checkpoints) {
  std::vector<MemberErrors> done(static_cast<std::size_t>(members));
  std::FILE* f = std::fopen(path.c_str(), "r");
  if (f == nullptr) return done;
  std::string line;
  for (int ch; (ch = std::fgetc(f)) != EOF;) {
    if (ch != '\n') {
      line.push_back(static_cast<char>(ch));
      continue;
    }
    const std::string prefix = key + " m ";
    if (line.compare(0, prefix.size(), prefix) == 0 && line.size() > 4 &&
        line.compare(line.size() - 4, 4, " end") == 0) {
      const char* p = line.c_str() + prefix.size();
      char* end = nullptr;
      const long m = std::strtol(p, &end, 10);
      MemberErrors e(n_checkpoints);
      bool ok = end != p && m >= 0 && m < members;
      p = end;
      for (std::size_t c = 0; ok && c < n_checkpoints; ++c)
        for (std::size_t k = 0; ok && k < 4; ++k) {
          e[c][k] = std::strtod(p, &end);
          ok = end != p;
          p = end;
        }
      if (ok && std::strcmp(p, " end") == 0) done[static_cast<std::size_t>(m)] = std::move(e);
    }
    line.clear();
  }
  std::fclose(f);
  return done;
}

void append_line(const std::string& path, const std::string& line);

// Ends a last line that a kill cut short, so that the next line appended starts a line of its own.
void end_cut_line(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "r");
  if (f == nullptr) return;
  const bool cut = std::fseek(f, -1, SEEK_END) == 0 && std::fgetc(f) != '\n';
  std::fclose(f);
  if (cut) append_line(path, "\n");
}

// Appends one line with a single write(2) on an O_APPEND descriptor, so concurrent members and a kill leave
// whole lines (the reader drops a line without its end marker).
void append_line(const std::string& path, const std::string& line) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd < 0 || ::write(fd, line.data(), line.size()) != static_cast<ssize_t>(line.size()) ||
      ::fsync(fd) != 0) {
    std::fprintf(stderr, "brouwer_growth: cannot append to checkpoint file '%s': %s\n", path.c_str(),
                 std::strerror(errno));
    std::exit(1);
  }
  ::close(fd);
}

// Integrates one member through every checkpoint.
MemberErrors run_member(Run& run, const Mat3& R0, const Vec3& omega0, const std::vector<long>& checkpoints) {
  run.reset(R0, omega0);
  const Invariants start = run.sample();
  MemberErrors out(checkpoints.size());
  long done = 0;
  for (std::size_t c = 0; c < checkpoints.size(); ++c) {
    run.advance(checkpoints[c] - done);
    done = checkpoints[c];
    const Errors e = errors(run.sample(), start);
    out[c] = {e.energy, e.L_space, e.L_norm, e.orthogonality};
  }
  return out;
}

// The ensemble mean of the signed relative errors of the energy (k = 0) and |L| (k = 2) at every checkpoint,
// with its standard error, in ε, and the mean a step; sums in member order.
void print_signed_means(const std::vector<MemberErrors>& results, const std::vector<long>& checkpoints) {
  constexpr double kEps = 0x1.0p-52;
  const double m = static_cast<double>(results.size());
  std::printf("%-12s %24s %12s %24s %12s\n", "N", "energy mean +- s.e. [eps]", "per step",
              "|L| mean +- s.e. [eps]", "per step");
  for (std::size_t c = 0; c < checkpoints.size(); ++c) {
    std::printf("%-12ld", checkpoints[c]);
    for (std::size_t k : {std::size_t{0}, std::size_t{2}}) {
      double sum = 0.0, sum_sq = 0.0;
      for (const MemberErrors& e : results)
        sum += e[c][k];
      const double mean = sum / m;
      for (const MemberErrors& e : results)
        sum_sq += (e[c][k] - mean) * (e[c][k] - mean);
      const double se = m > 1.0 ? std::sqrt(sum_sq / (m - 1.0) / m) : 0.0;
      std::printf(" %+11.3f +- %9.3f %+12.2e", mean / kEps, se / kEps,
                  mean / static_cast<double>(checkpoints[c]));
    }
    std::printf("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  double max_steps = 1e6, fit_from = 1e4, dt = 1e-3;
  int members = 20, threads = 1;
  std::uint64_t seed = 20;
  std::string methods = "dlm,rattle,mb-rattle,mb-rk4", checkpoint_path;
  bool signed_means = false;
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
    } else if (a == "--threads") {
      threads = static_cast<int>(number_arg(i, argc, argv));
    } else if (a == "--methods" && i + 1 < argc) {
      methods = argv[++i];
    } else if (a == "--checkpoint" && i + 1 < argc) {
      checkpoint_path = argv[++i];
    } else if (a == "--signed") {
      signed_means = true;
    } else {
      usage("unknown option");
    }
  }
  if (max_steps < 1e3 || max_steps > 1e10) usage("--max-steps must lie in [1e3, 1e10]");
  if (dt > 0.1) usage("--dt must be at most 0.1 s (the body turns at ~2 rad/s)");
  if (members < 1 || members > 100000) usage("--members must lie in [1, 100000]");
  if (threads < 1 || threads > 256) usage("--threads must lie in [1, 256]");
  if (signed_means && !checkpoint_path.empty()) usage("--signed does not combine with --checkpoint");

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

  // Every member's initial condition, drawn in member order before any is integrated.
  std::vector<Mat3> R0(static_cast<std::size_t>(members));
  std::vector<Vec3> omega0(static_cast<std::size_t>(members));
  {
    poinsot::test::SplitMixDraws rng{seed};
    for (std::size_t m = 0; m < R0.size(); ++m) {
      R0[m] = poinsot::so3::exp(rng.vec(1e-3));
      omega0[m] = kOmega0 + rng.vec(1e-3);
    }
  }

  std::printf(
      "# Brouwer growth: J = diag(1, 2, 3) kg m^2, omega0 = (0.01, 2, 0.01) rad/s, dt = %g s, %d members, "
      "seed %llu\n",
      dt, members, static_cast<unsigned long long>(seed));
  const char* labels[4] = {"energy", "L_space", "|L|", "RtR-I"};
  for (const MethodCase& mc : cases) {
    const auto t_start = std::chrono::steady_clock::now();
    const std::string key = run_key(mc.name, seed, dt, checkpoints);
    if (!checkpoint_path.empty()) end_cut_line(checkpoint_path);
    std::vector<MemberErrors> results =
        checkpoint_path.empty() ? std::vector<MemberErrors>(static_cast<std::size_t>(members))
                                : read_checkpoint(checkpoint_path, key, members, checkpoints.size());
    std::vector<int> todo;
    for (int m = 0; m < members; ++m)
      if (results[static_cast<std::size_t>(m)].empty()) todo.push_back(m);
    const std::size_t resumed = static_cast<std::size_t>(members) - todo.size();
    if (resumed > 0)
      std::fprintf(stderr, "%s: %zu members read from %s\n", mc.name.c_str(), resumed,
                   checkpoint_path.c_str());

    std::atomic<std::size_t> next{0};
    auto worker = [&] {
      auto run = make_run(mc.name, dt);
      for (std::size_t i; (i = next.fetch_add(1)) < todo.size();) {
        const std::size_t m = static_cast<std::size_t>(todo[i]);
        results[m] = run_member(*run, R0[m], omega0[m], checkpoints);
        if (!checkpoint_path.empty())
          append_line(checkpoint_path, checkpoint_line(key, static_cast<int>(m), results[m]));
      }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < std::min<int>(threads, static_cast<int>(todo.size())); ++t)
      pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool)
      t.join();

    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
    std::printf("\n## %s  (%.1f s wall, %zu of %d members integrated here, %.0f ns/step per thread)\n%-12s",
                mc.name.c_str(), seconds, todo.size(), members,
                todo.empty()
                    ? 0.0
                    : 1e9 * seconds * std::min<double>(threads, static_cast<double>(todo.size())) /
                          (static_cast<double>(todo.size()) * static_cast<double>(checkpoints.back())),
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
        double sum_sq = 0.0;  // in member order, whatever order the members finished in
        for (const MemberErrors& e : results)
          sum_sq += e[c][k] * e[c][k];
        const double r = std::sqrt(sum_sq / members);
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
    if (signed_means) print_signed_means(results, checkpoints);
    std::fflush(stdout);
  }
  return 0;
}
