#include "poinsot/dynamics/torque.hpp"

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"

namespace poinsot::dynamics {
namespace {

class NoTorque final : public TorqueModel {
 public:
  Vec3 torque_body(double, const Mat3&, const Vec3&) const override { return Vec3::Zero(); }
  bool is_zero() const override { return true; }
  std::string describe() const override { return "none"; }
};

class ConstantBodyTorque final : public TorqueModel {
 public:
  explicit ConstantBodyTorque(const Vec3& tau) : tau_(tau) {}
  Vec3 torque_body(double, const Mat3&, const Vec3&) const override { return tau_; }
  std::string describe() const override {
    return fmt::format("constant in body {} N·m", format_vector(tau_));
  }

 private:
  Vec3 tau_;
};

class ConstantSpaceTorque final : public TorqueModel {
 public:
  explicit ConstantSpaceTorque(const Vec3& tau) : tau_(tau) {}
  Vec3 torque_body(double, const Mat3& R, const Vec3&) const override { return R.transpose() * tau_; }
  std::string describe() const override {
    return fmt::format("constant in space {} N·m", format_vector(tau_));
  }

 private:
  Vec3 tau_;
};

/// τ_body = m d × (Rᵀ g): the moment about the pivot of the weight m g applied at the centre of mass.
class GravityTorque final : public TorqueModel {
 public:
  GravityTorque(double mass, const Vec3& d, const Vec3& g) : m_d_(mass * d), g_(g) {}
  Vec3 torque_body(double, const Mat3& R, const Vec3&) const override {
    return m_d_.cross(R.transpose() * g_);
  }
  bool is_gravity() const override { return true; }
  Vec3 gravity_space() const override { return g_; }
  std::string describe() const override { return fmt::format("gravity {} m/s²", format_vector(g_)); }

 private:
  Vec3 m_d_;
  Vec3 g_;
};

class CallbackTorque final : public TorqueModel {
 public:
  CallbackTorque(Callback f, bool depends_on_omega, std::string description)
      : f_(std::move(f)), depends_on_omega_(depends_on_omega), description_(std::move(description)) {}
  Vec3 torque_body(double t, const Mat3& R, const Vec3& w) const override { return f_(t, R, w); }
  bool depends_on_omega() const override { return depends_on_omega_; }
  std::string describe() const override { return description_; }

 private:
  Callback f_;
  bool depends_on_omega_;
  std::string description_;
};

}  // namespace

std::shared_ptr<const TorqueModel> TorqueModel::none() {
  return std::make_shared<NoTorque>();
}

std::shared_ptr<const TorqueModel> TorqueModel::constant_body(const Vec3& torque_body) {
  require_finite("torque: value (N·m, body frame)", torque_body);
  return std::make_shared<ConstantBodyTorque>(torque_body);
}

std::shared_ptr<const TorqueModel> TorqueModel::constant_space(const Vec3& torque_space) {
  require_finite("torque: value (N·m, space frame)", torque_space);
  return std::make_shared<ConstantSpaceTorque>(torque_space);
}

std::shared_ptr<const TorqueModel> TorqueModel::gravity(const RigidBody& body, const Vec3& g_space) {
  require_finite("torque: g (m/s²)", g_space);
  if (!body.has_pivot()) {
    throw InvalidInput("torque: gravity needs a body with a pivot; expected body.mass and body.pivot_to_com");
  }
  return std::make_shared<GravityTorque>(body.mass(), body.pivot_to_com(), g_space);
}

std::shared_ptr<const TorqueModel> TorqueModel::callback(Callback f, bool depends_on_omega,
                                                         std::string description) {
  if (!f) throw InvalidInput("torque: callback is empty; expected a callable tau(t, R, omega)");
  return std::make_shared<CallbackTorque>(std::move(f), depends_on_omega, std::move(description));
}

}  // namespace poinsot::dynamics
