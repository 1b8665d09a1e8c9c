// The minimal-coordinate point model of a multibody problem (multibody_minimal_model.hpp).
#include "multibody_minimal_model.hpp"

#include <cmath>

#include <fmt/format.h>
#include <Eigen/Geometry>
#include <unsupported/Eigen/AutoDiff>

#include "multibody_final_conditions.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/so3/hat.hpp"

namespace poinsot::optimal::detail {
namespace {

using Der1 = Eigen::VectorXd;
using AD1 = Eigen::AutoDiffScalar<Der1>;
using Der2 = Eigen::Matrix<AD1, Eigen::Dynamic, 1>;
using AD2 = Eigen::AutoDiffScalar<Der2>;

/// R(e/|e|) = I + 2(e₀ j(ē) + j(ē)²)/|e|², the attitude of a quaternion of any norm > 0.
template <class S>
Eigen::Matrix<S, 3, 3> minimal_quaternion_rotation(const S* e) {
  Eigen::Matrix<S, 3, 3> K;
  const S zero(0.0);
  K << zero, -e[3], e[2], e[3], zero, -e[1], -e[2], e[1], zero;
  const S scale = S(2.0) / (e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + e[3] * e[3]);
  return Mat3::Identity().cast<S>() + (K * e[0] + K * K) * scale;
}

/// The path rows at w = (q, ν, ν̇, u) (the file comment of multibody_minimal_model.hpp), for any scalar type
/// (double, or first- and second-order automatic differentiation).
template <class S>
void minimal_inverse_dynamics_rows(const HingeTree& tree, const MinimalLayout& at,
                                   const std::vector<int>& motor, const S* w, S* out) {
  using V3 = Eigen::Matrix<S, 3, 1>;
  using M3 = Eigen::Matrix<S, 3, 3>;
  const int n = static_cast<int>(tree.links.size());
  std::vector<M3> R(static_cast<std::size_t>(n));
  std::vector<V3> om(R.size()), dom(R.size()), acc(R.size()), f(R.size()), couple(R.size());
  const V3 zero = V3::Constant(S(0.0));
  const M3 eye = Mat3::Identity().cast<S>();
  if (at.floating) {
    R[0] = minimal_quaternion_rotation(w);
    om[0] = V3(w[at.omega()], w[at.omega() + 1], w[at.omega() + 2]);
    dom[0] = V3(w[at.omega_dot()], w[at.omega_dot() + 1], w[at.omega_dot() + 2]);
    acc[0] = zero;  // shifted below by the centre of mass's acceleration
  }
  for (int i = at.first_link(); i < n; ++i) {
    const auto iu = static_cast<std::size_t>(i);
    const HingeTree::Link& L = tree.links[iu];
    const S& th = w[at.angle(i)];
    const S& dth = w[at.rate(i)];
    const S& ddth = w[at.acceleration(i)];
    const M3 K = so3::hat(L.axis).cast<S>();
    const M3 rot = eye + K * sin(th) + (K * K) * (S(1.0) - cos(th));
    const M3 E = L.C.cast<S>() * rot;
    const V3 axis = L.axis.cast<S>(), A = L.A.cast<S>(), B = L.B.cast<S>();
    const bool world = L.parent == multibody::kWorld;
    const auto p = static_cast<std::size_t>(std::max(L.parent, 0));
    const M3 Rp = world ? eye : R[p];
    const V3 omp = world ? zero : om[p], domp = world ? zero : dom[p], ap = world ? zero : acc[p];
    R[iu] = Rp * E;
    om[iu] = E.transpose() * omp + axis * dth;
    dom[iu] = E.transpose() * domp + axis * ddth + om[iu].cross(axis) * dth;
    acc[iu] = ap + Rp * (domp.cross(B) + omp.cross(omp.cross(B))) -
              R[iu] * (dom[iu].cross(A) + om[iu].cross(om[iu].cross(A)));
  }
  if (at.floating) {  // the centre of mass does not accelerate: Σ m_i a_i = 0
    V3 moment = zero;
    double mass = 0.0;
    for (int i = 0; i < n; ++i) {
      moment += acc[static_cast<std::size_t>(i)] * S(tree.links[static_cast<std::size_t>(i)].mass);
      mass += tree.links[static_cast<std::size_t>(i)].mass;
    }
    for (V3& a : acc)
      a -= moment / S(mass);
  }
  for (int i = 0; i < n; ++i) {
    f[static_cast<std::size_t>(i)] = zero;
    couple[static_cast<std::size_t>(i)] = zero;
  }
  for (int i = n - 1; i >= 0; --i) {
    const auto iu = static_cast<std::size_t>(i);
    const HingeTree::Link& L = tree.links[iu];
    const M3 J = L.J.cast<S>();
    f[iu] += (acc[iu] - tree.gravity.cast<S>()) * S(L.mass);
    couple[iu] += R[iu] * (J * dom[iu] + om[iu].cross(J * om[iu])) - (R[iu] * L.A.cast<S>()).cross(f[iu]);
    if (i < at.first_link()) {  // the floating base: the total angular momentum's rate, base frame
      const V3 body = R[iu].transpose() * couple[iu];
      for (int k = 0; k < 3; ++k)
        out[k] = body(k);
      continue;
    }
    if (L.parent != multibody::kWorld) {
      const auto p = static_cast<std::size_t>(L.parent);
      f[p] += f[iu];
      couple[p] += couple[iu] + (R[p] * L.B.cast<S>()).cross(f[iu]);
    }
    out[at.row(i)] = (R[iu] * L.axis.cast<S>()).dot(couple[iu]);
    if (motor[iu] >= 0) out[at.row(i)] -= w[motor[iu]];
  }
}

/// The inverse-dynamics rows with their derivatives by forward automatic differentiation.
class MinimalInverseDynamicsRows final : public PointFunctions {
 public:
  MinimalInverseDynamicsRows(const HingeTree& tree, const MinimalLayout& layout, std::vector<int> motor,
                             int point_size)
      : tree_(tree), layout_(layout), motor_(std::move(motor)), nw_(point_size) {
    const int n = static_cast<int>(tree_.links.size());
    const int dense = layout_.controls_begin();
    for (int r = 0; r < rows(); ++r)
      for (int v = 0; v < dense; ++v)
        jac_.push_back({r, v});
    for (int i = layout_.first_link(); i < n; ++i)
      if (motor_[static_cast<std::size_t>(i)] >= 0)
        jac_.push_back({layout_.row(i), motor_[static_cast<std::size_t>(i)]});
    for (int i = 0; i < dense; ++i)
      for (int j = 0; j <= i; ++j)
        hess_.push_back({i, j});
  }
  int rows() const override { return layout_.base_rows() + layout_.hinges; }
  void values(const double* w, double* out) const override {
    minimal_inverse_dynamics_rows<double>(tree_, layout_, motor_, w, out);
  }
  const std::vector<IndexPair>& jacobian_pattern() const override { return jac_; }
  void jacobian_values(const double* w, double* values) const override {
    std::vector<AD1> x(static_cast<std::size_t>(nw_)), out(static_cast<std::size_t>(rows()));
    for (int i = 0; i < nw_; ++i)
      x[static_cast<std::size_t>(i)] = AD1(w[i], nw_, i);
    minimal_inverse_dynamics_rows<AD1>(tree_, layout_, motor_, x.data(), out.data());
    for (std::size_t e = 0; e < jac_.size(); ++e) {
      const auto& d = out[static_cast<std::size_t>(jac_[e].first)].derivatives();
      values[e] = d.size() == 0 ? 0.0 : d(jac_[e].second);
    }
  }
  const std::vector<IndexPair>& hessian_pattern() const override { return hess_; }
  void hessian_values(const double* w, const double* weights, double* values) const override {
    const auto nw = static_cast<Eigen::Index>(nw_);
    std::vector<AD2> x(static_cast<std::size_t>(nw_)), out(static_cast<std::size_t>(rows()));
    for (Eigen::Index i = 0; i < nw; ++i) {
      Der2 d(nw);
      for (Eigen::Index j = 0; j < nw; ++j)
        d(j) = AD1(i == j ? 1.0 : 0.0, Der1::Zero(nw));
      x[static_cast<std::size_t>(i)] = AD2(AD1(w[i], nw_, static_cast<int>(i)), d);
    }
    minimal_inverse_dynamics_rows<AD2>(tree_, layout_, motor_, x.data(), out.data());
    AD2 sum(AD1(0.0, Der1::Zero(nw)), Der2::Constant(nw, AD1(0.0, Der1::Zero(nw))));
    for (int r = 0; r < rows(); ++r)
      sum += out[static_cast<std::size_t>(r)] *
             AD2(AD1(weights[r], Der1::Zero(nw)), Der2::Constant(nw, AD1(0.0, Der1::Zero(nw))));
    for (std::size_t e = 0; e < hess_.size(); ++e) {
      const AD1& di = sum.derivatives()(hess_[e].first);
      values[e] = di.derivatives().size() == 0 ? 0.0 : di.derivatives()(hess_[e].second);
    }
  }

 private:
  const HingeTree& tree_;
  MinimalLayout layout_;
  std::vector<int> motor_;
  int nw_;
  std::vector<IndexPair> jac_, hess_;
};

Mat3 minimal_axis_rotation(const Vec3& axis, double angle) {
  const Mat3 K = so3::hat(axis);
  return Mat3::Identity() + std::sin(angle) * K + (1.0 - std::cos(angle)) * K * K;
}

}  // namespace

MultibodyMinimalModel::MultibodyMinimalModel(const MultibodyProblem& problem) {
  const multibody::System& sys = problem.system;
  const int n = sys.body_count();
  const auto refuse = [](const std::string& why) {
    throw InvalidInput(fmt::format(
        "optimal control: coordinates = \"minimal\": {}; expected a tree of hinges (each body the body_a of "
        "one hinge, its body_b the world or a body of lower index, or body 0 a floating base in no joint to "
        "the world) with hinge motors only",
        why));
  };
  if (!sys.forces().empty() || !sys.torques().empty()) refuse("the system has constant forces or torques");
  tree_.links.resize(static_cast<std::size_t>(n));
  tree_.gravity = sys.gravity();
  std::vector<int> hinge_of(static_cast<std::size_t>(n), -1);
  bool touches_world = false;
  for (int ji = 0; ji < sys.joint_count(); ++ji) {
    const multibody::Joint& j = sys.joints()[static_cast<std::size_t>(ji)];
    if (j.type != multibody::JointType::hinge) refuse(fmt::format("joint '{}' is not a hinge", j.name));
    if (hinge_of[static_cast<std::size_t>(j.body_a)] >= 0 || j.body_b >= j.body_a)
      refuse(fmt::format("joint '{}' does not hang body_a from the world or a body of lower index", j.name));
    hinge_of[static_cast<std::size_t>(j.body_a)] = ji;
    touches_world = touches_world || j.body_b == multibody::kWorld;
  }
  const auto& s0 = problem.initial_state.bodies;
  tree_.floating_base = n > 0 && hinge_of[0] < 0 && !touches_world;
  layout_.floating = tree_.floating_base;
  layout_.hinges = n - layout_.first_link();
  if (tree_.floating_base) {
    // The translation is eliminated by x_com = const, which needs P = 0 and no external force.
    if (sys.gravity().norm() != 0.0) {
      refuse(fmt::format(
          "a floating base with gravity ({}, {}, {}) m/s²: its centre of mass would fall, expected "
          "no gravity",
          sys.gravity().x(), sys.gravity().y(), sys.gravity().z()));
    }
    const Vec3 P = multibody::linear_momentum(sys, problem.initial_state);
    double scale = 0.0;
    for (int i = 0; i < n; ++i)
      scale +=
          sys.bodies()[static_cast<std::size_t>(i)].mass * s0[static_cast<std::size_t>(i)].v_space.norm();
    if (P.norm() > 1e-9 * scale) {
      refuse(
          fmt::format("initial_state: a floating base with linear momentum |P| = {:.3g} kg·m/s, expected 0 "
                      "(the centre of mass at rest eliminates the translation)",
                      P.norm()));
    }
    double mass = 0.0;
    for (int i = 0; i < n; ++i) {
      com_space_ += sys.bodies()[static_cast<std::size_t>(i)].mass * s0[static_cast<std::size_t>(i)].x_space;
      mass += sys.bodies()[static_cast<std::size_t>(i)].mass;
    }
    com_space_ /= mass;
    const Eigen::Quaterniond e(s0[0].R_space_body);
    sign_reference_ = Eigen::Vector4d(e.w(), e.x(), e.y(), e.z());
    if (sign_reference_(0) < 0.0) sign_reference_ = -sign_reference_;
    HingeTree::Link& base = tree_.links[0];
    base.mass = sys.bodies()[0].mass;
    base.J = sys.bodies()[0].inertia;
    base.A = Vec3::Zero();
  }
  for (int i = layout_.first_link(); i < n; ++i) {
    const int ji = hinge_of[static_cast<std::size_t>(i)];
    if (ji < 0)
      refuse(fmt::format("body '{}' hangs from no hinge", sys.bodies()[static_cast<std::size_t>(i)].name));
    const multibody::Joint& j = sys.joints()[static_cast<std::size_t>(ji)];
    HingeTree::Link& L = tree_.links[static_cast<std::size_t>(i)];
    const Mat3 Rp = j.body_b == multibody::kWorld ? Mat3::Identity()
                                                  : s0[static_cast<std::size_t>(j.body_b)].R_space_body;
    L.parent = j.body_b;
    L.axis = j.p_a[0].cross(j.p_a[1]);
    L.C = Rp.transpose() * s0[static_cast<std::size_t>(i)].R_space_body;
    L.A = j.point_a;
    L.B = j.point_b;
    L.mass = sys.bodies()[static_cast<std::size_t>(i)].mass;
    L.J = sys.bodies()[static_cast<std::size_t>(i)].inertia;
  }
  motor_of_link_.assign(static_cast<std::size_t>(n), -1);
  for (const Actuator& a : problem.actuators) {
    if (a.kind != ActuatorKind::hinge_torque)
      refuse(a.kind == ActuatorKind::body_torque ? "a body torque is given" : "a ball-joint torque is given");
    const int body = sys.joints()[static_cast<std::size_t>(a.index)].body_a;
    const int index = layout_.controls_begin() + static_cast<int>(controls_.size());
    motor_of_link_[static_cast<std::size_t>(body)] = index;
    controls_.push_back(index);
    bounds_.push_back(a.torque_max);
  }
  // ẏ = (q̇, ν̇): ė = ½ e ⊗ (0, ω₀) = ½ (−ē·ω₀, e₀ ω₀ + ē × ω₀) for a floating base, θ̇ for the hinges.
  if (layout_.floating) {
    const int om = layout_.omega();
    const int r0 = rhs_.add_row();
    for (int k = 0; k < 3; ++k)
      rhs_.add_bilinear(r0, 1 + k, om + k, -0.5);
    for (int k = 0; k < 3; ++k) {
      const int r = rhs_.add_row();
      const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      rhs_.add_bilinear(r, 0, om + k, 0.5);
      rhs_.add_bilinear(r, 1 + k1, om + k2, 0.5);
      rhs_.add_bilinear(r, 1 + k2, om + k1, -0.5);
    }
  }
  for (int i = layout_.first_link(); i < n; ++i)
    rhs_.add_linear(rhs_.add_row(), layout_.rate(i), 1.0);
  for (int r = 0; r < layout_.velocities(); ++r)
    rhs_.add_linear(rhs_.add_row(), layout_.omega_dot() + r, 1.0);
  rhs_.finish();
  path_ = std::make_unique<MinimalInverseDynamicsRows>(tree_, layout_, motor_of_link_, point_size());
}

void MultibodyMinimalModel::variable_bounds(bool, double* lower, double* upper) const {
  for (int i = 0; i < point_size(); ++i) {
    lower[i] = -1e20;
    upper[i] = 1e20;
  }
  for (std::size_t k = 0; k < controls_.size(); ++k) {
    lower[controls_[k]] = -std::min(bounds_[k], 1e20);
    upper[controls_[k]] = std::min(bounds_[k], 1e20);
  }
}

Eigen::VectorXd MultibodyMinimalModel::state_vector(const multibody::State& state) const {
  Eigen::VectorXd y(state_size());
  if (layout_.floating) {
    const Eigen::Quaterniond e(state.bodies[0].R_space_body);
    Eigen::Vector4d v(e.w(), e.x(), e.y(), e.z());
    if (v.dot(sign_reference_) < 0.0) v = -v;
    y.head<4>() = v;
    y.segment<3>(layout_.omega()) = state.bodies[0].omega_body;
  }
  for (int i = layout_.first_link(); i < static_cast<int>(tree_.links.size()); ++i) {
    const HingeTree::Link& L = tree_.links[static_cast<std::size_t>(i)];
    const multibody::BodyState& b = state.bodies[static_cast<std::size_t>(i)];
    const bool world = L.parent == multibody::kWorld;
    const Mat3 Rp = world ? Mat3::Identity() : state.bodies[static_cast<std::size_t>(L.parent)].R_space_body;
    const Vec3 omp = world ? Vec3::Zero() : state.bodies[static_cast<std::size_t>(L.parent)].omega_body;
    const Mat3 E = Rp.transpose() * b.R_space_body;
    const Mat3 D = L.C.transpose() * E;  // Rot(n, θ)
    const Vec3 s(D(2, 1) - D(1, 2), D(0, 2) - D(2, 0), D(1, 0) - D(0, 1));
    y(layout_.angle(i)) = std::atan2(0.5 * L.axis.dot(s), 0.5 * (D.trace() - 1.0));
    y(layout_.rate(i)) = L.axis.dot(b.omega_body - E.transpose() * omp);
  }
  return y;
}

multibody::State MultibodyMinimalModel::state_of(const double* w, double time) const {
  const auto n = tree_.links.size();
  multibody::State s;
  s.time = time;
  s.bodies.resize(n);
  if (layout_.floating) {  // the base at the origin, at rest; shifted below
    s.bodies[0].R_space_body = minimal_quaternion_rotation(w);
    s.bodies[0].omega_body = Vec3(w[layout_.omega()], w[layout_.omega() + 1], w[layout_.omega() + 2]);
  }
  for (int i = layout_.first_link(); i < static_cast<int>(n); ++i) {
    const HingeTree::Link& L = tree_.links[static_cast<std::size_t>(i)];
    const bool world = L.parent == multibody::kWorld;
    const multibody::BodyState parent =
        world ? multibody::BodyState{} : s.bodies[static_cast<std::size_t>(L.parent)];
    const Mat3 E = L.C * minimal_axis_rotation(L.axis, w[layout_.angle(i)]);
    multibody::BodyState& b = s.bodies[static_cast<std::size_t>(i)];
    b.R_space_body = parent.R_space_body * E;
    b.omega_body = E.transpose() * parent.omega_body + L.axis * w[layout_.rate(i)];
    b.x_space = parent.x_space + parent.R_space_body * L.B - b.R_space_body * L.A;
    b.v_space = parent.v_space + parent.R_space_body * parent.omega_body.cross(L.B) -
                b.R_space_body * b.omega_body.cross(L.A);
  }
  if (layout_.floating) {  // x_com at its place, P = 0
    Vec3 x = Vec3::Zero(), v = Vec3::Zero();
    double mass = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      x += tree_.links[i].mass * s.bodies[i].x_space;
      v += tree_.links[i].mass * s.bodies[i].v_space;
      mass += tree_.links[i].mass;
    }
    for (multibody::BodyState& b : s.bodies) {
      b.x_space += com_space_ - x / mass;
      b.v_space -= v / mass;
    }
  }
  return s;
}

void MultibodyMinimalModel::equations_of_motion(const Eigen::VectorXd& y, const Eigen::VectorXd& u,
                                                Eigen::MatrixXd& mass, Eigen::VectorXd& bias) const {
  // The rows are affine in ν̇: rows(y, ν̇, u) = M ν̇ + c − B u.
  Eigen::VectorXd w = Eigen::VectorXd::Zero(point_size());
  w.head(state_size()) = y;
  for (std::size_t k = 0; k < controls_.size(); ++k)
    w(controls_[k]) = u(static_cast<Eigen::Index>(k));
  const int nv = layout_.velocities();
  bias.resize(nv);
  path_->values(w.data(), bias.data());
  mass.resize(nv, nv);
  Eigen::VectorXd column(nv);
  for (int j = 0; j < nv; ++j) {
    w(layout_.omega_dot() + j) = 1.0;
    path_->values(w.data(), column.data());
    mass.col(j) = column - bias;
    w(layout_.omega_dot() + j) = 0.0;
  }
}

Eigen::VectorXd MultibodyMinimalModel::state_derivative(const Eigen::VectorXd& y,
                                                        const Eigen::VectorXd& u) const {
  Eigen::MatrixXd mass;
  Eigen::VectorXd bias;
  equations_of_motion(y, u, mass, bias);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(point_size());
  w.head(state_size()) = y;
  w.segment(layout_.omega_dot(), layout_.velocities()) = mass.llt().solve(-bias);
  Eigen::VectorXd ydot(state_size());
  rhs_.values(w.data(), ydot.data());
  return ydot;
}

Eigen::MatrixXd MultibodyMinimalModel::local_coordinates(const Eigen::VectorXd& y) const {
  const int n = state_size();
  if (!layout_.floating) return Eigen::MatrixXd::Identity(n, n);
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(n - 1, n);
  F.topLeftCorner(3, 4) = null_space(y.head<4>().transpose()).transpose();
  F.bottomRightCorner(n - 4, n - 4).setIdentity();
  return F;
}

}  // namespace poinsot::optimal::detail
