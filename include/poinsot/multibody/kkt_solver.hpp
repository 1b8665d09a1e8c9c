#pragma once
/// @file kkt_solver.hpp
/// The linear saddle-point (KKT) system of every Newton step of the multibody integrator,
///
///     [ M  Gᵀ ] [ x ]   [ r ]
///     [ G  0  ] [ y ] = [ s ],      M = blockdiag(m_i I₃, J_i)  (per body, in (v_space, ω_body)),
///
/// with G the joint Jacobians (constraints.hpp). M is the constant mass matrix of the 12 coordinates
/// restricted to the tangent space of RᵀR = I, where it is blockdiag(m I, J) with J = tr(K) I − K positive
/// definite even when K is singular (docs/multibody_theory.md §3).
///
/// Tree-structured systems (the graph of bodies and joints has no cycle, and each connected part has at most
/// one joint to the world) are solved in O(N) by Baraff's block LDLᵀ factorisation in tree order (D. Baraff
/// 1996, "Linear-time dynamics using Lagrange multipliers", SIGGRAPH, §5–7): the nodes are the bodies and the
/// joints, ordered children first, so the factorisation has no fill-in; body pivots are positive definite,
/// joint pivots negative definite, each factored by Cholesky (≤ 6×6). Other systems (closed loops, several
/// joints to the world in one part) are assembled into a sparse matrix and solved by Eigen's SparseLU (COLAMD
/// ordering). The workspace is allocated once, in the constructor; factor() and solve() allocate nothing on
/// trees.
///
/// Ball-joint chains (every joint a ball joint, every body with at most two joints: ropes, chains, pendulums,
/// tops) take a faster route to the same solution: the bodies are eliminated first (M is block diagonal and
/// constant), leaving the Schur complement G M⁻¹ Gᵀ on the joints, which is block tridiagonal with 3 × 3
/// blocks along each chain, factored without fill (src/multibody/ball_chain_solver.hpp). On trees with
/// branching bodies that order would fill in (a body with d joints couples them all), so Baraff's order is
/// kept there.

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "poinsot/multibody/constraints.hpp"
#include "poinsot/multibody/model.hpp"

namespace poinsot::multibody {

namespace detail {
class BallChainSolver;
}

/// How the KKT system is solved: chosen from the system's structure (automatic), or forced (tests compare
/// the methods with each other; a forced method the structure does not allow throws InvalidInput).
enum class KktMethod { automatic, ball_chain, tree, sparse_lu };
/// "automatic", "ball_chain", "tree" or "sparse_lu" (the names used by the CLI's JSON and by Python).
const char* kkt_method_name(KktMethod method);
/// A line for reports, e.g. "tree-order block LDLT (Baraff), O(N)".
const char* kkt_method_description(KktMethod method);

class KktSolver {
 public:
  explicit KktSolver(const System& system, KktMethod method = KktMethod::automatic);
  ~KktSolver();
  KktSolver(KktSolver&&) noexcept;
  KktSolver& operator=(KktSolver&&) noexcept;

  /// True when an O(N) factorisation is used (ball chain or tree), false for the sparse LU fallback.
  bool is_tree() const { return method_ != KktMethod::sparse_lu; }
  /// The method in use (never automatic).
  KktMethod method() const { return method_; }
  /// Offset of joint j's rows in the stacked constraint vector.
  int joint_offset(int j) const { return joint_offset_[static_cast<std::size_t>(j)]; }
  int constraint_rows() const { return rows_; }

  /// Factors the matrix for the Jacobians G_a[j], G_b[j] of every joint j. Throws ComputationFailed when a
  /// pivot is singular (redundant or degenerate constraints).
  void factor(const std::vector<JointJacobian>& G_a, const std::vector<JointJacobian>& G_b);
  /// Same for the Jacobians at the positions of `bodies` (constraints.hpp joint_jacobians), computed here:
  /// in place for ball chains, into storage allocated by the constructor otherwise (nothing is allocated).
  void factor_at(const std::vector<BodyState>& bodies);
  /// Solves in place: on entry body[i] = r_i and joint = s (stacked rows), on exit x and y.
  void solve(std::vector<Vec6>& body, Eigen::VectorXd& joint);

 private:
  // Blocks are stored as fixed 6×6 matrices and used through fixed-size corners (unrolled by Eigen): bodies
  // and hinge/weld joints have size 6 (a joint with c < 6 rows gets 6 − c decoupled padding rows with pivot
  // −1 and right-hand side 0, whose solution is 0), ball joints size 3.
  using Mat6 = Eigen::Matrix<double, 6, 6>;
  struct Node {
    int dim = 0;
    int size = 6;     // 6, or 3 for a ball joint (no padding)
    int parent = -1;  // node index, −1 for a root
    bool is_body = true;
    bool parent_side_a = true;  // which side of the joint the body is (body under joint or joint under body)
    Mat6 D;                     // pivot block
    Mat6 H_up;                  // block of H in (parent row, this column)
    Mat6 Lt;                    // D⁻¹ H_upᵀ
    Mat6 D_inv;                 // D⁻¹ (Cholesky of D for bodies, of −D for joints)
  };
  struct Sparse;

  void build_tree(const System& system);

  const System* system_;
  bool tree_ = true;
  KktMethod method_ = KktMethod::tree;
  std::unique_ptr<detail::BallChainSolver> chain_;
  int rows_ = 0;
  std::vector<int> joint_offset_;
  std::vector<Node> nodes_;  // bodies 0..N−1, then joints
  std::vector<int> order_;   // elimination order, children before parents
  std::vector<Vec6> work_;
  std::vector<JointJacobian> G_a_, G_b_;  // factor_at's Jacobians (not for ball chains)
  std::unique_ptr<Sparse> sparse_;
};

}  // namespace poinsot::multibody
