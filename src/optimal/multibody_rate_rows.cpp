// The hinge rates of the rate bounds as point functions (multibody_rate_rows.hpp).
#include "multibody_rate_rows.hpp"

#include <algorithm>

namespace poinsot::optimal::detail {

QuadraticFunctions minimal_rate_rows(const MultibodyProblem& problem, const MultibodyMinimalModel& model) {
  QuadraticFunctions out;
  for (const RateBound& b : problem.rate_bounds) {
    // θ̇ of the joint's higher-indexed body, which is −q̇ when that is body_b.
    const multibody::Joint& j = problem.system.joints()[static_cast<std::size_t>(b.joint)];
    const MinimalTree::Link& child =
        model.tree().links[static_cast<std::size_t>(std::max(j.body_a, j.body_b))];
    out.add_linear(out.add_row(), child.v, child.motor_sign);
  }
  out.finish();
  return out;
}

namespace {

/// Adds s · n·ω of `body` to `row`: n·vee(½(M − Mᵀ)) = ½ Σ_c n_c (M(c2, c1) − M(c1, c2)), (c, c1, c2) cyclic,
/// with M(i, j) = Σ_k R(k, i) V(k, j).
void add_axis_rate(QuadraticFunctions& out, int row, const MultibodyRotationModel& m, int body, const Vec3& n,
                   double s) {
  for (int c = 0; c < 3; ++c) {
    const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
    for (int k = 0; k < 3; ++k) {
      out.add_bilinear(row, m.R(body, k, c2), m.V(body, k, c1), 0.5 * s * n[c]);
      out.add_bilinear(row, m.R(body, k, c1), m.V(body, k, c2), -0.5 * s * n[c]);
    }
  }
}

}  // namespace

QuadraticFunctions rotation_rate_rows(const MultibodyProblem& problem, const MultibodyRotationModel& model) {
  QuadraticFunctions out;
  for (const RateBound& b : problem.rate_bounds) {
    const multibody::Joint& j = problem.system.joints()[static_cast<std::size_t>(b.joint)];
    const int row = out.add_row();
    add_axis_rate(out, row, model, j.body_a, j.hinge_axis_a(), 1.0);
    if (j.body_b != multibody::kWorld) add_axis_rate(out, row, model, j.body_b, j.u_b[0], -1.0);
  }
  // s·vee(M − Mᵀ) = Σ_ij c_ij M_ij with c_ij = −Σ_m ε_ijm s_m, M = Cᵀ R_aᵀ R_b: M_ij = Σ_kl C_li R_a(k, l)
  // R_b(k, j).
  for (const NoTwist& t : problem.no_twist) {
    const multibody::Joint& j = problem.system.joints()[static_cast<std::size_t>(t.joint)];
    const int row = out.add_row();
    for (int i = 0; i < 3; ++i) {
      for (int jj = 0; jj < 3; ++jj) {
        const Vec3 e_i = Vec3::Unit(i), e_j = Vec3::Unit(jj);
        const double c = -e_i.cross(e_j).dot(t.axis_a);  // ε_ijm s_m = (e_i × e_j)·s
        if (c == 0.0) continue;
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) {
            const double coeff = c * t.straight(l, i);
            if (coeff == 0.0) continue;
            if (j.body_b == multibody::kWorld) {
              if (k == jj) out.add_linear(row, model.R(j.body_a, k, l), coeff);
            } else {
              out.add_bilinear(row, model.R(j.body_a, k, l), model.R(j.body_b, k, jj), coeff);
            }
          }
      }
    }
  }
  out.finish();
  return out;
}

}  // namespace poinsot::optimal::detail
