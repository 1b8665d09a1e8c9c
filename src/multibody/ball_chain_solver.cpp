// Schur complement on the joints, block tridiagonal along each path (ball_chain_solver.hpp).
#include "ball_chain_solver.hpp"

#include <array>
#include <cmath>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"

namespace poinsot::multibody::detail {
namespace {

// A⁻¹ of a symmetric positive definite 3 × 3 matrix by Cholesky; false when a pivot falls below 1e-13 of its
// diagonal entry (S singular to working accuracy: redundant constraints).
bool spd_inverse3(const Mat3& A, Mat3& inv) {
  const double d0 = A(0, 0);
  if (!(d0 > 0.0)) return false;
  const double l00 = std::sqrt(d0);
  const double l10 = A(1, 0) / l00, l20 = A(2, 0) / l00;
  const double d1 = A(1, 1) - l10 * l10;
  if (!(d1 > 1e-13 * A(1, 1))) return false;
  const double l11 = std::sqrt(d1);
  const double l21 = (A(2, 1) - l20 * l10) / l11;
  const double d2 = A(2, 2) - l20 * l20 - l21 * l21;
  if (!(d2 > 1e-13 * A(2, 2))) return false;
  const double l22 = std::sqrt(d2);
  // M = L⁻¹ (lower triangular), A⁻¹ = Mᵀ M.
  const double m00 = 1.0 / l00, m11 = 1.0 / l11, m22 = 1.0 / l22;
  const double m10 = -l10 * m00 * m11;
  const double m21 = -l21 * m11 * m22;
  const double m20 = -(l20 * m00 + l21 * m10) * m22;
  inv(0, 0) = m00 * m00 + m10 * m10 + m20 * m20;
  inv(1, 0) = inv(0, 1) = m11 * m10 + m21 * m20;
  inv(2, 0) = inv(0, 2) = m22 * m20;
  inv(1, 1) = m11 * m11 + m21 * m21;
  inv(2, 1) = inv(1, 2) = m22 * m21;
  inv(2, 2) = m22 * m22;
  return true;
}

}  // namespace

std::unique_ptr<BallChainSolver> BallChainSolver::make(const System& system) {
  const auto nb = static_cast<std::size_t>(system.body_count());
  const auto nj = static_cast<std::size_t>(system.joint_count());
  std::vector<std::vector<int>> joints_of(nb);
  for (std::size_t j = 0; j < nj; ++j) {
    const Joint& joint = system.joints()[j];
    if (joint.type != JointType::ball) return nullptr;
    joints_of[static_cast<std::size_t>(joint.body_a)].push_back(static_cast<int>(j));
    if (joint.body_b != kWorld)
      joints_of[static_cast<std::size_t>(joint.body_b)].push_back(static_cast<int>(j));
  }
  for (const auto& js : joints_of) {
    if (js.size() > 2) return nullptr;
  }
  std::unique_ptr<BallChainSolver> solver(new BallChainSolver(system));
  // The joint next to joint j through one of its bodies, or −1.
  auto neighbour = [&](int j, int body) {
    if (body == kWorld) return -1;
    for (int k : joints_of[static_cast<std::size_t>(body)])
      if (k != j) return k;
    return -1;
  };
  auto bodies_of = [&](int j) {
    const Joint& joint = system.joints()[static_cast<std::size_t>(j)];
    return std::array<int, 2>{joint.body_a, joint.body_b};
  };
  std::vector<char> placed(nj, 0);
  auto walk = [&](int j) {  // from an end joint j along its path
    int previous_body = kWorld;
    int previous_link = -1;
    while (j >= 0 && !placed[static_cast<std::size_t>(j)]) {
      placed[static_cast<std::size_t>(j)] = 1;
      Link link;
      link.joint = j;
      const auto bodies = bodies_of(j);
      for (int s = 0; s < 2; ++s) {
        link.sides[s].body = bodies[static_cast<std::size_t>(s)];
        link.sides[s].sign = s == 0 ? 1.0 : -1.0;
      }
      int next = -1, next_body = kWorld;
      for (int s = 0; s < 2; ++s) {
        const int b = bodies[static_cast<std::size_t>(s)];
        if (b == kWorld) continue;
        if (previous_link >= 0 && b == previous_body) {
          link.shared_side = s;
          const Link& prev = solver->links_[static_cast<std::size_t>(previous_link)];
          link.previous_side = prev.sides[0].body == b ? 0 : 1;
        } else {
          const int k = neighbour(j, b);
          if (k >= 0) {
            next = k;
            next_body = b;
          }
        }
      }
      solver->links_.push_back(link);
      previous_link = static_cast<int>(solver->links_.size()) - 1;
      previous_body = next_body;
      j = next;
    }
  };
  // Paths start at a joint with at most one neighbouring joint; a forest has no path without an end.
  for (std::size_t j = 0; j < nj; ++j) {
    const auto bodies = bodies_of(static_cast<int>(j));
    const int count = (neighbour(static_cast<int>(j), bodies[0]) >= 0 ? 1 : 0) +
                      (neighbour(static_cast<int>(j), bodies[1]) >= 0 ? 1 : 0);
    if (count <= 1 && !placed[j]) walk(static_cast<int>(j));
  }
  for (std::size_t j = 0; j < nj; ++j) {
    if (!placed[j]) return nullptr;  // a loop: not a forest (build_tree has rejected it already)
  }
  solver->y_.assign(nj, Vec3::Zero());
  solver->t_.assign(nb, Vec6::Zero());
  for (const Body& b : system.bodies())
    solver->inverse_mass_.push_back(1.0 / b.mass);
  return solver;
}

void BallChainSolver::factor(const std::vector<JointJacobian>& G_a, const std::vector<JointJacobian>& G_b) {
  const auto& bodies = system_->bodies();
  Link* previous = nullptr;
  for (Link& link : links_) {
    const auto j = static_cast<std::size_t>(link.joint);
    Mat3 S = Mat3::Zero();
    for (int s = 0; s < 2; ++s) {
      Side& side = link.sides[s];
      if (side.body == kWorld) continue;
      const Body& b = bodies[static_cast<std::size_t>(side.body)];
      side.G_omega = (s == 0 ? G_a[j] : G_b[j]).block<3, 3>(0, 3);
      side.X.noalias() = side.G_omega * b.inertia_inverse;
      S.noalias() += side.X * side.G_omega.transpose();
      S.diagonal().array() += inverse_mass_[static_cast<std::size_t>(side.body)];
    }
    if (link.shared_side >= 0) {
      const Side& mine = link.sides[link.shared_side];
      const Side& theirs = previous->sides[link.previous_side];
      link.E.noalias() = theirs.X * mine.G_omega.transpose();
      link.E.diagonal().array() +=
          theirs.sign * mine.sign * inverse_mass_[static_cast<std::size_t>(mine.body)];
      link.Lt.noalias() = previous->D_inv * link.E;
      S.noalias() -= link.E.transpose() * link.Lt;
    }
    if (!spd_inverse3(S, link.D_inv)) {
      throw ComputationFailed(
          fmt::format("multibody: singular pivot at joint '{}' (redundant or degenerate constraints)",
                      system_->joints()[j].name));
    }
    previous = &link;
  }
}

void BallChainSolver::solve(std::vector<Vec6>& body, Eigen::VectorXd& joint) {
  const auto& bodies = system_->bodies();
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    t_[i].head<3>() = inverse_mass_[i] * body[i].head<3>();
    t_[i].tail<3>().noalias() = bodies[i].inertia_inverse * body[i].tail<3>();
  }
  // Forward: L y′ = G M⁻¹ r − s.
  for (std::size_t p = 0; p < links_.size(); ++p) {
    const Link& link = links_[p];
    Vec3 z = -joint.segment<3>(3 * link.joint);
    for (const Side& side : link.sides) {
      if (side.body == kWorld) continue;
      const Vec6& t = t_[static_cast<std::size_t>(side.body)];
      z += side.sign * t.head<3>();
      z.noalias() += side.G_omega * t.tail<3>();
    }
    if (link.shared_side >= 0) z.noalias() -= link.Lt.transpose() * y_[p - 1];
    y_[p] = z;
  }
  // Diagonal and backward: Lᵀ y = D⁻¹ y′.
  for (std::size_t p = links_.size(); p-- > 0;) {
    const Link& link = links_[p];
    Vec3 y = link.D_inv * y_[p];
    if (p + 1 < links_.size() && links_[p + 1].shared_side >= 0) y.noalias() -= links_[p + 1].Lt * y_[p + 1];
    y_[p] = y;
  }
  // x = M⁻¹ (r − Gᵀ y) = t − Σ_sides (±y/m, Xᵀ y) with X = Gω J⁻¹ (J symmetric).
  for (std::size_t i = 0; i < bodies.size(); ++i)
    body[i] = t_[i];
  for (std::size_t p = 0; p < links_.size(); ++p) {
    const Link& link = links_[p];
    const Vec3& y = y_[p];
    joint.segment<3>(3 * link.joint) = y;
    for (const Side& side : link.sides) {
      if (side.body == kWorld) continue;
      const auto b = static_cast<std::size_t>(side.body);
      Vec6& x = body[b];
      x.head<3>() -= (side.sign * inverse_mass_[b]) * y;
      x.tail<3>().noalias() -= side.X.transpose() * y;
    }
  }
}

}  // namespace poinsot::multibody::detail
