// Schur complement on the joints, block tridiagonal along each path (ball_chain_solver.hpp).
#include "ball_chain_solver.hpp"

#include <array>

#include <fmt/format.h>

#include "poinsot/core/assert.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/multibody/constraints.hpp"

namespace poinsot::multibody::detail {
namespace {

// A symmetric 3 × 3 matrix by its lower triangle, held in registers (the helpers below are forced inline so
// that it stays there). The factorisation keeps its pivots in scalars because a matrix written entry by entry
// and read back by pairs stalls store forwarding, which perf showed on the loads after Eigen's 3 × 3
// temporaries.
struct Sym3 {
  double a, b, c, d, e, f;  // (0,0), (1,0), (2,0), (1,1), (2,1), (2,2)
  Mat3 full() const { return (Mat3() << a, b, c, b, d, e, c, e, f).finished(); }
};

// S += A Bᵀ, lower triangle (A Bᵀ symmetric): 18 multiplications instead of 27.
[[gnu::always_inline]] inline void add_ABt(Sym3& S, const Mat3& A, const Mat3& B) {
  auto dot = [&](int r, int col) { return A(r, 0) * B(col, 0) + A(r, 1) * B(col, 1) + A(r, 2) * B(col, 2); };
  S.a += dot(0, 0);
  S.b += dot(1, 0);
  S.c += dot(2, 0);
  S.d += dot(1, 1);
  S.e += dot(2, 1);
  S.f += dot(2, 2);
}

// S −= Aᵀ B, lower triangle (AᵀB symmetric).
[[gnu::always_inline]] inline void subtract_AtB(Sym3& S, const Mat3& A, const Mat3& B) {
  auto dot = [&](int r, int col) { return A(0, r) * B(0, col) + A(1, r) * B(1, col) + A(2, r) * B(2, col); };
  S.a -= dot(0, 0);
  S.b -= dot(1, 0);
  S.c -= dot(2, 0);
  S.d -= dot(1, 1);
  S.e -= dot(2, 1);
  S.f -= dot(2, 2);
}

// out = D E with D symmetric, in scalars (D stays in registers).
[[gnu::always_inline]] inline void symmetric_times(const Sym3& D, const Mat3& E, Mat3& out) {
  for (int col = 0; col < 3; ++col) {
    const double e0 = E(0, col), e1 = E(1, col), e2 = E(2, col);
    out(0, col) = D.a * e0 + D.b * e1 + D.c * e2;
    out(1, col) = D.b * e0 + D.d * e1 + D.e * e2;
    out(2, col) = D.c * e0 + D.e * e1 + D.f * e2;
  }
}

// A⁻¹ of a symmetric positive definite 3 × 3 matrix by its adjugate: one division, against Cholesky's three
// square roots and three divisions in series (the factorisation's recurrence runs through this inverse from
// joint to joint, so its latency counts). False when a leading minor is not positive to working accuracy
// (Cholesky's pivots d₁ = minor₂/a and d₂ = det/minor₂ below 1e-13 of their diagonal entry): S singular,
// redundant constraints.
[[gnu::always_inline]] inline bool spd_inverse3(const Sym3& S, Sym3& inv) {
  const double c00 = S.d * S.f - S.e * S.e, c10 = S.c * S.e - S.b * S.f, c20 = S.b * S.e - S.c * S.d;
  const double c11 = S.a * S.f - S.c * S.c, c21 = S.b * S.c - S.a * S.e, c22 = S.a * S.d - S.b * S.b;
  const double det = S.a * c00 + S.b * c10 + S.c * c20;
  if (!(S.a > 0.0) || !(c22 > 1e-13 * S.a * S.d) || !(det > 1e-13 * S.f * c22)) return false;
  const double r = 1.0 / det;
  inv = {r * c00, r * c10, r * c20, r * c11, r * c21, r * c22};
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
  factor_with([&](std::size_t j, int s) -> Mat3 { return (s == 0 ? G_a[j] : G_b[j]).block<3, 3>(0, 3); });
}

void BallChainSolver::factor_at(const std::vector<BodyState>& q) {
  POINSOT_ASSERT(q.size() == system_->bodies().size(), "one state per body of the system");
  // The ω-blocks of the point rows, computed in place (no JointJacobian storage).
  const auto& joints = system_->joints();
  factor_with([&](std::size_t j, int s) -> Mat3 {
    const Joint& joint = joints[j];
    if (s == 0)
      return point_rows_omega_jacobian_a(joint, q[static_cast<std::size_t>(joint.body_a)].R_space_body);
    return point_rows_omega_jacobian_b(joint, q[static_cast<std::size_t>(joint.body_b)].R_space_body);
  });
}

template <class OmegaBlock>
void BallChainSolver::factor_with(OmegaBlock omega_block) {
  const auto& bodies = system_->bodies();
  // The ω-blocks first, in a pass of their own: read back in the same iteration they were just written entry
  // by entry, they stalled the loads that followed (store forwarding).
  for (Link& link : links_) {
    for (int s = 0; s < 2; ++s) {
      if (link.sides[s].body != kWorld)
        link.sides[s].G_omega = omega_block(static_cast<std::size_t>(link.joint), s);
    }
  }
  Sym3 D_inv_previous{};
  for (std::size_t p = 0; p < links_.size(); ++p) {
    Link& link = links_[p];
    const auto j = static_cast<std::size_t>(link.joint);
    Sym3 S{};  // S_pp, then the pivot D_p = S_pp − E_pᵀ D_{p−1}⁻¹ E_p
    for (int s = 0; s < 2; ++s) {
      Side& side = link.sides[s];
      if (side.body == kWorld) continue;
      const Body& b = bodies[static_cast<std::size_t>(side.body)];
      side.X.noalias() = side.G_omega * b.inertia_inverse;
      add_ABt(S, side.X, side.G_omega);
      const double inverse_mass = inverse_mass_[static_cast<std::size_t>(side.body)];
      S.a += inverse_mass;
      S.d += inverse_mass;
      S.f += inverse_mass;
    }
    if (link.shared_side >= 0) {
      POINSOT_ASSERT(p > 0 && link.previous_side >= 0 && link.previous_side < 2,
                     "a link shares a body with the link before it");
      const Side& mine = link.sides[link.shared_side];
      const Side& theirs = links_[p - 1].sides[link.previous_side];
      link.E.noalias() = theirs.X * mine.G_omega.transpose();
      link.E.diagonal().array() +=
          theirs.sign * mine.sign * inverse_mass_[static_cast<std::size_t>(mine.body)];
      symmetric_times(D_inv_previous, link.E, link.Lt);
      subtract_AtB(S, link.E, link.Lt);
    }
    Sym3 D_inv{};
    if (!spd_inverse3(S, D_inv)) {
      throw ComputationFailed(
          fmt::format("multibody: singular pivot at joint '{}' (redundant or degenerate constraints)",
                      system_->joints()[j].name));
    }
    link.D_inv = D_inv.full();
    D_inv_previous = D_inv;
  }
}

void BallChainSolver::solve(std::vector<Vec6>& body, Eigen::VectorXd& joint) {
  const auto& bodies = system_->bodies();
  POINSOT_ASSERT(
      body.size() == bodies.size() && joint.size() == 3 * static_cast<Eigen::Index>(system_->joint_count()),
      "right-hand side sized for the factored system: 6 per body, 3 per ball joint");
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    t_[i].head<3>() = inverse_mass_[i] * body[i].head<3>();
    t_[i].tail<3>().noalias() = bodies[i].inertia_inverse * body[i].tail<3>();
  }
  // Forward: L y′ = G M⁻¹ r − s; first G M⁻¹ r − s for every joint (independent), then the recurrence, with
  // the previous joint's value carried in registers.
  for (std::size_t p = 0; p < links_.size(); ++p) {
    const Link& link = links_[p];
    Vec3 z = -joint.segment<3>(3 * link.joint);
    for (const Side& side : link.sides) {
      if (side.body == kWorld) continue;
      const Vec6& t = t_[static_cast<std::size_t>(side.body)];
      z += side.sign * t.head<3>();
      z.noalias() += side.G_omega * t.tail<3>();
    }
    y_[p] = z;
  }
  Vec3 previous = Vec3::Zero();
  for (std::size_t p = 0; p < links_.size(); ++p) {
    Vec3 y = y_[p];
    if (links_[p].shared_side >= 0) y.noalias() -= links_[p].Lt.transpose() * previous;
    y_[p] = y;
    previous = y;
  }
  // Diagonal and backward: Lᵀ y = D⁻¹ y′.
  Vec3 next = Vec3::Zero();
  for (std::size_t p = links_.size(); p-- > 0;) {
    Vec3 y = links_[p].D_inv * y_[p];
    if (p + 1 < links_.size() && links_[p + 1].shared_side >= 0) y.noalias() -= links_[p + 1].Lt * next;
    y_[p] = y;
    next = y;
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
