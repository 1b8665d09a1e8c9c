// scenario.hpp: the projection of initial velocities onto the joints (the files are read in the io layer,
// tests/io/scenario/test_multibody_scenario.cpp; the run driver is tests/multibody/test_run.cpp).
#include "poinsot/multibody/scenario.hpp"

#include "multibody_fixtures.hpp"
#include "poinsot/multibody/constraints.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot_test.hpp"

namespace poinsot::multibody {
namespace {

/// The kinetic-energy inner product of two sets of body velocities: Σ m vᵢ·uᵢ + ωᵢ·J ωᵢ'.
double energy_product(const System& s, const State& a, const State& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    const Body& body = s.bodies()[i];
    sum += body.mass * a.bodies[i].v_space.dot(b.bodies[i].v_space) +
           a.bodies[i].omega_body.dot(body.inertia * b.bodies[i].omega_body);
  }
  return sum;
}

State with_velocities(State st, int seed) {
  for (std::size_t i = 0; i < st.bodies.size(); ++i) {
    const double k = static_cast<double>(seed) + static_cast<double>(i);
    st.bodies[i].v_space = Vec3(std::sin(k), std::cos(2 * k), 0.5 * std::sin(3 * k + 1));
    st.bodies[i].omega_body = Vec3(std::cos(k + 2), 0.3 * std::sin(5 * k), std::cos(7 * k));
  }
  return st;
}

State difference(const State& a, const State& b) {
  State d = a;
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    d.bodies[i].v_space -= b.bodies[i].v_space;
    d.bodies[i].omega_body -= b.bodies[i].omega_body;
  }
  return d;
}

TEST(ProjectVelocities, IsTheKineticEnergyOrthogonalProjectionOntoTheJoints) {
  // Oracle: the least-kinetic-energy-change projection P onto {G v = 0} is characterised by (1) P v is
  // admissible, (2) v − P v is M-orthogonal to every admissible velocity, (3) P P v = P v.
  const int n = 4;
  const System s = test::rod_chain(n);
  const State v0 = with_velocities(test::rod_chain_state(n), 1);
  State p = v0;
  project_velocities(s, p);
  EXPECT_LT(constraint_violation(s, p).joint_velocity, 1e-14);
  State u = with_velocities(test::rod_chain_state(n), 7);  // another admissible velocity
  project_velocities(s, u);
  const double scale = std::sqrt(energy_product(s, v0, v0) * energy_product(s, u, u));
  // One KKT solve: round-off of order 1e-16 of the energy scale, times the condition of the chain.
  EXPECT_LT(std::abs(energy_product(s, difference(v0, p), u)), 1e-13 * scale);
  State pp = p;
  project_velocities(s, pp);
  for (int i = 0; i < n; ++i) {
    const auto iu = static_cast<std::size_t>(i);
    EXPECT_LT((pp.bodies[iu].v_space - p.bodies[iu].v_space).norm(), 1e-13);
    EXPECT_LT((pp.bodies[iu].omega_body - p.bodies[iu].omega_body).norm(), 1e-13);
  }
  // The projection loses kinetic energy, never gains it (Pythagoras in the energy metric).
  EXPECT_LE(energy_product(s, p, p), energy_product(s, v0, v0));
}

TEST(ProjectVelocities, LeavesAFreeSystemAlone) {
  System s;
  s.add_body_from_inertia("a", 2.0, Vec3(1, 2, 3).asDiagonal());
  State st = with_velocities(test::rod_chain_state(1), 3);
  const State before = st;
  project_velocities(s, st);
  EXPECT_EQ(st.bodies[0].v_space, before.bodies[0].v_space);
  EXPECT_EQ(st.bodies[0].omega_body, before.bodies[0].omega_body);
}

}  // namespace
}  // namespace poinsot::multibody
