// The contract every single-body method of the registry (dynamics/methods.hpp) must meet, run on each entry:
// a new method is tested here as soon as it has its entry. The integrator agrees with its entry (name, order,
// adaptivity, dense output, torques); its measured order equals the declared one; R stays a rotation to
// round-off; what it declares preserved is preserved to round-off; stepping allocates nothing; a rotated body
// frame gives the same motion; repeated runs are bit-identical.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "allocation_counter.hpp"
#include "dynamics_test_util.hpp"
#include "poinsot/dynamics/methods.hpp"
#include "poinsot/so3/projection.hpp"
#include "poinsot_test.hpp"

namespace poinsot::test {
namespace {

using dynamics::MethodInfo;

/// The registry's entries (pointers: the test names the entry it ran, and compares addresses).
std::vector<const MethodInfo*> entries() {
  std::vector<const MethodInfo*> out;
  for (const MethodInfo& m : dynamics::methods())
    out.push_back(&m);
  return out;
}

class IntegratorContract : public ::testing::TestWithParam<const MethodInfo*> {
 protected:
  const MethodInfo& info() const { return *GetParam(); }

  /// A fixed step h (s) for every method: an adaptive one with tolerances so loose that it accepts every
  /// step it is asked (no max_step), so that it is measured as the Runge–Kutta method it is.
  std::unique_ptr<dynamics::Integrator> make(const RigidBody& body, double h,
                                             std::shared_ptr<const TorqueModel> torque = nullptr) const {
    IntegratorOptions o;
    o.dt = h;
    if (info().adaptive) o.rtol = o.atol = 1e6;
    return info().make(body, torque ? std::move(torque) : TorqueModel::none(), o);
  }

  /// A torque for the methods that take one: constant in the body frame, N·m (of the order of |J ω̇| here).
  std::shared_ptr<const TorqueModel> torque() const {
    return info().takes_torque ? TorqueModel::constant_body(Vec3(0.3, -0.2, 0.1)) : TorqueModel::none();
  }
};

TEST_P(IntegratorContract, AgreesWithItsRegistryEntry) {
  const auto m = make(kBody, 1e-3);
  EXPECT_EQ(m->name(), info().name);
  EXPECT_EQ(m->order(), info().order);
  EXPECT_EQ(m->is_adaptive(), info().adaptive);
  EXPECT_EQ(m->has_dense_output(), info().dense_output);
  EXPECT_EQ(&dynamics::method_info(info().name), &info());
  EXPECT_FALSE(info().description.empty());
  if (!info().takes_torque) {
    POINSOT_EXPECT_THROWS_MESSAGE(make(kBody, 1e-3, TorqueModel::constant_body(Vec3(0, 0, 1))), InvalidInput,
                                  std::string(info().name));
  }
}

// Error against the dop853 reference (rtol = atol = 1e-14: error ~1e-13) at T with n and 2n steps, on the
// tumbling body (|ω| = 1.4 rad/s) with a constant body torque for the methods that take one. T and n put each
// method in its asymptotic range with the finer error well above the reference's (measured: order 2, T = 1 s,
// n = 50: 2.00 with errors ~1e-4; rk4 and dopri5, T = 1 s, n = 20: 3.99 and 5.03, errors 1e-8 and 6e-12;
// dop853, T = 4 s, n = 10: 8.10, errors 5e-8 and 2e-10). The next error term shifts the measured order by
// O(h): ±0.2.
TEST_P(IntegratorContract, MeasuredOrderIsTheDeclaredOrder) {
  const State s0 = tumbling();
  const int p = info().order;
  const double T = p >= 8 ? 4.0 : 1.0;
  const auto tau = torque();
  const State ref = reference(kBody, tau, s0, T);
  if (p == 0) {  // exact: no truncation error at any step
    auto m = make(kBody, 0.25);
    EXPECT_LT(state_error(run_fixed(*m, s0, T, 4), ref), 1e-12);
    return;
  }
  const long long n = p >= 8 ? 10 : p >= 4 ? 20 : 50;
  auto a = make(kBody, T / static_cast<double>(n), tau);
  auto b = make(kBody, T / static_cast<double>(2 * n), tau);
  const double e1 = state_error(run_fixed(*a, s0, T, n), ref);
  const double e2 = state_error(run_fixed(*b, s0, T, 2 * n), ref);
  EXPECT_GT(e2, 1e-12) << "the finer error is too close to the reference's to measure an order";
  EXPECT_NEAR(measured_order(e1, e2), p, 0.2) << "errors " << e1 << ", " << e2;
}

// 2000 steps of h = 0.01 s (about 4 turns): RᵀR = I to round-off, and the declared invariants of the
// torque-free motion to round-off: relative drift ≤ 1e-12, i.e. 2000 steps of a few ulp each (a method of
// order p that does not preserve them drifts by ~(hω)^p ≥ 1e-9 here).
TEST_P(IntegratorContract, KeepsRotationAndDeclaredInvariantsToRoundOff) {
  auto m = make(kBody, 0.01);
  const State s0 = tumbling();
  const State s = run_fixed(*m, s0, 20.0, 2000);
  EXPECT_LT(so3::orthogonality_error(s.R_space_body), 1e-13);
  const auto rel = [](double a, double b) { return std::abs(a - b) / std::abs(b); };
  const auto& p = info().preserves;
  if (p.energy) {
    EXPECT_LT(rel(dynamics::kinetic_energy(kBody, s), dynamics::kinetic_energy(kBody, s0)), 1e-12);
  }
  const Vec3 L0 = dynamics::angular_momentum_space(kBody, s0);
  if (p.L_space) {
    EXPECT_LT((dynamics::angular_momentum_space(kBody, s) - L0).norm() / L0.norm(), 1e-12);
  }
  if (p.L_body_norm) {
    EXPECT_LT(rel(dynamics::angular_momentum_body(kBody, s).norm(), L0.norm()), 1e-12);
  }
}

TEST_P(IntegratorContract, StepsWithoutAllocating) {
  auto m = make(kBody, 0.01, torque());
  State s = tumbling();
  m->step(s, 0.01);  // the first step may set up caches
  const long long before = allocation_count();
  for (int i = 0; i < 100; ++i)
    m->step(s, 0.01);
  m->advance(s, 0.01, 50);
  if (m->has_dense_output()) m->dense_output(s.time - 0.005);
  Mat3 lambda;
  m->last_multiplier(lambda);
  EXPECT_EQ(allocation_count(), before);
}

// kBody in its principal frame and in a body frame rotated by Q (J = Q diag(1, 2, 3) Qᵀ, the general code
// path): R_b = R_p Qᵀ, ω_b = Q ω_p at all times. Every method is equivariant under that change of frame, so
// the two runs agree to round-off amplified over 300 steps (and the eigen-decomposition's accuracy): 1e-12.
TEST_P(IntegratorContract, SameMotionInARotatedBodyFrame) {
  const Mat3 Q = so3::exp(Vec3(0.4, -0.7, 0.2));
  const RigidBody rotated = RigidBody::from_inertia(Q * Vec3(1.0, 2.0, 3.0).asDiagonal() * Q.transpose());
  const State p0 = tumbling();
  State b0 = p0;
  b0.R_space_body = p0.R_space_body * Q.transpose();
  b0.omega_body = Q * p0.omega_body;
  auto a = make(kBody, 0.01);
  auto b = make(rotated, 0.01);
  const State p = run_fixed(*a, p0, 3.0, 300);
  const State q = run_fixed(*b, b0, 3.0, 300);
  POINSOT_EXPECT_MATRIX_NEAR(q.R_space_body, Mat3(p.R_space_body * Q.transpose()), 1e-12);
  POINSOT_EXPECT_MATRIX_NEAR(q.omega_body, Vec3(Q * p.omega_body), 1e-12);
}

// Two fresh integrators on the same input give the same bits, with the method's own (adaptive) steps.
TEST_P(IntegratorContract, RepeatedRunsAreBitIdentical) {
  const auto run = [this] {
    IntegratorOptions o;
    o.dt = 0.02;
    auto m = info().make(kBody, torque(), o);
    State s = tumbling();
    double h = 0.02;
    for (int i = 0; i < 100; ++i)
      h = m->step(s, h).dt_next;
    return s;
  };
  const State a = run();
  const State b = run();
  EXPECT_EQ(a.time, b.time);
  EXPECT_TRUE(a.R_space_body == b.R_space_body);
  EXPECT_TRUE(a.omega_body == b.omega_body);
}

// advance(s, h, n) leaves bit for bit what n calls of step(s, h) leave, and shows its watcher the time and ω
// of every step; split into two advances (10 + 15 steps) and on the three code paths of a method such as
// rk4: the torque-free body in its principal frame, with a torque, and with a full inertia tensor.
TEST_P(IntegratorContract, AdvanceIsRepeatedSteps) {
  struct Recorder final : dynamics::StepWatcher {
    std::vector<std::pair<double, Vec3>> seen;
    long long expected_k = 0;
    void after_step(long long k, double time, const Vec3& omega_body) override {
      EXPECT_EQ(k, expected_k++);
      seen.emplace_back(time, omega_body);
    }
  };
  const Mat3 Q = so3::exp(Vec3(0.4, -0.7, 0.2));
  const RigidBody rotated = RigidBody::from_inertia(Q * Vec3(1.0, 2.0, 3.0).asDiagonal() * Q.transpose());
  const std::pair<const RigidBody*, std::shared_ptr<const TorqueModel>> cases[] = {
      {&kBody, TorqueModel::none()}, {&kBody, torque()}, {&rotated, TorqueModel::none()}};
  for (const auto& [body, tau] : cases) {
    auto a = make(*body, 0.01, tau);
    auto b = make(*body, 0.01, tau);
    State sa = tumbling();
    State sb = tumbling();
    std::vector<std::pair<double, Vec3>> stepped;
    for (int k = 0; k < 25; ++k) {
      a->step(sa, 0.01);
      stepped.emplace_back(sa.time, sa.omega_body);
    }
    Recorder rec;
    b->advance(sb, 0.01, 10, &rec);
    rec.expected_k = 0;
    b->advance(sb, 0.01, 15, &rec);
    EXPECT_EQ(sa.time, sb.time);
    EXPECT_TRUE(sa.R_space_body == sb.R_space_body);
    EXPECT_TRUE(sa.omega_body == sb.omega_body);
    ASSERT_EQ(rec.seen.size(), stepped.size());
    for (std::size_t k = 0; k < stepped.size(); ++k) {
      EXPECT_EQ(rec.seen[k].first, stepped[k].first) << "step " << k;
      EXPECT_TRUE(rec.seen[k].second == stepped[k].second) << "step " << k;
    }
    // A State not produced by the integrator (here: moved by hand) is taken as it is.
    sa.omega_body *= 0.5;
    sb.omega_body *= 0.5;
    a->step(sa, 0.01);
    b->advance(sb, 0.01, 1);
    EXPECT_TRUE(sa.R_space_body == sb.R_space_body);
    EXPECT_TRUE(sa.omega_body == sb.omega_body);
  }
  State s = tumbling();
  POINSOT_EXPECT_THROWS_MESSAGE(make(kBody, 0.01)->advance(s, 0.01, 0), InvalidInput, "n = 0 steps");
}

INSTANTIATE_TEST_SUITE_P(Registry, IntegratorContract, ::testing::ValuesIn(entries()),
                         [](const ::testing::TestParamInfo<const MethodInfo*>& p) {
                           return std::string(p.param->name);
                         });

}  // namespace
}  // namespace poinsot::test
