// Block LDLᵀ in tree order (Baraff 1996) with a sparse LU fallback for loops (kkt_solver.hpp).
#include "poinsot/multibody/kkt_solver.hpp"

#include <cmath>
#include <deque>

#include <fmt/format.h>
#include <Eigen/SparseCore>

#include "ball_chain_solver.hpp"
#include "poinsot/core/assert.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/linear_solvers.hpp"

namespace poinsot::multibody {
namespace {

// Inverse of the leading N×N block of a symmetric positive definite matrix by Cholesky, A = L Lᵀ,
// A⁻¹ = L⁻ᵀ L⁻¹ (fixed-size loops that the compiler unrolls). False when a pivot falls below 1e-13 of its
// diagonal entry (A singular or indefinite to working accuracy).
template <int N>
bool spd_inverse(const Eigen::Matrix<double, 6, 6>& A, Eigen::Matrix<double, 6, 6>& inv) {
  double L[N][N] = {};
  for (int j = 0; j < N; ++j) {
    double d = A(j, j);
    for (int k = 0; k < j; ++k)
      d -= L[j][k] * L[j][k];
    if (!(d > 1e-13 * std::abs(A(j, j)))) return false;
    L[j][j] = std::sqrt(d);
    for (int i = j + 1; i < N; ++i) {
      double v = A(i, j);
      for (int k = 0; k < j; ++k)
        v -= L[i][k] * L[j][k];
      L[i][j] = v / L[j][j];
    }
  }
  double M[N][N] = {};  // L⁻¹, lower triangular
  for (int i = 0; i < N; ++i) {
    M[i][i] = 1.0 / L[i][i];
    for (int j = 0; j < i; ++j) {
      double v = 0.0;
      for (int k = j; k < i; ++k)
        v += L[i][k] * M[k][j];
      M[i][j] = -v * M[i][i];
    }
  }
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j <= i; ++j) {
      double v = 0.0;
      for (int k = i; k < N; ++k)
        v += M[k][i] * M[k][j];
      inv(i, j) = v;
      inv(j, i) = v;
    }
  }
  return true;
}

// One elimination step of a node of size Ni under a parent of size Np (sizes 6, or 3 for ball joints):
// Lt = D⁻¹ H_upᵀ, D_p −= H_up Lt.
template <int Ni, int Np>
void eliminate(const Eigen::Matrix<double, 6, 6>& D_inv, const Eigen::Matrix<double, 6, 6>& H_up,
               Eigen::Matrix<double, 6, 6>& Lt, Eigen::Matrix<double, 6, 6>& D_parent) {
  Lt.topLeftCorner<Ni, Np>().noalias() =
      D_inv.topLeftCorner<Ni, Ni>() * H_up.topLeftCorner<Np, Ni>().transpose();
  D_parent.topLeftCorner<Np, Np>().noalias() -= H_up.topLeftCorner<Np, Ni>() * Lt.topLeftCorner<Ni, Np>();
}

}  // namespace

struct KktSolver::Sparse {
  Eigen::SparseMatrix<double> H;
  std::vector<Eigen::Triplet<double>> triplets;
  SparseLu lu;
  Eigen::VectorXd rhs;
  bool analysed = false;
};

const char* kkt_method_name(KktMethod method) {
  switch (method) {
    case KktMethod::ball_chain:
      return "ball_chain";
    case KktMethod::tree:
      return "tree";
    case KktMethod::sparse_lu:
      return "sparse_lu";
    default:
      return "automatic";
  }
}

const char* kkt_method_description(KktMethod method) {
  switch (method) {
    case KktMethod::ball_chain:
      return "ball-chain Schur complement, block tridiagonal, O(N)";
    case KktMethod::tree:
      return "tree-order block LDLT (Baraff), O(N)";
    case KktMethod::sparse_lu:
      return "sparse LU (closed loops)";
    default:
      return "chosen from the system's structure";
  }
}

KktSolver::~KktSolver() = default;
KktSolver::KktSolver(KktSolver&&) noexcept = default;
KktSolver& KktSolver::operator=(KktSolver&&) noexcept = default;

KktSolver::KktSolver(const System& system, KktMethod method) : system_(&system) {
  const auto nj = static_cast<std::size_t>(system.joint_count());
  joint_offset_.resize(nj);
  for (std::size_t j = 0; j < nj; ++j) {
    joint_offset_[j] = rows_;
    rows_ += system.joints()[j].rows();
  }
  build_tree(system);
  if (tree_ && (method == KktMethod::automatic || method == KktMethod::ball_chain)) {
    chain_ = detail::BallChainSolver::make(system);
  }
  if (method == KktMethod::ball_chain && !chain_) {
    throw InvalidInput(
        "multibody: the ball-chain KKT solver needs only ball joints, at most two per body, and no loop");
  }
  if (method == KktMethod::tree && !tree_) {
    throw InvalidInput("multibody: the tree KKT solver needs a system without closed loops");
  }
  if (method == KktMethod::sparse_lu) tree_ = false;
  method_ = chain_ ? KktMethod::ball_chain : tree_ ? KktMethod::tree : KktMethod::sparse_lu;
  if (!tree_) {
    sparse_ = std::make_unique<Sparse>();
    const int n = 6 * system.body_count() + rows_;
    sparse_->H.resize(n, n);
    sparse_->rhs.resize(n);
  }
  if (!chain_) {
    G_a_.resize(nj);
    G_b_.resize(nj);
  }
}

void KktSolver::factor_at(const std::vector<BodyState>& bodies) {
  POINSOT_ASSERT(bodies.size() == static_cast<std::size_t>(system_->body_count()),
                 "one state per body of the system");
  if (chain_) {
    chain_->factor_at(bodies);
    return;
  }
  const auto& joints = system_->joints();
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const Joint& joint = joints[j];
    joint_jacobians(joint, side_state(bodies, joint.body_a), side_state(bodies, joint.body_b), G_a_[j],
                    G_b_[j]);
  }
  factor(G_a_, G_b_);
}

void KktSolver::build_tree(const System& system) {
  const int nb = system.body_count();
  const int nj = system.joint_count();
  const int n = nb + nj;
  nodes_.clear();
  nodes_.resize(static_cast<std::size_t>(n));
  std::vector<std::vector<int>> adjacent(static_cast<std::size_t>(n));
  for (int j = 0; j < nj; ++j) {
    const Joint& joint = system.joints()[static_cast<std::size_t>(j)];
    const int node = nb + j;
    adjacent[static_cast<std::size_t>(node)].push_back(joint.body_a);
    adjacent[static_cast<std::size_t>(joint.body_a)].push_back(node);
    if (joint.body_b != kWorld) {
      adjacent[static_cast<std::size_t>(node)].push_back(joint.body_b);
      adjacent[static_cast<std::size_t>(joint.body_b)].push_back(node);
    }
  }
  for (int i = 0; i < n; ++i) {
    Node& node = nodes_[static_cast<std::size_t>(i)];
    node.is_body = i < nb;
    node.dim = node.is_body ? 6 : system.joints()[static_cast<std::size_t>(i - nb)].rows();
    node.size = node.dim == 3 ? 3 : 6;
    node.D.setZero();
    node.D_inv.setZero();
    node.H_up.setZero();
    node.Lt.setZero();
  }
  // Connected parts: count nodes, edges and joints to the world; a tree part has edges = nodes − 1.
  std::vector<int> part(static_cast<std::size_t>(n), -1);
  std::vector<int> roots;
  for (int start = 0; start < n; ++start) {
    if (part[static_cast<std::size_t>(start)] >= 0) continue;
    const int id = static_cast<int>(roots.size());
    std::vector<int> members{start};
    part[static_cast<std::size_t>(start)] = id;
    std::size_t edges2 = 0;
    for (std::size_t k = 0; k < members.size(); ++k) {
      for (int nb_node : adjacent[static_cast<std::size_t>(members[k])]) {
        ++edges2;
        if (part[static_cast<std::size_t>(nb_node)] < 0) {
          part[static_cast<std::size_t>(nb_node)] = id;
          members.push_back(nb_node);
        }
      }
    }
    int world_joints = 0;
    int root = start;
    for (int m : members) {
      if (m >= nb && system.joints()[static_cast<std::size_t>(m - nb)].body_b == kWorld) {
        ++world_joints;
        root = m;  // a joint to the world has one neighbour: it must be a root, never a leaf pivot
      }
    }
    if (edges2 / 2 + 1 != members.size() || world_joints > 1) tree_ = false;
    roots.push_back(root);
  }
  if (!tree_) return;
  // Breadth-first from each root; the reverse of the visiting order has every child before its parent.
  std::vector<char> seen(static_cast<std::size_t>(n), 0);
  std::vector<int> visit;
  visit.reserve(static_cast<std::size_t>(n));
  for (int root : roots) {
    std::deque<int> queue{root};
    seen[static_cast<std::size_t>(root)] = 1;
    while (!queue.empty()) {
      const int i = queue.front();
      queue.pop_front();
      visit.push_back(i);
      for (int c : adjacent[static_cast<std::size_t>(i)]) {
        if (seen[static_cast<std::size_t>(c)]) continue;
        seen[static_cast<std::size_t>(c)] = 1;
        nodes_[static_cast<std::size_t>(c)].parent = i;
        queue.push_back(c);
      }
    }
  }
  order_.assign(visit.rbegin(), visit.rend());
  for (int i = 0; i < n; ++i) {
    Node& node = nodes_[static_cast<std::size_t>(i)];
    if (node.parent < 0) continue;
    const int joint_node = node.is_body ? node.parent : i;
    const int body_node = node.is_body ? i : node.parent;
    node.parent_side_a = system.joints()[static_cast<std::size_t>(joint_node - nb)].body_a == body_node;
    node.H_up.setZero();
    node.Lt.setZero();
  }
  work_.assign(static_cast<std::size_t>(n), Vec6::Zero());
}

void KktSolver::factor(const std::vector<JointJacobian>& G_a, const std::vector<JointJacobian>& G_b) {
  if (chain_) {
    chain_->factor(G_a, G_b);
    return;
  }
  const System& system = *system_;
  const int nb = system.body_count();
  if (!tree_) {
    Sparse& sp = *sparse_;
    sp.triplets.clear();
    for (int i = 0; i < nb; ++i) {
      const Body& body = system.bodies()[static_cast<std::size_t>(i)];
      for (int r = 0; r < 3; ++r)
        sp.triplets.emplace_back(6 * i + r, 6 * i + r, body.mass);
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c)
          sp.triplets.emplace_back(6 * i + 3 + r, 6 * i + 3 + c, body.inertia(r, c));
      }
    }
    for (int j = 0; j < system.joint_count(); ++j) {
      const Joint& joint = system.joints()[static_cast<std::size_t>(j)];
      const int row0 = 6 * nb + joint_offset(j);
      for (int side = 0; side < 2; ++side) {
        const int b = side == 0 ? joint.body_a : joint.body_b;
        if (b == kWorld) continue;
        const JointJacobian& G =
            side == 0 ? G_a[static_cast<std::size_t>(j)] : G_b[static_cast<std::size_t>(j)];
        for (int r = 0; r < joint.rows(); ++r) {
          for (int c = 0; c < 6; ++c) {
            if (G(r, c) == 0.0) continue;
            sp.triplets.emplace_back(row0 + r, 6 * b + c, G(r, c));
            sp.triplets.emplace_back(6 * b + c, row0 + r, G(r, c));
          }
        }
      }
    }
    // Structural zeros are dropped above, so the pattern can change between calls: analyse each time it does.
    const auto nnz_before = sp.H.nonZeros();
    sp.H.setFromTriplets(sp.triplets.begin(), sp.triplets.end());
    if (!sp.analysed || sp.H.nonZeros() != nnz_before) {
      sp.lu.analyse_pattern(sp.H);
      sp.analysed = true;
    }
    if (!sp.lu.factorise(sp.H)) {
      throw ComputationFailed(
          "multibody: the constraint matrix is singular (redundant or degenerate joints)");
    }
    return;
  }
  for (int i = 0; i < nb; ++i) {
    Node& node = nodes_[static_cast<std::size_t>(i)];
    const Body& body = system.bodies()[static_cast<std::size_t>(i)];
    node.D.setZero();
    node.D.topLeftCorner<3, 3>().diagonal().setConstant(body.mass);
    node.D.bottomRightCorner<3, 3>() = body.inertia;
  }
  for (std::size_t i = static_cast<std::size_t>(nb); i < nodes_.size(); ++i) {
    Node& node = nodes_[i];
    node.D.setZero();
    for (int k = node.dim; k < node.size; ++k)
      node.D(k, k) = -1.0;  // padding rows
  }
  for (int i : order_) {
    Node& node = nodes_[static_cast<std::size_t>(i)];
    bool ok = false;
    if (node.is_body) {
      ok = spd_inverse<6>(node.D, node.D_inv);
    } else {
      ok = node.size == 3 ? spd_inverse<3>(-node.D, node.D_inv) : spd_inverse<6>(-node.D, node.D_inv);
      node.D_inv = -node.D_inv;
    }
    if (!ok) {
      const std::string what =
          node.is_body ? fmt::format("body '{}'", system.bodies()[static_cast<std::size_t>(i)].name)
                       : fmt::format("joint '{}'", system.joints()[static_cast<std::size_t>(i - nb)].name);
      throw ComputationFailed(
          fmt::format("multibody: singular pivot at {} (redundant or degenerate constraints)", what));
    }
    if (node.parent < 0) continue;
    // H_up: the Jacobian block of the joint on the body, G (rows × 6), or its transpose.
    if (node.is_body) {
      const auto j = static_cast<std::size_t>(node.parent - nb);
      const JointJacobian& G = node.parent_side_a ? G_a[j] : G_b[j];
      node.H_up.topRows(G.rows()) = G;
    } else {
      const auto j = static_cast<std::size_t>(i - nb);
      const JointJacobian& G = node.parent_side_a ? G_a[j] : G_b[j];
      node.H_up.leftCols(G.rows()) = G.transpose();
    }
    Node& parent = nodes_[static_cast<std::size_t>(node.parent)];
    if (node.size == 6 && parent.size == 6) {
      eliminate<6, 6>(node.D_inv, node.H_up, node.Lt, parent.D);
    } else if (node.size == 6) {
      eliminate<6, 3>(node.D_inv, node.H_up, node.Lt, parent.D);
    } else {
      eliminate<3, 6>(node.D_inv, node.H_up, node.Lt, parent.D);
    }
  }
}

void KktSolver::solve(std::vector<Vec6>& body, Eigen::VectorXd& joint) {
  POINSOT_ASSERT(body.size() == static_cast<std::size_t>(system_->body_count()) && joint.size() == rows_,
                 "right-hand side sized for the factored system: 6 per body, one per constraint row");
  if (chain_) {
    chain_->solve(body, joint);
    return;
  }
  const int nb = system_->body_count();
  if (!tree_) {
    Sparse& sp = *sparse_;
    for (int i = 0; i < nb; ++i)
      sp.rhs.segment<6>(6 * i) = body[static_cast<std::size_t>(i)];
    sp.rhs.tail(rows_) = joint;
    const Eigen::VectorXd x = sp.lu.solve(sp.rhs);
    for (int i = 0; i < nb; ++i)
      body[static_cast<std::size_t>(i)] = x.segment<6>(6 * i);
    joint = x.tail(rows_);
    return;
  }
  for (int i = 0; i < nb; ++i)
    work_[static_cast<std::size_t>(i)] = body[static_cast<std::size_t>(i)];
  for (int j = 0; j < system_->joint_count(); ++j) {
    const int dim = nodes_[static_cast<std::size_t>(nb + j)].dim;
    POINSOT_ASSERT(dim >= 0 && dim <= 6 && joint_offset(j) + dim <= rows_, "joint rows inside the vector");
    work_[static_cast<std::size_t>(nb + j)].head(dim) = joint.segment(joint_offset(j), dim);
    work_[static_cast<std::size_t>(nb + j)].tail(6 - dim).setZero();
  }
  for (int i : order_) {  // L y = b
    const Node& node = nodes_[static_cast<std::size_t>(i)];
    if (node.parent < 0) continue;
    const Vec6& w = work_[static_cast<std::size_t>(i)];
    Vec6& wp = work_[static_cast<std::size_t>(node.parent)];
    if (node.size == 6 && nodes_[static_cast<std::size_t>(node.parent)].size == 6) {
      wp.noalias() -= node.Lt.transpose() * w;
    } else if (node.size == 6) {
      wp.head<3>().noalias() -= node.Lt.topLeftCorner<6, 3>().transpose() * w;
    } else {
      wp.noalias() -= node.Lt.topLeftCorner<3, 6>().transpose() * w.head<3>();
    }
  }
  for (int i : order_) {  // D z = y
    const Node& node = nodes_[static_cast<std::size_t>(i)];
    Vec6& w = work_[static_cast<std::size_t>(i)];
    if (node.size == 6) {
      w = node.D_inv * w;
    } else {
      w.head<3>() = node.D_inv.topLeftCorner<3, 3>() * w.head<3>();
    }
  }
  for (auto it = order_.rbegin(); it != order_.rend(); ++it) {  // Lᵀ x = z
    const Node& node = nodes_[static_cast<std::size_t>(*it)];
    if (node.parent < 0) continue;
    Vec6& w = work_[static_cast<std::size_t>(*it)];
    const Vec6& wp = work_[static_cast<std::size_t>(node.parent)];
    if (node.size == 6 && nodes_[static_cast<std::size_t>(node.parent)].size == 6) {
      w.noalias() -= node.Lt * wp;
    } else if (node.size == 6) {
      w.noalias() -= node.Lt.topLeftCorner<6, 3>() * wp.head<3>();
    } else {
      w.head<3>().noalias() -= node.Lt.topLeftCorner<3, 6>() * wp;
    }
  }
  for (int i = 0; i < nb; ++i)
    body[static_cast<std::size_t>(i)] = work_[static_cast<std::size_t>(i)];
  for (int j = 0; j < system_->joint_count(); ++j) {
    const int dim = nodes_[static_cast<std::size_t>(nb + j)].dim;
    joint.segment(joint_offset(j), dim) = work_[static_cast<std::size_t>(nb + j)].head(dim);
  }
}

}  // namespace poinsot::multibody
