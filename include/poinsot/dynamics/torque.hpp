#pragma once
/// @file torque.hpp
/// External torques on the body, about its rotation point, returned in the body frame (N·m).
///
/// Euler's equations `J ω̇ + ω × J ω = τ_body(t, R, ω)`. Every model states whether it depends on ω (the
/// splitting and variational integrators apply torques as symmetric kicks and need to know) and whether it is
/// zero (the exact solution refuses any other).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/rigid_body.hpp"

namespace poinsot::dynamics {

class TorqueModel {
 public:
  virtual ~TorqueModel() = default;
  /// τ in the body frame (N·m) at time t (s), attitude R (body → space) and body angular velocity ω (rad/s).
  virtual Vec3 torque_body(double t, const Mat3& R, const Vec3& omega_body) const = 0;
  /// True for the zero torque (torque-free motion).
  virtual bool is_zero() const { return false; }
  /// True when τ depends on ω (a user callback may; none of the built-in models does).
  virtual bool depends_on_omega() const { return false; }
  /// True when τ derives from the potential V(R) = −m gᵀ R d (uniform gravity about a pivot).
  virtual bool is_gravity() const { return false; }
  /// The gravity vector (space frame, m/s²) of a gravity model; zero otherwise.
  virtual Vec3 gravity_space() const { return Vec3::Zero(); }
  /// A short description for reports: "none", "body (0, 0, 0.1) N·m", "gravity (0, 0, -9.81) m/s²", ...
  virtual std::string describe() const = 0;
  /// Times (s, ascending) where τ(t) jumps or has a kink (a tabulated torque); empty for smooth models. The
  /// simulation driver ends a step at each of them, so that no step straddles one.
  virtual std::vector<double> breakpoints() const { return {}; }
  /// Called by the simulation driver before each step with the step's start time (s), for models with
  /// breakpoints: every stage of the step, including one exactly at a breakpoint ending it, then evaluates
  /// the piece the step lies in. Smooth models ignore it.
  virtual void enter_interval(double /*t_begin*/) const {}

  /// No torque.
  static std::shared_ptr<const TorqueModel> none();
  /// A constant torque fixed in the body frame (N·m).
  static std::shared_ptr<const TorqueModel> constant_body(const Vec3& torque_body);
  /// A constant torque fixed in space (N·m); τ_body = Rᵀ τ_space.
  static std::shared_ptr<const TorqueModel> constant_space(const Vec3& torque_space);
  /// Uniform gravity g (space frame, m/s²) on a body with a pivot: τ_body = m d × (Rᵀ g). Throws InvalidInput
  /// if the body has no pivot (RigidBody::with_pivot).
  static std::shared_ptr<const TorqueModel> gravity(const RigidBody& body, const Vec3& g_space);
  /// A user callback τ_body = f(t, R, ω). `depends_on_omega` tells the integrators whether f reads ω.
  using Callback = std::function<Vec3(double t, const Mat3& R, const Vec3& omega_body)>;
  static std::shared_ptr<const TorqueModel> callback(Callback f, bool depends_on_omega = true,
                                                     std::string description = "user callback");
};

}  // namespace poinsot::dynamics
