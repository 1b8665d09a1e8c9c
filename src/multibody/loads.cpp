// Applied loads and potential energy (loads.hpp).
#include "poinsot/multibody/loads.hpp"

#include <cmath>

#include "poinsot/multibody/constraints.hpp"
#include "poinsot/so3/hat.hpp"

namespace poinsot::multibody {
namespace {

void add_point_force(BodyLoads& loads, const BodyState& s, const Vec3& f_space, const Vec3& X_body) {
  const Vec3 f_body = s.R_space_body.transpose() * f_space;
  loads.force_space += f_space;
  loads.torque_body += X_body.cross(f_body);
  loads.phi_body += f_body * X_body.transpose();
}

}  // namespace

void applied_loads(const System& system, const std::vector<BodyState>& bodies, std::vector<BodyLoads>& out) {
  const auto n = static_cast<std::size_t>(system.body_count());
  out.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    out[i] = BodyLoads{};
    out[i].force_space = system.bodies()[i].mass * system.gravity();
  }
  for (const ConstantForce& f : system.forces()) {
    const auto i = static_cast<std::size_t>(f.body);
    add_point_force(out[i], bodies[i], f.force_space, f.point_body);
  }
  for (const ConstantTorque& t : system.torques()) {
    const auto i = static_cast<std::size_t>(t.body);
    const Vec3 tau_body = t.in_body_frame ? t.torque : Vec3(bodies[i].R_space_body.transpose() * t.torque);
    out[i].torque_body += tau_body;
    out[i].phi_body += 0.5 * so3::hat(tau_body);
  }
  for (const Spring& s : system.springs()) {
    const BodyState& a = side_state(bodies, s.body_a);
    const BodyState& b = side_state(bodies, s.body_b);
    const Vec3 ra = a.R_space_body * s.point_a;
    const Vec3 rb = b.R_space_body * s.point_b;
    const Vec3 d = a.x_space + ra - b.x_space - rb;
    const double length = d.norm();
    const Vec3 d_dot = a.v_space + a.R_space_body * a.omega_body.cross(s.point_a) - b.v_space -
                       b.R_space_body * b.omega_body.cross(s.point_b);
    Vec3 f_a = Vec3::Zero();
    if (length > 0.0) {
      const Vec3 e = d / length;
      f_a = -(s.stiffness * (length - s.rest_length) + s.damping * e.dot(d_dot)) * e;
    } else if (s.rest_length == 0.0) {
      f_a = -s.damping * d_dot;  // ℓ = ℓ₀ = 0: no elastic force, damping along the relative velocity
    }
    add_point_force(out[static_cast<std::size_t>(s.body_a)], a, f_a, s.point_a);
    if (s.body_b != kWorld) add_point_force(out[static_cast<std::size_t>(s.body_b)], b, -f_a, s.point_b);
  }
}

double potential_energy(const System& system, const std::vector<BodyState>& bodies) {
  double V = 0.0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    V -= system.bodies()[i].mass * system.gravity().dot(bodies[i].x_space);
  }
  for (const ConstantForce& f : system.forces()) {
    const BodyState& s = bodies[static_cast<std::size_t>(f.body)];
    V -= f.force_space.dot(s.x_space + s.R_space_body * f.point_body);
  }
  for (const Spring& s : system.springs()) {
    const BodyState& a = side_state(bodies, s.body_a);
    const BodyState& b = side_state(bodies, s.body_b);
    const double length =
        (a.x_space + a.R_space_body * s.point_a - b.x_space - b.R_space_body * s.point_b).norm();
    V += 0.5 * s.stiffness * (length - s.rest_length) * (length - s.rest_length);
  }
  return V;
}

}  // namespace poinsot::multibody
