// The rotation-matrix point model of a multibody problem (multibody_rotation_model.hpp).
#include "multibody_rotation_model.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "poinsot/multibody/constraints.hpp"
#include "poinsot/so3/hat.hpp"

namespace poinsot::optimal::detail {
namespace {

double epsilon(int i, int j, int k) {  // the Levi-Civita symbol
  return static_cast<double>((i - j) * (j - k) * (k - i)) / 2.0;
}

}  // namespace

int MultibodyRotationModel::sym(int k, int l) {
  if (k == l) return k;
  const int lo = std::min(k, l), hi = std::max(k, l);
  return lo == 0 ? 2 + hi : 5;  // (0,1) → 3, (0,2) → 4, (1,2) → 5
}

int MultibodyRotationModel::mu(int joint) const {
  return lambda(joint) + problem_.system.joints()[static_cast<std::size_t>(joint)].rows();
}

MultibodyRotationModel::MultibodyRotationModel(const MultibodyProblem& problem, double stabilisation_step)
    : problem_(problem), stabilisation_step_(stabilisation_step) {
  bodies_ = problem_.system.body_count();
  z_ = 24 * bodies_;
  int next = z_ + 24 * bodies_;
  for (const multibody::Joint& j : problem_.system.joints()) {
    joint_offset_.push_back(next);
    next += 2 * j.rows();
  }
  for (const Actuator& a : problem_.actuators) {
    control_offset_.push_back(next);
    for (int k = 0; k < a.controls(); ++k)
      controls_.push_back(next + k);
    next += a.controls();
  }
  size_ = next;
  build_rhs();
  build_path(first_path_, true);
  build_path(path_, false);
  add_invariant_rows(invariants0_, 0);
  add_invariant_rows(invariants1_, 1);
  invariants0_.finish();
  invariants1_.finish();
}

namespace {

// Emits terms of the constraints and of their time derivatives. A body's matrix at derivative level 0, 1, 2
// is R, V, A and its vector x, v, a; the world's matrix is I and its vector 0 (constant).
struct Emitter {
  const MultibodyRotationModel& m;
  const multibody::System& system;
  QuadraticFunctions& out;

  int matrix(int body, int level, int r, int c) const {
    return level == 0 ? m.R(body, r, c) : level == 1 ? m.V(body, r, c) : m.A(body, r, c);
  }
  void matrix_linear(int row, int level, int body, int r, int c, double coeff) const {
    if (body == multibody::kWorld) {
      if (level == 0 && r == c) out.add_constant(row, coeff);
    } else {
      out.add_linear(row, matrix(body, level, r, c), coeff);
    }
  }
  void vector_linear(int row, int level, int body, int k, double coeff) const {
    if (body == multibody::kWorld) return;
    out.add_linear(row, (level == 0 ? m.x(body) : level == 1 ? m.v(body) : m.a(body)) + k, coeff);
  }
  // coeff · d^level/dt^level [M_i(r1, c1) M_j(r2, c2)] by Leibniz' rule.
  void product(int row, int level, int bi, int r1, int c1, int bj, int r2, int c2, double coeff) const {
    for (int l = 0; l <= level; ++l) {
      const double binomial = (level == 2 && l == 1) ? 2.0 : 1.0;
      const int lj = level - l;
      const bool wi = bi == multibody::kWorld, wj = bj == multibody::kWorld;
      if (wi && wj) {
        if (l == 0 && lj == 0 && r1 == c1 && r2 == c2) out.add_constant(row, coeff);
      } else if (wj) {
        if (lj == 0 && r2 == c2) out.add_linear(row, matrix(bi, l, r1, c1), coeff * binomial);
      } else if (wi) {
        if (l == 0 && r1 == c1) out.add_linear(row, matrix(bj, lj, r2, c2), coeff * binomial);
      } else {
        out.add_bilinear(row, matrix(bi, l, r1, c1), matrix(bj, lj, r2, c2), coeff * binomial);
      }
    }
  }
  // sign · Gᵀ(multiplier) of every joint, added to the x rows `xrow(body) + k` and the R rows
  // `xrow(body) + 3 + r + 3c` (the layout of y's (x, R) block).
  void joint_gradient(const std::function<int(int)>& xrow, const std::function<int(int)>& multiplier,
                      double sign) const {
    const auto& joints = system.joints();
    for (std::size_t jj = 0; jj < joints.size(); ++jj) {
      const multibody::Joint& j = joints[jj];
      const int first = multiplier(static_cast<int>(jj));
      const int a = j.body_a, b = j.body_b;
      for (int k = 0; k < 3; ++k) {
        out.add_linear(xrow(a) + k, first + k, sign);
        for (int c = 0; c < 3; ++c)
          out.add_linear(xrow(a) + 3 + k + 3 * c, first + k, sign * j.point_a(c));
        if (b == multibody::kWorld) continue;
        out.add_linear(xrow(b) + k, first + k, -sign);
        for (int c = 0; c < 3; ++c)
          out.add_linear(xrow(b) + 3 + k + 3 * c, first + k, -sign * j.point_b(c));
      }
      for (int n = 0; n < j.perpendicular_count; ++n) {
        const Vec3& p = j.p_a[static_cast<std::size_t>(n)];
        const Vec3& u = j.u_b[static_cast<std::size_t>(n)];
        const int mult = first + 3 + n;
        for (int r = 0; r < 3; ++r) {
          for (int c = 0; c < 3; ++c) {
            for (int d = 0; d < 3; ++d) {
              // ∂/∂R_a(r, c) = p_c (R_b u)_r and ∂/∂R_b(r, d) = u_d (R_a p)_r.
              if (b == multibody::kWorld) {
                if (d == r) out.add_linear(xrow(a) + 3 + r + 3 * c, mult, sign * p(c) * u(d));
              } else {
                out.add_bilinear(xrow(a) + 3 + r + 3 * c, mult, m.R(b, r, d), sign * p(c) * u(d));
                out.add_bilinear(xrow(b) + 3 + r + 3 * d, mult, m.R(a, r, c), sign * p(c) * u(d));
              }
            }
          }
        }
      }
    }
  }
};

}  // namespace

void MultibodyRotationModel::add_invariant_rows(QuadraticFunctions& out, int level) const {
  const Emitter e{*this, problem_.system, out};
  for (int i = 0; i < bodies_; ++i) {
    for (int k = 0; k < 3; ++k) {
      for (int l = k; l < 3; ++l) {
        const int row = out.add_row();
        for (int r = 0; r < 3; ++r)
          e.product(row, level, i, r, k, i, r, l, 1.0);
        if (level == 0 && k == l) out.add_constant(row, -1.0);
      }
    }
  }
  for (const multibody::Joint& j : problem_.system.joints()) {
    const int a = j.body_a, b = j.body_b;
    for (int k = 0; k < 3; ++k) {
      const int row = out.add_row();
      e.vector_linear(row, level, a, k, 1.0);
      e.vector_linear(row, level, b, k, -1.0);
      for (int c = 0; c < 3; ++c) {
        e.matrix_linear(row, level, a, k, c, j.point_a(c));
        e.matrix_linear(row, level, b, k, c, -j.point_b(c));
      }
    }
    for (int n = 0; n < j.perpendicular_count; ++n) {
      const int row = out.add_row();
      const Vec3& p = j.p_a[static_cast<std::size_t>(n)];
      const Vec3& u = j.u_b[static_cast<std::size_t>(n)];
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          for (int d = 0; d < 3; ++d)
            e.product(row, level, a, r, c, b, r, d, p(c) * u(d));
    }
  }
}

void MultibodyRotationModel::build_rhs() {
  for (int r = 0; r < state_size(); ++r)
    rhs_.add_row();
  for (int i = 0; i < bodies_; ++i) {
    for (int k = 0; k < 3; ++k) {
      rhs_.add_linear(x(i) + k, v(i) + k, 1.0);
      rhs_.add_linear(v(i) + k, a(i) + k, 1.0);
    }
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        rhs_.add_linear(R(i, r, c), V(i, r, c), 1.0);
        rhs_.add_linear(V(i, r, c), A(i, r, c), 1.0);
        for (int k = 0; k < 3; ++k)
          rhs_.add_bilinear(R(i, r, c), R(i, r, k), S(i, k, c), 1.0);
      }
    }
  }
  const Emitter e{*this, problem_.system, rhs_};
  e.joint_gradient([this](int body) { return x(body); }, [this](int joint) { return mu(joint); }, 1.0);
  rhs_.finish();
}

void MultibodyRotationModel::build_path(QuadraticFunctions& out, bool first_node) {
  const multibody::System& sys = problem_.system;
  // Dynamics: 12 rows per body, laid out like (x, R): m a − f − Gₓᵀλ, A K − R Λ − F_R − G_Rᵀλ − F_R(u).
  for (int r = 0; r < 12 * bodies_; ++r)
    out.add_row();
  const auto xrow = [](int body) { return 12 * body; };
  const auto Rrow = [](int body, int r, int c) { return 12 * body + 3 + r + 3 * c; };
  for (int i = 0; i < bodies_; ++i) {
    const multibody::Body& body = sys.bodies()[static_cast<std::size_t>(i)];
    for (int k = 0; k < 3; ++k) {
      out.add_linear(xrow(i) + k, a(i) + k, body.mass);
      out.add_constant(xrow(i) + k, -body.mass * sys.gravity()(k));
    }
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        for (int k = 0; k < 3; ++k) {
          out.add_linear(Rrow(i, r, c), A(i, r, k), body.poinsot(k, c));
          out.add_bilinear(Rrow(i, r, c), R(i, r, k), Lambda(i, k, c), -1.0);
        }
      }
    }
  }
  for (const multibody::ConstantForce& f : sys.forces()) {
    for (int r = 0; r < 3; ++r) {
      out.add_constant(xrow(f.body) + r, -f.force_space(r));
      for (int c = 0; c < 3; ++c)
        out.add_constant(Rrow(f.body, r, c), -f.force_space(r) * f.point_body(c));
    }
  }
  for (const multibody::ConstantTorque& t : sys.torques()) {
    const Mat3 W = so3::hat(t.torque);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) {
          if (t.in_body_frame)  // F_R = ½ R j(τ)
            out.add_linear(Rrow(t.body, r, c), R(t.body, r, k), -0.5 * W(k, c));
          else  // F_R = ½ j(τ) R
            out.add_linear(Rrow(t.body, r, c), R(t.body, k, c), -0.5 * W(r, k));
        }
  }
  for (std::size_t ai = 0; ai < problem_.actuators.size(); ++ai) {
    const Actuator& act = problem_.actuators[ai];
    const int u = control(static_cast<int>(ai));
    // ½ u R j(axis) on each side (sign +1 on a, −1 on b), or ½ R j(τ) for a body torque.
    const auto couple = [&](int body, const Vec3& axis, double sign) {
      const Mat3 W = so3::hat(axis);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          for (int k = 0; k < 3; ++k)
            out.add_bilinear(Rrow(body, r, c), R(body, r, k), u, -0.5 * sign * W(k, c));
    };
    // ½ j(τ) R for a space-frame torque τ (sign +1 on a, −1 on b): (j(τ) R)(r, c) = Σ ε(r, m, k) τ_m R(k, c).
    const auto space_couple = [&](int body, double sign) {
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          for (int k = 0; k < 3; ++k)
            for (int mm = 0; mm < 3; ++mm)
              out.add_bilinear(Rrow(body, r, c), R(body, k, c), u + mm, -0.5 * sign * epsilon(r, mm, k));
    };
    if (act.kind == ActuatorKind::hinge_torque) {
      const multibody::Joint& j = sys.joints()[static_cast<std::size_t>(act.index)];
      couple(j.body_a, j.hinge_axis_a(), 1.0);
      if (j.body_b != multibody::kWorld) couple(j.body_b, j.u_b[0], -1.0);
    } else if (act.kind == ActuatorKind::ball_torque) {
      const multibody::Joint& j = sys.joints()[static_cast<std::size_t>(act.index)];
      space_couple(j.body_a, 1.0);
      if (j.body_b != multibody::kWorld) space_couple(j.body_b, -1.0);
    } else {
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          for (int k = 0; k < 3; ++k)
            for (int mm = 0; mm < 3; ++mm)
              out.add_bilinear(Rrow(act.index, r, c), R(act.index, r, k), u + mm, -0.5 * epsilon(k, mm, c));
    }
  }
  const Emitter e{*this, problem_.system, out};
  e.joint_gradient(
      xrow, [this](int joint) { return lambda(joint); }, -1.0);
  if (first_node) {
    add_invariant_rows(out, 2);
  } else {
    add_invariant_rows(out, 1);
    add_invariant_rows(out, 0);
  }
  out.finish();
}

void MultibodyRotationModel::variable_bounds(const PointRole& role, double* lower, double* upper) const {
  const bool first_node = role.first;
  for (int i = 0; i < size_; ++i) {
    lower[i] = -kNoBound;
    upper[i] = kNoBound;
  }
  for (std::size_t ai = 0; ai < problem_.actuators.size(); ++ai) {
    const Actuator& act = problem_.actuators[ai];
    const double bound = std::min(act.torque_max, kNoBound);
    for (int k = 0; k < act.controls(); ++k) {
      lower[control(static_cast<int>(ai)) + k] = -bound;
      upper[control(static_cast<int>(ai)) + k] = bound;
    }
  }
  // Node 0: S = μ = 0 (its state is given and consistent); elsewhere the bounds of the constructor, if any.
  const double h = problem_.final_time / problem_.intervals;
  const double sigma = first_node ? 0.0 : stabilisation_step_ > 0.0 ? stabilisation_step_ / h : kNoBound;
  const double ell = point_row_scale();
  for (int i = 0; i < bodies_; ++i)
    for (int k = 0; k < 6; ++k) {
      lower[S(i, 0, 0) + k] = -sigma;
      upper[S(i, 0, 0) + k] = sigma;
    }
  for (int j = 0; j < problem_.system.joint_count(); ++j) {
    const multibody::Joint& joint = problem_.system.joints()[static_cast<std::size_t>(j)];
    for (int k = 0; k < joint.rows(); ++k) {
      const double bound = k < joint.translation_rows() ? std::min(sigma * ell, kNoBound) : sigma;
      lower[mu(j) + k] = -bound;
      upper[mu(j) + k] = bound;
    }
  }
}

double MultibodyRotationModel::stabilisation_step(const double* w) const {
  const double h = problem_.final_time / problem_.intervals;
  const double ell = point_row_scale();
  double step = 0.0;
  for (int i = 0; i < bodies_; ++i)
    for (int k = 0; k < 6; ++k)
      step = std::max(step, h * std::abs(w[S(i, 0, 0) + k]));
  for (int j = 0; j < problem_.system.joint_count(); ++j) {
    const multibody::Joint& joint = problem_.system.joints()[static_cast<std::size_t>(j)];
    for (int k = 0; k < joint.rows(); ++k)
      step = std::max(step, h * std::abs(w[mu(j) + k]) / (k < joint.translation_rows() ? ell : 1.0));
  }
  return step;
}

Eigen::VectorXd MultibodyRotationModel::state_vector(const multibody::State& state) const {
  Eigen::VectorXd y(state_size());
  for (int i = 0; i < bodies_; ++i) {
    const multibody::BodyState& b = state.bodies[static_cast<std::size_t>(i)];
    y.segment<3>(x(i)) = b.x_space;
    y.segment<3>(v(i)) = b.v_space;
    const Mat3 Vm = b.R_space_body * so3::hat(b.omega_body);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        y(R(i, r, c)) = b.R_space_body(r, c);
        y(V(i, r, c)) = Vm(r, c);
      }
  }
  return y;
}

multibody::State MultibodyRotationModel::state_of(const double* w, double time) const {
  multibody::State s;
  s.time = time;
  s.bodies.resize(static_cast<std::size_t>(bodies_));
  for (int i = 0; i < bodies_; ++i) {
    multibody::BodyState& b = s.bodies[static_cast<std::size_t>(i)];
    Mat3 Vm;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        b.R_space_body(r, c) = w[R(i, r, c)];
        Vm(r, c) = w[V(i, r, c)];
      }
    b.x_space = Eigen::Map<const Vec3>(w + x(i));
    b.v_space = Eigen::Map<const Vec3>(w + v(i));
    const Mat3 W = b.R_space_body.transpose() * Vm;
    b.omega_body = 0.5 * Vec3(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1));
  }
  return s;
}

multibody::Multipliers MultibodyRotationModel::multipliers_of(const double* w) const {
  const multibody::State s = state_of(w, 0.0);
  multibody::Multipliers out;
  for (int i = 0; i < bodies_; ++i) {
    Mat3 L;
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l)
        L(k, l) = w[Lambda(i, k, l)];
    out.Lambda_body.push_back(L);
  }
  const auto& joints = problem_.system.joints();
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const multibody::Joint& jt = joints[j];
    const multibody::JointVector lam =
        Eigen::Map<const Eigen::VectorXd>(w + lambda(static_cast<int>(j)), jt.rows());
    const multibody::JointLoads loads = multibody::joint_loads(
        jt, multibody::side_state(s.bodies, jt.body_a), multibody::side_state(s.bodies, jt.body_b), lam);
    out.joint_force_space.push_back(loads.force_a_space);
    out.joint_torque_space.push_back(loads.torque_a_space);
  }
  return out;
}

Eigen::MatrixXd MultibodyRotationModel::invariant_jacobian(const multibody::State& state) const {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(size_);
  w.head(state_size()) = state_vector(state);
  const int n0 = invariants0_.rows(), n1 = invariants1_.rows();
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n0 + n1, state_size());
  int row_offset = 0;
  for (const QuadraticFunctions* f : {&invariants0_, &invariants1_}) {
    std::vector<double> values(f->jacobian_pattern().size());
    f->jacobian_values(w.data(), values.data());
    for (std::size_t e = 0; e < values.size(); ++e) {
      const auto [r, c] = f->jacobian_pattern()[e];
      C(row_offset + r, c) += values[e];
    }
    row_offset += f->rows();
  }
  return C;
}

}  // namespace poinsot::optimal::detail
