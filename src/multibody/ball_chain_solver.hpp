#pragma once
// Private to the multibody layer (used by kkt_solver.cpp).
//
// The KKT system [M Gᵀ; G 0][x; y] = [r; s] of a system whose joints are all ball joints and whose bodies
// have at most two joints each (chains, ropes, pendulums: the body–joint graph is a set of paths), solved
// through the Schur complement on the joints:
//
//     S y = G M⁻¹ r − s,   S = G M⁻¹ Gᵀ,   x = M⁻¹ (r − Gᵀ y),
//
// with M = blockdiag(m I₃, J) constant and inverted once. Numbering the joints along each path makes S block
// tridiagonal with 3 × 3 blocks: a ball joint's rows are G = ±[I, −R j(A)], so
// S_kk = Σ_sides (1/m) I + R j(A) J⁻¹ j(A)ᵀ Rᵀ and S_{k,k+1} couples the two joints of the body they share.
// Its block LDLᵀ factorisation (no fill) costs one 3 × 3 inversion (adjugate) per joint, against a 6 × 6 and
// a 3 × 3 per link for Baraff's ordering of the same tree (the elimination order differs, the solution is the
// same).

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "poinsot/multibody/constraints.hpp"
#include "poinsot/multibody/model.hpp"

namespace poinsot::multibody::detail {

class BallChainSolver {
 public:
  /// The solver for `system`, or null when some joint is not a ball joint or some body has more than two
  /// joints. The system must be a forest (no closed loop, at most one joint to the world per part).
  static std::unique_ptr<BallChainSolver> make(const System& system);

  /// Factors S for the ball-joint Jacobians G_a[j], G_b[j] (3 rows each). Throws ComputationFailed when a
  /// pivot is singular.
  void factor(const std::vector<JointJacobian>& G_a, const std::vector<JointJacobian>& G_b);
  /// Same with the Jacobians of the positions `q` computed here (no JointJacobian storage: the ω-blocks
  /// ∓R j(X) are all a ball chain needs).
  void factor_at(const std::vector<BodyState>& q);
  /// Solves in place: on entry body[i] = r_i and joint = s (3 rows per joint in joint order), on exit x, y.
  void solve(std::vector<Vec6>& body, Eigen::VectorXd& joint);

 private:
  explicit BallChainSolver(const System& system) : system_(&system) {}
  // The factorisation with Gω of joint j's side s (0: a, 1: b) given by omega_block(j, s).
  template <class OmegaBlock>
  void factor_with(OmegaBlock omega_block);

  // One side of a joint in path order: the body, the sign of its translation block (+1 side a, −1 side b)
  // and Gω = the ω-block of G (3 × 3), with X = Gω J⁻¹ cached by factor().
  struct Side {
    int body = kWorld;
    double sign = 1.0;
    Mat3 G_omega = Mat3::Zero();
    Mat3 X = Mat3::Zero();
  };
  struct Link {
    int joint = 0;
    Side sides[2];
    int shared_side = -1;  // which side is the body shared with the previous joint of the path (−1: first)
    int previous_side = -1;     // which side of the previous joint that body is
    Mat3 E = Mat3::Zero();      // S_{p−1,p}
    Mat3 Lt = Mat3::Zero();     // D_{p−1}⁻¹ E_p
    Mat3 D_inv = Mat3::Zero();  // D_p⁻¹
  };

  const System* system_;
  std::vector<Link> links_;           // all paths, one after the other
  std::vector<Vec3> y_;               // per link
  std::vector<Vec6> t_;               // per body: M⁻¹ r
  std::vector<double> inverse_mass_;  // per body, 1/kg
};

}  // namespace poinsot::multibody::detail
