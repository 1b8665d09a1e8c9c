// The minimal-coordinate point model of a multibody problem (multibody_minimal_model.hpp).
#include "multibody_minimal_model.hpp"

#include <algorithm>
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
void minimal_inverse_dynamics_rows(const MinimalTree& tree, const S* w, S* out) {
  using V3 = Eigen::Matrix<S, 3, 1>;
  using M3 = Eigen::Matrix<S, 3, 3>;
  const int n = static_cast<int>(tree.links.size());
  const int accelerations =
      tree.positions + tree.velocities;  // ν̇ = w[accelerations + (ν's index − positions)]
  const auto vec3 = [&](int i) { return V3(w[i], w[i + 1], w[i + 2]); };
  std::vector<M3> R(static_cast<std::size_t>(n));
  std::vector<V3> om(R.size()), dom(R.size()), acc(R.size()), f(R.size()), couple(R.size());
  const V3 zero = V3::Constant(S(0.0));
  const M3 eye = Mat3::Identity().cast<S>();
  if (tree.floating) {
    R[0] = minimal_quaternion_rotation(w);
    om[0] = vec3(tree.positions);
    dom[0] = vec3(accelerations);
    acc[0] = zero;  // shifted below by the centre of mass's acceleration
  }
  for (int i = tree.first_link(); i < n; ++i) {
    const auto iu = static_cast<std::size_t>(i);
    const MinimalTree::Link& L = tree.links[iu];
    M3 E;
    V3 rv, ra;  // ν_i and ν̇_i, body i's frame
    if (L.ball) {
      E = L.C.cast<S>() * minimal_quaternion_rotation(w + L.q);
      rv = vec3(L.v);
      ra = vec3(L.v - tree.positions + accelerations);
    } else {
      const M3 K = so3::hat(L.axis).cast<S>();
      const S& th = w[L.q];
      E = L.C.cast<S>() * (eye + K * sin(th) + (K * K) * (S(1.0) - cos(th)));
      rv = L.axis.cast<S>() * w[L.v];
      ra = L.axis.cast<S>() * w[L.v - tree.positions + accelerations];
    }
    const V3 A = L.A.cast<S>(), B = L.B.cast<S>();
    const bool world = L.parent == multibody::kWorld;
    const auto p = static_cast<std::size_t>(std::max(L.parent, 0));
    const M3 Rp = world ? eye : R[p];
    const V3 omp = world ? zero : om[p], domp = world ? zero : dom[p], ap = world ? zero : acc[p];
    R[iu] = Rp * E;
    om[iu] = E.transpose() * omp + rv;
    dom[iu] = E.transpose() * domp + ra + om[iu].cross(rv);
    acc[iu] = ap + Rp * (domp.cross(B) + omp.cross(omp.cross(B))) -
              R[iu] * (dom[iu].cross(A) + om[iu].cross(om[iu].cross(A)));
  }
  if (tree.floating) {  // the centre of mass does not accelerate: Σ m_i a_i = 0
    V3 moment = zero;
    double mass = 0.0;
    for (const MinimalTree::Link& L : tree.links)
      mass += L.mass;
    for (int i = 0; i < n; ++i)
      moment += acc[static_cast<std::size_t>(i)] * S(tree.links[static_cast<std::size_t>(i)].mass / mass);
    for (V3& a : acc)
      a -= moment;
  }
  for (int i = 0; i < n; ++i) {
    f[static_cast<std::size_t>(i)] = zero;
    couple[static_cast<std::size_t>(i)] = zero;
  }
  for (int i = n - 1; i >= 0; --i) {
    const auto iu = static_cast<std::size_t>(i);
    const MinimalTree::Link& L = tree.links[iu];
    const M3 J = L.J.cast<S>();
    f[iu] += (acc[iu] - tree.gravity.cast<S>()) * S(L.mass);
    couple[iu] += R[iu] * (J * dom[iu] + om[iu].cross(J * om[iu])) - (R[iu] * L.A.cast<S>()).cross(f[iu]);
    if (i < tree.first_link()) {  // the floating base: the total angular momentum's rate, base frame
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
    if (L.ball) {  // body i's frame: the generalised force dual to ν_i
      V3 c = couple[iu];
      if (L.motor >= 0) c -= vec3(L.motor) * S(L.motor_sign);
      const V3 body = R[iu].transpose() * c;
      for (int k = 0; k < 3; ++k)
        out[L.row + k] = body(k);
    } else {
      out[L.row] = (R[iu] * L.axis.cast<S>()).dot(couple[iu]);
      if (L.motor >= 0) out[L.row] -= w[L.motor] * S(L.motor_sign);
    }
  }
}

/// The inverse-dynamics rows with their derivatives by forward automatic differentiation.
class MinimalInverseDynamicsRows final : public PointFunctions {
 public:
  MinimalInverseDynamicsRows(const MinimalTree& tree, int point_size) : tree_(tree), nw_(point_size) {
    const int dense = tree_.positions + 2 * tree_.velocities;
    for (int r = 0; r < rows(); ++r)
      for (int v = 0; v < dense; ++v)
        jac_.push_back({r, v});
    for (const MinimalTree::Link& L : tree_.links) {
      if (L.motor < 0) continue;
      if (!L.ball) {
        jac_.push_back({L.row, L.motor});
        continue;
      }
      for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k)
          jac_.push_back({L.row + r, L.motor + k});
    }
    for (int i = 0; i < dense; ++i)
      for (int j = 0; j <= i; ++j)
        hess_.push_back({i, j});
    // A ball's row R_iᵀ τ is bilinear in its motor's torque and the positions.
    for (const MinimalTree::Link& L : tree_.links)
      if (L.ball && L.motor >= 0)
        for (int k = 0; k < 3; ++k)
          for (int j = 0; j < tree_.positions; ++j)
            hess_.push_back({L.motor + k, j});
  }
  int rows() const override { return tree_.rows; }
  void values(const double* w, double* out) const override {
    minimal_inverse_dynamics_rows<double>(tree_, w, out);
  }
  const std::vector<IndexPair>& jacobian_pattern() const override { return jac_; }
  void jacobian_values(const double* w, double* values) const override {
    std::vector<AD1> x(static_cast<std::size_t>(nw_)), out(static_cast<std::size_t>(rows()));
    for (int i = 0; i < nw_; ++i)
      x[static_cast<std::size_t>(i)] = AD1(w[i], nw_, i);
    minimal_inverse_dynamics_rows<AD1>(tree_, x.data(), out.data());
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
    minimal_inverse_dynamics_rows<AD2>(tree_, x.data(), out.data());
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
  const MinimalTree& tree_;
  int nw_;
  std::vector<IndexPair> jac_, hess_;
};

Mat3 minimal_axis_rotation(const Vec3& axis, double angle) {
  const Mat3 K = so3::hat(axis);
  return Mat3::Identity() + std::sin(angle) * K + (1.0 - std::cos(angle)) * K * K;
}

/// The rows ė = ½ e ⊗ (0, ω) = ½ (−ē·ω, e₀ ω + ē × ω) for e at w[e..e+4) and ω at w[omega..omega+3).
void add_minimal_quaternion_rate(QuadraticFunctions& rhs, int e, int omega) {
  const int r0 = rhs.add_row();
  for (int k = 0; k < 3; ++k)
    rhs.add_bilinear(r0, e + 1 + k, omega + k, -0.5);
  for (int k = 0; k < 3; ++k) {
    const int r = rhs.add_row();
    const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    rhs.add_bilinear(r, e, omega + k, 0.5);
    rhs.add_bilinear(r, e + 1 + k1, omega + k2, 0.5);
    rhs.add_bilinear(r, e + 1 + k2, omega + k1, -0.5);
  }
}

/// The quaternion (e₀, ē) of the rotation R, of the sign nearest `reference`.
Eigen::Vector4d minimal_quaternion_of(const Mat3& R, const Eigen::Vector4d& reference) {
  const Eigen::Quaterniond e(R);
  const Eigen::Vector4d v(e.w(), e.x(), e.y(), e.z());
  return v.dot(reference) < 0.0 ? Eigen::Vector4d(-v) : v;
}

}  // namespace

MultibodyMinimalModel::MultibodyMinimalModel(const MultibodyProblem& problem) {
  const multibody::System& sys = problem.system;
  const int n = sys.body_count();
  const auto refuse = [](const std::string& why) {
    throw InvalidInput(
        fmt::format("optimal control: coordinates = \"minimal\": {}; expected a tree of hinges and ball "
                    "joints (each body "
                    "the higher-indexed body of one joint, its other body the world or a body of lower "
                    "index, or body 0 a "
                    "floating base in no joint to the world) with hinge and ball motors only",
                    why));
  };
  if (!sys.forces().empty() || !sys.torques().empty()) refuse("the system has constant forces or torques");
  if (!problem.no_twist.empty()) refuse("a no-twist condition is given (rotation-matrix coordinates only)");
  tree_.links.resize(static_cast<std::size_t>(n));
  tree_.gravity = sys.gravity();
  std::vector<int> joint_of(static_cast<std::size_t>(n), -1);
  bool touches_world = false;
  for (int ji = 0; ji < sys.joint_count(); ++ji) {
    const multibody::Joint& j = sys.joints()[static_cast<std::size_t>(ji)];
    if (j.type != multibody::JointType::hinge && j.type != multibody::JointType::ball)
      refuse(fmt::format("joint '{}' is neither a hinge nor a ball joint", j.name));
    const auto child = static_cast<std::size_t>(std::max(j.body_a, j.body_b));
    if (joint_of[child] >= 0)
      refuse(fmt::format("body '{}' is the higher-indexed body of two joints", sys.bodies()[child].name));
    joint_of[child] = ji;
    touches_world = touches_world || j.body_b == multibody::kWorld;
  }
  const auto& s0 = problem.initial_state.bodies;
  tree_.floating = n > 0 && joint_of[0] < 0 && !touches_world;
  if (tree_.floating) {
    // The translation is eliminated by x_com = const, which needs P = 0 and no external force.
    if (sys.gravity().norm() != 0.0) {
      refuse(
          fmt::format("a floating base with gravity ({}, {}, {}) m/s²: its centre of mass would fall, "
                      "expected no gravity",
                      sys.gravity().x(), sys.gravity().y(), sys.gravity().z()));
    }
    const Vec3 P = multibody::linear_momentum(sys, problem.initial_state);
    double scale = 0.0, mass = 0.0;
    for (int i = 0; i < n; ++i) {
      const double m = sys.bodies()[static_cast<std::size_t>(i)].mass;
      scale += m * s0[static_cast<std::size_t>(i)].v_space.norm();
      com_space_ += m * s0[static_cast<std::size_t>(i)].x_space;
      mass += m;
    }
    if (P.norm() > 1e-9 * scale) {
      refuse(
          fmt::format("initial_state: a floating base with linear momentum |P| = {:.3g} kg·m/s, expected 0 "
                      "(the centre of mass at rest eliminates the translation)",
                      P.norm()));
    }
    com_space_ /= mass;
    sign_reference_ = minimal_quaternion_of(s0[0].R_space_body, Eigen::Vector4d::UnitX());
    MinimalTree::Link& base = tree_.links[0];
    base.mass = sys.bodies()[0].mass;
    base.J = sys.bodies()[0].inertia;
    base.A = Vec3::Zero();
  }
  // Positions first (the base's quaternion, then one angle or quaternion per joint), then velocities.
  tree_.positions = tree_.floating ? 4 : 0;
  tree_.velocities = tree_.floating ? 3 : 0;
  tree_.rows = tree_.floating ? 3 : 0;
  for (int i = tree_.first_link(); i < n; ++i) {
    const int ji = joint_of[static_cast<std::size_t>(i)];
    if (ji < 0)
      refuse(fmt::format("body '{}' hangs from no joint", sys.bodies()[static_cast<std::size_t>(i)].name));
    const multibody::Joint& j = sys.joints()[static_cast<std::size_t>(ji)];
    MinimalTree::Link& L = tree_.links[static_cast<std::size_t>(i)];
    const bool a_side = j.body_a == i;
    L.parent = a_side ? j.body_b : j.body_a;
    L.ball = j.type == multibody::JointType::ball;
    L.axis = a_side ? j.hinge_axis_a() : j.u_b[0];
    L.motor_sign = a_side ? 1.0 : -1.0;
    const Mat3 Rp = L.parent == multibody::kWorld ? Mat3::Identity()
                                                  : s0[static_cast<std::size_t>(L.parent)].R_space_body;
    L.C = Rp.transpose() * s0[static_cast<std::size_t>(i)].R_space_body;
    L.A = a_side ? j.point_a : j.point_b;
    L.B = a_side ? j.point_b : j.point_a;
    L.mass = sys.bodies()[static_cast<std::size_t>(i)].mass;
    L.J = sys.bodies()[static_cast<std::size_t>(i)].inertia;
    L.q = tree_.positions;
    tree_.positions += L.ball ? 4 : 1;
    L.row = tree_.rows;
    tree_.rows += L.ball ? 3 : 1;
  }
  for (int i = tree_.first_link(); i < n; ++i) {
    MinimalTree::Link& L = tree_.links[static_cast<std::size_t>(i)];
    L.v = tree_.positions + tree_.velocities;
    tree_.velocities += L.ball ? 3 : 1;
  }
  for (const Actuator& a : problem.actuators) {
    if (a.kind == ActuatorKind::body_torque) refuse("a body torque is given");
    const multibody::Joint& j = sys.joints()[static_cast<std::size_t>(a.index)];
    const int index = state_size() + tree_.velocities + static_cast<int>(controls_.size());
    tree_.links[static_cast<std::size_t>(std::max(j.body_a, j.body_b))].motor = index;
    for (int k = 0; k < a.controls(); ++k) {
      controls_.push_back(index + k);
      bounds_.push_back(a.torque_max);
    }
  }
  // ẏ = (q̇, ν̇): ė = ½ e ⊗ (0, ω) for each quaternion, θ̇ for each hinge.
  if (tree_.floating) add_minimal_quaternion_rate(rhs_, 0, tree_.positions);
  for (int i = tree_.first_link(); i < n; ++i) {
    const MinimalTree::Link& L = tree_.links[static_cast<std::size_t>(i)];
    if (L.ball)
      add_minimal_quaternion_rate(rhs_, L.q, L.v);
    else
      rhs_.add_linear(rhs_.add_row(), L.v, 1.0);
  }
  for (int r = 0; r < tree_.velocities; ++r)
    rhs_.add_linear(rhs_.add_row(), state_size() + r, 1.0);
  rhs_.finish();
  path_ = std::make_unique<MinimalInverseDynamicsRows>(tree_, point_size());
}

void MultibodyMinimalModel::variable_bounds(const PointRole&, double* lower, double* upper) const {
  for (int i = 0; i < point_size(); ++i) {
    lower[i] = -kNoBound;
    upper[i] = kNoBound;
  }
  for (std::size_t k = 0; k < controls_.size(); ++k) {
    lower[controls_[k]] = -std::min(bounds_[k], kNoBound);
    upper[controls_[k]] = std::min(bounds_[k], kNoBound);
  }
}

Eigen::VectorXd MultibodyMinimalModel::state_vector(const multibody::State& state) const {
  Eigen::VectorXd y(state_size());
  if (tree_.floating) {
    y.head<4>() = minimal_quaternion_of(state.bodies[0].R_space_body, sign_reference_);
    y.segment<3>(tree_.positions) = state.bodies[0].omega_body;
  }
  for (int i = tree_.first_link(); i < static_cast<int>(tree_.links.size()); ++i) {
    const MinimalTree::Link& L = tree_.links[static_cast<std::size_t>(i)];
    const multibody::BodyState& b = state.bodies[static_cast<std::size_t>(i)];
    const bool world = L.parent == multibody::kWorld;
    const Mat3 Rp = world ? Mat3::Identity() : state.bodies[static_cast<std::size_t>(L.parent)].R_space_body;
    const Vec3 omp = world ? Vec3::Zero() : state.bodies[static_cast<std::size_t>(L.parent)].omega_body;
    const Mat3 E = Rp.transpose() * b.R_space_body;
    const Mat3 D = L.C.transpose() * E;  // Rot(n, θ) or R(e)
    const Vec3 relative = b.omega_body - E.transpose() * omp;
    if (L.ball) {
      y.segment<4>(L.q) = minimal_quaternion_of(D, Eigen::Vector4d::UnitX());
      y.segment<3>(L.v) = relative;
      continue;
    }
    const Vec3 s(D(2, 1) - D(1, 2), D(0, 2) - D(2, 0), D(1, 0) - D(0, 1));
    y(L.q) = std::atan2(0.5 * L.axis.dot(s), 0.5 * (D.trace() - 1.0));
    y(L.v) = L.axis.dot(relative);
  }
  return y;
}

multibody::State MultibodyMinimalModel::state_of(const double* w, double time) const {
  const auto n = tree_.links.size();
  multibody::State s;
  s.time = time;
  s.bodies.resize(n);
  if (tree_.floating) {  // the base at the origin, at rest; shifted below
    s.bodies[0].R_space_body = minimal_quaternion_rotation(w);
    s.bodies[0].omega_body = Vec3(w[tree_.positions], w[tree_.positions + 1], w[tree_.positions + 2]);
  }
  for (int i = tree_.first_link(); i < static_cast<int>(n); ++i) {
    const MinimalTree::Link& L = tree_.links[static_cast<std::size_t>(i)];
    const bool world = L.parent == multibody::kWorld;
    const multibody::BodyState parent =
        world ? multibody::BodyState{} : s.bodies[static_cast<std::size_t>(L.parent)];
    const Mat3 E =
        L.C * (L.ball ? minimal_quaternion_rotation(w + L.q) : minimal_axis_rotation(L.axis, w[L.q]));
    const Vec3 relative = L.ball ? Vec3(w[L.v], w[L.v + 1], w[L.v + 2]) : Vec3(L.axis * w[L.v]);
    multibody::BodyState& b = s.bodies[static_cast<std::size_t>(i)];
    b.R_space_body = parent.R_space_body * E;
    b.omega_body = E.transpose() * parent.omega_body + relative;
    b.x_space = parent.x_space + parent.R_space_body * L.B - b.R_space_body * L.A;
    b.v_space = parent.v_space + parent.R_space_body * parent.omega_body.cross(L.B) -
                b.R_space_body * b.omega_body.cross(L.A);
  }
  if (tree_.floating) {  // x_com at its place, P = 0
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
  const int nv = tree_.velocities;
  bias.resize(nv);
  path_->values(w.data(), bias.data());
  mass.resize(nv, nv);
  Eigen::VectorXd column(nv);
  for (int j = 0; j < nv; ++j) {
    w(state_size() + j) = 1.0;
    path_->values(w.data(), column.data());
    mass.col(j) = column - bias;
    w(state_size() + j) = 0.0;
  }
}

Eigen::VectorXd MultibodyMinimalModel::state_derivative(const Eigen::VectorXd& y,
                                                        const Eigen::VectorXd& u) const {
  Eigen::MatrixXd mass;
  Eigen::VectorXd bias;
  equations_of_motion(y, u, mass, bias);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(point_size());
  w.head(state_size()) = y;
  w.segment(state_size(), tree_.velocities) = mass.llt().solve(-bias);
  Eigen::VectorXd ydot(state_size());
  rhs_.values(w.data(), ydot.data());
  return ydot;
}

Eigen::MatrixXd MultibodyMinimalModel::local_coordinates(const Eigen::VectorXd& y) const {
  std::vector<int> quaternions;
  if (tree_.floating) quaternions.push_back(0);
  for (const MinimalTree::Link& L : tree_.links)
    if (L.ball) quaternions.push_back(L.q);
  const int n = state_size();
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(n - static_cast<int>(quaternions.size()), n);
  int row = 0;
  for (int c = 0; c < n;) {
    if (std::find(quaternions.begin(), quaternions.end(), c) != quaternions.end()) {
      F.block(row, c, 3, 4) = null_space(y.segment<4>(c).transpose()).transpose();
      row += 3;
      c += 4;
      continue;
    }
    F(row++, c++) = 1.0;
  }
  return F;
}

}  // namespace poinsot::optimal::detail
