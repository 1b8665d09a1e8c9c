// The tree-order factorisation and the sparse fallback against a dense LU of the assembled KKT matrix.
#include "poinsot/multibody/kkt_solver.hpp"

#include <cmath>

#include <Eigen/Dense>

#include "poinsot/core/error.hpp"
#include "poinsot/core/linear_solvers.hpp"

#include "multibody_fixtures.hpp"
#include "poinsot_test.hpp"

namespace poinsot::multibody {
namespace {

using poinsot::test::random_rotation;
using poinsot::test::random_vector;

// Random poses (the KKT matrix needs no assembled joints), Jacobians, and the dense matrix [M Gᵀ; G 0].
struct Problem {
  std::vector<JointJacobian> Ga, Gb;
  Eigen::MatrixXd H;
};

Problem make_problem(const System& s, const KktSolver& solver) {
  State st;
  st.bodies.resize(static_cast<std::size_t>(s.body_count()));
  for (BodyState& b : st.bodies) {
    b.x_space = random_vector();
    b.R_space_body = random_rotation();
  }
  Problem p;
  const int nb = s.body_count();
  const int n = 6 * nb + s.constraint_rows();
  p.H = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < nb; ++i) {
    const Body& b = s.bodies()[static_cast<std::size_t>(i)];
    p.H.block<3, 3>(6 * i, 6 * i) = b.mass * Mat3::Identity();
    p.H.block<3, 3>(6 * i + 3, 6 * i + 3) = b.inertia;
  }
  p.Ga.resize(static_cast<std::size_t>(s.joint_count()));
  p.Gb.resize(static_cast<std::size_t>(s.joint_count()));
  for (int j = 0; j < s.joint_count(); ++j) {
    const Joint& joint = s.joints()[static_cast<std::size_t>(j)];
    const BodyState& b =
        joint.body_b == kWorld ? world_body_state() : st.bodies[static_cast<std::size_t>(joint.body_b)];
    joint_jacobians(joint, st.bodies[static_cast<std::size_t>(joint.body_a)], b,
                    p.Ga[static_cast<std::size_t>(j)], p.Gb[static_cast<std::size_t>(j)]);
    const int r0 = 6 * nb + solver.joint_offset(j);
    const int rows = joint.rows();
    p.H.block(r0, 6 * joint.body_a, rows, 6) = p.Ga[static_cast<std::size_t>(j)];
    p.H.block(6 * joint.body_a, r0, 6, rows) = p.Ga[static_cast<std::size_t>(j)].transpose();
    if (joint.body_b != kWorld) {
      p.H.block(r0, 6 * joint.body_b, rows, 6) = p.Gb[static_cast<std::size_t>(j)];
      p.H.block(6 * joint.body_b, r0, 6, rows) = p.Gb[static_cast<std::size_t>(j)].transpose();
    }
  }
  return p;
}

// Solves with the KktSolver and with a dense LU; returns the max difference relative to the solution's size.
double solve_both(const System& s, KktMethod expected, KktMethod forced = KktMethod::automatic) {
  KktSolver solver(s, forced);
  EXPECT_EQ(solver.method(), expected);
  EXPECT_EQ(solver.is_tree(), expected != KktMethod::sparse_lu);
  const Problem p = make_problem(s, solver);
  solver.factor(p.Ga, p.Gb);
  const int nb = s.body_count();
  Eigen::VectorXd rhs = Eigen::VectorXd::Random(p.H.rows());
  std::vector<Vec6> body(static_cast<std::size_t>(nb));
  for (int i = 0; i < nb; ++i)
    body[static_cast<std::size_t>(i)] = rhs.segment<6>(6 * i);
  Eigen::VectorXd joint = rhs.tail(s.constraint_rows());
  solver.solve(body, joint);
  const Eigen::VectorXd dense = DenseLu(p.H).solve(rhs);
  double err = 0.0;
  for (int i = 0; i < nb; ++i) {
    err = std::max(err, (body[static_cast<std::size_t>(i)] - dense.segment<6>(6 * i)).cwiseAbs().maxCoeff());
  }
  err = std::max(err, (joint - dense.tail(s.constraint_rows())).cwiseAbs().maxCoeff());
  return err / dense.cwiseAbs().maxCoeff();
}

// Round-off of a well-conditioned (random poses, unit masses) solve: a few hundred ulps.
constexpr double kTol = 1e-11;

TEST(KktSolver, ChainMatchesDenseLuByEveryMethod) {
  const System s = test::rod_chain(12, 1.0, 1.0, 0.1);
  EXPECT_LT(solve_both(s, KktMethod::ball_chain), kTol);
  EXPECT_LT(solve_both(s, KktMethod::tree, KktMethod::tree), kTol);
  EXPECT_LT(solve_both(s, KktMethod::sparse_lu, KktMethod::sparse_lu), kTol);
}

TEST(KktSolver, BallChainsOfEveryShapeMatchDenseLu) {
  // Sides in both orders along the path, masses and lever arms over three decades, a floating chain (no world
  // joint), a single free body and a chain hung by its middle link's end: every path the chain solver walks.
  System s;
  for (int i = 0; i < 6; ++i) {
    const double m = std::pow(10.0, i % 3 - 1);
    s.add_body_from_inertia(test::indexed("c", i), m, m * Vec3(0.15 + 0.01 * (i + 1), 0.2, 0.3).asDiagonal());
  }
  s.add_ball("w", 2, Vec3(0.1, 0, 0), kWorld, Vec3(1, 2, 3));
  s.add_ball("a", 2, Vec3(-0.3, 0.1, 0), 1, Vec3(0.2, 0, 0.05));  // parent 2 on side a
  s.add_ball("b", 0, Vec3(0.5, 0, 0), 1, Vec3(-0.5, 0, 0));
  s.add_ball("c", 3, Vec3(0, 0.4, 0), 2, Vec3(0, 0, 0.2));  // 2 now has three joints: not a chain
  {
    KktSolver solver(s);
    EXPECT_EQ(solver.method(), KktMethod::tree);
    EXPECT_THROW(KktSolver(s, KktMethod::ball_chain), InvalidInput);
  }
  System chains;
  for (int i = 0; i < 7; ++i) {
    const double m = std::pow(10.0, i % 3 - 1);
    chains.add_body_from_inertia(test::indexed("c", i), m,
                                 m * Vec3(0.15 + 0.01 * (i + 1), 0.2, 0.3).asDiagonal());
  }
  chains.add_ball("b", 0, Vec3(0.5, 0, 0), 1, Vec3(-0.5, 0, 0));  // floating chain 0-1-2
  chains.add_ball("a", 2, Vec3(-0.3, 0.1, 0), 1, Vec3(0.2, 0, 0.05));
  chains.add_ball("w", 4, Vec3(0.1, 0, 0), kWorld, Vec3(1, 2, 3));  // 3 free; chain world-4-5-6
  chains.add_ball("d", 4, Vec3(-0.1, 0.3, 0), 5, Vec3(0, 0, 0.2));
  chains.add_ball("e", 6, Vec3(0.2, 0, 0.1), 5, Vec3(0, -0.4, 0));
  EXPECT_LT(solve_both(chains, KktMethod::ball_chain), kTol);
  EXPECT_LT(solve_both(chains, KktMethod::tree, KktMethod::tree), kTol);
}

TEST(KktSolver, BranchedTreeWithHingesAndWeldsMatchesDenseLu) {
  System s;
  for (int i = 0; i < 7; ++i)
    s.add_body_from_inertia(test::indexed("b", i), 1.0 + i, Vec3(1, 2, 2.5).asDiagonal());
  s.add_hinge("h0", 0, Vec3(0.1, 0, 0), Vec3(0, 0, 1), kWorld, Vec3::Zero(), Vec3(0, 1, 1));
  s.add_ball("j1", 1, Vec3(0.2, 0.1, 0), 0, Vec3(-0.3, 0, 0.1));
  s.add_hinge("j2", 2, Vec3(0.2, 0, 0), Vec3(1, 1, 0), 0, Vec3(0.3, 0.2, 0), Vec3(0, 1, 0));
  s.add_weld("j3", 3, Vec3(0, 0.2, 0), 1, Vec3(0, -0.2, 0), random_rotation());
  s.add_ball("j4", 0, Vec3(0, 0.2, 0.1), 4, Vec3(0, -0.2, 0));  // the parent as side a
  s.add_hinge("j5", 5, Vec3(0, 0.1, 0), Vec3(1, 0, 0), 4, Vec3(0.1, 0, 0), Vec3(0, 0, 1));
  s.add_ball("j6", 6, Vec3(0.1, 0, 0.1), 2, Vec3(0, 0, 0.3));
  EXPECT_LT(solve_both(s, KktMethod::tree), kTol);
  EXPECT_THROW(KktSolver(s, KktMethod::ball_chain), InvalidInput);
}

TEST(KktSolver, FreeBodiesAndSeparateTreesMatchDenseLu) {
  System s = test::rod_chain(3, 1.0, 1.0, 0.1);
  s.add_body_from_inertia("free", 2.0, Vec3(1, 1, 1).asDiagonal());
  const int a = s.add_body_from_inertia("a", 1.0, Vec3(1, 2, 2).asDiagonal());
  const int b = s.add_body_from_inertia("b", 1.0, Vec3(1, 2, 2).asDiagonal());
  s.add_ball("ab", a, Vec3(0.5, 0, 0), b, Vec3(-0.5, 0, 0));
  EXPECT_LT(solve_both(s, KktMethod::ball_chain), kTol);
  EXPECT_LT(solve_both(s, KktMethod::tree, KktMethod::tree), kTol);
}

TEST(KktSolver, ClosedLoopUsesSparseLuAndMatchesDenseLu) {
  // Four-bar: chain of three hinged to the world at both ends (two world joints in one part = a loop).
  System s;
  for (int i = 0; i < 3; ++i)
    s.add_body_from_inertia(test::indexed("b", i), 1.0, Vec3(0.1, 1, 1).asDiagonal());
  s.add_ball("w0", 0, Vec3(-0.5, 0, 0), kWorld, Vec3::Zero());
  s.add_ball("j1", 1, Vec3(-0.5, 0, 0), 0, Vec3(0.5, 0, 0));
  s.add_ball("j2", 2, Vec3(-0.5, 0, 0), 1, Vec3(0.5, 0, 0));
  s.add_hinge("w3", 2, Vec3(0.5, 0, 0), Vec3(0, 0, 1), kWorld, Vec3(2.5, 0, 0), Vec3(0, 0, 1));
  EXPECT_LT(solve_both(s, KktMethod::sparse_lu), kTol);
  EXPECT_THROW(KktSolver(s, KktMethod::tree), InvalidInput);
  // A ring of four bodies.
  System ring;
  for (int i = 0; i < 4; ++i)
    ring.add_body_from_inertia(test::indexed("r", i), 1.0, Vec3(1, 1, 1).asDiagonal());
  for (int i = 0; i < 4; ++i)
    ring.add_ball(test::indexed("j", i), i, Vec3(0.5, 0, 0), (i + 1) % 4, Vec3(-0.5, 0, 0));
  EXPECT_LT(solve_both(ring, KktMethod::sparse_lu), kTol);
}

TEST(KktSolver, RedundantConstraintsAreReported) {
  System s = test::rod_chain(2, 1.0, 1.0, 0.1);
  s.add_ball("again", 1, Vec3(-0.5, 0, 0), 0, Vec3(0.5, 0, 0));  // the same joint twice: a loop, singular
  KktSolver solver(s);
  EXPECT_FALSE(solver.is_tree());
  const Problem p = make_problem(s, solver);
  EXPECT_THROW(solver.factor(p.Ga, p.Gb), ComputationFailed);
}

TEST(KktSolver, UniversalAndPrismaticJointsTakeTheTreeAndSparsePaths) {
  // 4 and 5 rows: padded 6 × 6 joint pivots in the tree order, any rows for SparseLU; never the ball chain.
  System s;
  for (int i = 0; i < 4; ++i)
    s.add_body_from_inertia(test::indexed("c", i), 1.0 + i, Vec3(0.15 + 0.01 * i, 0.2, 0.3).asDiagonal());
  s.add_universal("u", 0, Vec3(0.1, 0, 0), Vec3(1, 0, 0), kWorld, Vec3(1, 2, 3), Vec3(0, 1, 0));
  s.add_prismatic("p", 1, Vec3(-0.3, 0.1, 0), Vec3(1, 1, 0), 0, Vec3(0.2, 0, 0.05), random_rotation());
  s.add_universal("u2", 2, Vec3(0, 0.4, 0), Vec3(0, 0, 1), 1, Vec3(0, 0, 0.2), Vec3(1, 0, 0));
  s.add_prismatic("p2", 3, Vec3(0, 0.1, 0.2), Vec3(0, 0, 1), 2, Vec3(0.3, 0, 0), random_rotation());
  EXPECT_THROW(KktSolver(s, KktMethod::ball_chain), InvalidInput);
  EXPECT_LT(solve_both(s, KktMethod::tree), kTol);
  EXPECT_LT(solve_both(s, KktMethod::sparse_lu, KktMethod::sparse_lu), kTol);
}

}  // namespace
}  // namespace poinsot::multibody
