// The minimal-coordinate point model of a multibody problem (multibody_minimal_model.hpp).
#include "multibody_minimal_model.hpp"

#include <cmath>

#include <fmt/format.h>
#include <unsupported/Eigen/AutoDiff>

#include "poinsot/core/error.hpp"
#include "poinsot/so3/hat.hpp"

namespace poinsot::optimal::detail {
namespace {

using Der1 = Eigen::VectorXd;
using AD1 = Eigen::AutoDiffScalar<Der1>;
using Der2 = Eigen::Matrix<AD1, Eigen::Dynamic, 1>;
using AD2 = Eigen::AutoDiffScalar<Der2>;

/// The rows (R_i n_i)·n_i − u_i of the recursive Newton–Euler inverse dynamics at w = (θ, θ̇, θ̈, u), for
/// any scalar type (double, or first- and second-order automatic differentiation).
template <class S>
void inverse_dynamics_rows(const HingeTree& tree, const std::vector<int>& motor, const S* w, S* out) {
  using V3 = Eigen::Matrix<S, 3, 1>;
  using M3 = Eigen::Matrix<S, 3, 3>;
  const int n = static_cast<int>(tree.links.size());
  std::vector<M3> R(static_cast<std::size_t>(n));
  std::vector<V3> om(R.size()), dom(R.size()), acc(R.size()), f(R.size()), couple(R.size());
  const V3 zero = V3::Constant(S(0.0));
  const M3 eye = Mat3::Identity().cast<S>();
  for (int i = 0; i < n; ++i) {
    const auto iu = static_cast<std::size_t>(i);
    const HingeTree::Link& L = tree.links[iu];
    const S& th = w[i];
    const S& dth = w[n + i];
    const S& ddth = w[2 * n + i];
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
    f[iu] = zero;
    couple[iu] = zero;
  }
  for (int i = n - 1; i >= 0; --i) {
    const auto iu = static_cast<std::size_t>(i);
    const HingeTree::Link& L = tree.links[iu];
    const M3 J = L.J.cast<S>();
    f[iu] += (acc[iu] - tree.gravity.cast<S>()) * S(L.mass);
    couple[iu] += R[iu] * (J * dom[iu] + om[iu].cross(J * om[iu])) - (R[iu] * L.A.cast<S>()).cross(f[iu]);
    if (L.parent != multibody::kWorld) {
      const auto p = static_cast<std::size_t>(L.parent);
      f[p] += f[iu];
      couple[p] += couple[iu] + (R[p] * L.B.cast<S>()).cross(f[iu]);
    }
    out[i] = (R[iu] * L.axis.cast<S>()).dot(couple[iu]);
    if (motor[iu] >= 0) out[i] -= w[motor[iu]];
  }
}

/// The inverse-dynamics rows with their derivatives by forward automatic differentiation.
class InverseDynamicsRows final : public PointFunctions {
 public:
  InverseDynamicsRows(const HingeTree& tree, std::vector<int> motor, int point_size)
      : tree_(tree), motor_(std::move(motor)), nw_(point_size) {
    const int n = static_cast<int>(tree_.links.size());
    for (int r = 0; r < n; ++r) {
      for (int v = 0; v < 3 * n; ++v)
        jac_.push_back({r, v});
      if (motor_[static_cast<std::size_t>(r)] >= 0) jac_.push_back({r, motor_[static_cast<std::size_t>(r)]});
    }
    for (int i = 0; i < 3 * n; ++i)
      for (int j = 0; j <= i; ++j)
        hess_.push_back({i, j});
  }
  int rows() const override { return static_cast<int>(tree_.links.size()); }
  void values(const double* w, double* out) const override {
    inverse_dynamics_rows<double>(tree_, motor_, w, out);
  }
  const std::vector<IndexPair>& jacobian_pattern() const override { return jac_; }
  void jacobian_values(const double* w, double* values) const override {
    std::vector<AD1> x(static_cast<std::size_t>(nw_)), out(static_cast<std::size_t>(rows()));
    for (int i = 0; i < nw_; ++i)
      x[static_cast<std::size_t>(i)] = AD1(w[i], nw_, i);
    inverse_dynamics_rows<AD1>(tree_, motor_, x.data(), out.data());
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
    inverse_dynamics_rows<AD2>(tree_, motor_, x.data(), out.data());
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
  std::vector<int> motor_;
  int nw_;
  std::vector<IndexPair> jac_, hess_;
};

Mat3 axis_rotation(const Vec3& axis, double angle) {
  const Mat3 K = so3::hat(axis);
  return Mat3::Identity() + std::sin(angle) * K + (1.0 - std::cos(angle)) * K * K;
}

}  // namespace

MultibodyMinimalModel::MultibodyMinimalModel(const MultibodyProblem& problem) {
  const multibody::System& sys = problem.system;
  n_ = sys.body_count();
  const auto refuse = [](const std::string& why) {
    throw InvalidInput(fmt::format(
        "optimal control: coordinates = \"minimal\": {}; expected a tree of hinges rooted at the world "
        "(each body the body_a of one hinge, its body_b the world or a body of lower index) with hinge "
        "motors only",
        why));
  };
  if (!sys.forces().empty() || !sys.torques().empty()) refuse("the system has constant forces or torques");
  tree_.links.resize(static_cast<std::size_t>(n_));
  tree_.gravity = sys.gravity();
  std::vector<int> hinge_of(static_cast<std::size_t>(n_), -1);
  for (int ji = 0; ji < sys.joint_count(); ++ji) {
    const multibody::Joint& j = sys.joints()[static_cast<std::size_t>(ji)];
    if (j.type != multibody::JointType::hinge) refuse(fmt::format("joint '{}' is not a hinge", j.name));
    if (hinge_of[static_cast<std::size_t>(j.body_a)] >= 0 || j.body_b >= j.body_a)
      refuse(fmt::format("joint '{}' does not hang body_a from the world or a body of lower index", j.name));
    hinge_of[static_cast<std::size_t>(j.body_a)] = ji;
  }
  for (int i = 0; i < n_; ++i) {
    const int ji = hinge_of[static_cast<std::size_t>(i)];
    if (ji < 0)
      refuse(fmt::format("body '{}' hangs from no hinge", sys.bodies()[static_cast<std::size_t>(i)].name));
    const multibody::Joint& j = sys.joints()[static_cast<std::size_t>(ji)];
    HingeTree::Link& L = tree_.links[static_cast<std::size_t>(i)];
    const auto& s0 = problem.initial_state.bodies;
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
  motor_of_link_.assign(static_cast<std::size_t>(n_), -1);
  for (const Actuator& a : problem.actuators) {
    if (a.kind != ActuatorKind::hinge_torque)
      refuse(a.kind == ActuatorKind::body_torque ? "a body torque is given" : "a ball-joint torque is given");
    const int body = sys.joints()[static_cast<std::size_t>(a.index)].body_a;
    motor_of_link_[static_cast<std::size_t>(body)] = 3 * n_ + static_cast<int>(controls_.size());
    controls_.push_back(3 * n_ + static_cast<int>(controls_.size()));
    bounds_.push_back(a.torque_max);
  }
  for (int r = 0; r < 2 * n_; ++r)
    rhs_.add_linear(rhs_.add_row(), n_ + r, 1.0);
  rhs_.finish();
  path_ = std::make_unique<InverseDynamicsRows>(tree_, motor_of_link_, point_size());
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
  Eigen::VectorXd y(2 * n_);
  for (int i = 0; i < n_; ++i) {
    const HingeTree::Link& L = tree_.links[static_cast<std::size_t>(i)];
    const multibody::BodyState& b = state.bodies[static_cast<std::size_t>(i)];
    const bool world = L.parent == multibody::kWorld;
    const Mat3 Rp = world ? Mat3::Identity() : state.bodies[static_cast<std::size_t>(L.parent)].R_space_body;
    const Vec3 omp = world ? Vec3::Zero() : state.bodies[static_cast<std::size_t>(L.parent)].omega_body;
    const Mat3 E = Rp.transpose() * b.R_space_body;
    const Mat3 D = L.C.transpose() * E;  // Rot(n, θ)
    const Vec3 s(D(2, 1) - D(1, 2), D(0, 2) - D(2, 0), D(1, 0) - D(0, 1));
    y(i) = std::atan2(0.5 * L.axis.dot(s), 0.5 * (D.trace() - 1.0));
    y(n_ + i) = L.axis.dot(b.omega_body - E.transpose() * omp);
  }
  return y;
}

multibody::State MultibodyMinimalModel::state_of(const double* w, double time) const {
  multibody::State s;
  s.time = time;
  s.bodies.resize(static_cast<std::size_t>(n_));
  for (int i = 0; i < n_; ++i) {
    const HingeTree::Link& L = tree_.links[static_cast<std::size_t>(i)];
    const bool world = L.parent == multibody::kWorld;
    const multibody::BodyState parent =
        world ? multibody::BodyState{} : s.bodies[static_cast<std::size_t>(L.parent)];
    const Mat3 E = L.C * axis_rotation(L.axis, w[i]);
    multibody::BodyState& b = s.bodies[static_cast<std::size_t>(i)];
    b.R_space_body = parent.R_space_body * E;
    b.omega_body = E.transpose() * parent.omega_body + L.axis * w[n_ + i];
    b.x_space = parent.x_space + parent.R_space_body * L.B - b.R_space_body * L.A;
    b.v_space = parent.v_space + parent.R_space_body * parent.omega_body.cross(L.B) -
                b.R_space_body * b.omega_body.cross(L.A);
  }
  return s;
}

}  // namespace poinsot::optimal::detail
