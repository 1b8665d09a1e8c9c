#pragma once
// Systems shared by the multibody tests: rods, chains, a body with a ball joint to the world.
#include <cmath>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/state.hpp"
#include "poinsot/so3/hat.hpp"
#include "poinsot_test.hpp"

namespace poinsot::multibody::test {

/// Long runs are shortened by this factor under the sanitizers (the instrumented library is many times
/// slower); the full-length figures are in docs/measurements/multibody.md, "Long runs".
inline int slowdown() {
  return ::poinsot::test::sanitized() ? 5 : 1;
}

/// prefix + index (avoids GCC 12's false -Wrestrict on "literal" + std::to_string).
inline std::string indexed(const char* prefix, int index) {
  std::string s(prefix);
  s.append(std::to_string(index));
  return s;
}

/// K about the centre of mass of a solid cylinder (mass m, length l along body x, radius r): ∫ρ X⊗X.
inline Mat3 rod_poinsot(double m, double l, double r) {
  return Vec3(m * l * l / 12.0, m * r * r / 4.0, m * r * r / 4.0).asDiagonal();
}

/// A chain of n rods (length l, mass m, radius r) along +x from the origin, the first hung from the world at
/// the origin by a ball joint, the others joined end to end; gravity −9.81 ẑ. At rest, horizontal.
inline System rod_chain(int n, double m = 1.0, double l = 1.0, double r = 0.01,
                        const Vec3& g = Vec3(0, 0, -9.81)) {
  System s;
  for (int i = 0; i < n; ++i)
    s.add_body(indexed("link", i), m, rod_poinsot(m, l, r));
  s.add_ball("pivot", 0, Vec3(-l / 2, 0, 0), kWorld, Vec3::Zero());
  for (int i = 1; i < n; ++i)
    s.add_ball(indexed("j", i), i, Vec3(-l / 2, 0, 0), i - 1, Vec3(l / 2, 0, 0));
  s.set_gravity(g);
  return s;
}

inline State rod_chain_state(int n, double l = 1.0) {
  State st;
  st.bodies.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    st.bodies[static_cast<std::size_t>(i)].x_space = Vec3((i + 0.5) * l, 0, 0);
  return st;
}

inline constexpr double kG = 9.81;  ///< m/s², the gravity of the fixtures below

/// A tree that is not a chain: three rods hung from the world (rod_chain(3)) and a fourth, the "arm", on a
/// hinge about y from link 1's point (0, 0.1, 0); at rest, horizontal. Solved by Baraff's tree order.
inline std::pair<System, State> hinge_tree() {
  System tree = rod_chain(3);
  tree.add_body("arm", 1.0, rod_poinsot(1.0, 1.0, 0.01));
  tree.add_hinge("h", 3, Vec3(-0.5, 0, 0), Vec3(0, 1, 0), 1, Vec3(0, 0.1, 0), Vec3(0, 1, 0));
  State st = rod_chain_state(3);
  st.bodies.push_back(BodyState{});
  st.bodies[3].x_space = Vec3(2.0, 0.1, 0);  // the arm's end at link 1's point (1.5, 0.1, 0)
  return {tree, st};
}

/// A spatial four-bar: three bars (1 m, 1 kg) joined by ball joints, both ends held at fixed points of the
/// world (a loop through the world: sparse LU), at rest, under an oblique gravity (0, −g, −3) m/s².
inline std::pair<System, State> four_bar_loop() {
  const double l = 1.0;
  System s;
  for (int i = 0; i < 3; ++i)
    s.add_body(indexed("bar", i), 1.0, rod_poinsot(1.0, l, 0.02));
  const Vec3 ends[4] = {Vec3(0, 0, 0), Vec3(0, -1, 0), Vec3(1, -1, 0),
                        Vec3(1 + std::sqrt(0.5), std::sqrt(0.5) - 1, 0)};
  s.add_ball("w0", 0, Vec3(-l / 2, 0, 0), kWorld, ends[0]);
  s.add_ball("j1", 1, Vec3(-l / 2, 0, 0), 0, Vec3(l / 2, 0, 0));
  s.add_ball("j2", 2, Vec3(-l / 2, 0, 0), 1, Vec3(l / 2, 0, 0));
  s.add_ball("w3", 2, Vec3(l / 2, 0, 0), kWorld, ends[3]);
  s.set_gravity(Vec3(0, -kG, -3.0));
  State st;
  st.bodies.resize(3);
  for (std::size_t i = 0; i < 3; ++i) {
    const Vec3 e = (ends[i + 1] - ends[i]).normalized();
    st.bodies[i].R_space_body = Eigen::Quaterniond::FromTwoVectors(Vec3::UnitX(), e).toRotationMatrix();
    st.bodies[i].x_space = 0.5 * (ends[i] + ends[i + 1]);
  }
  return {s, st};
}

/// A body of mass m on a spring of stiffness k (rest length 0) to the world origin, no gravity, released at
/// rest from x = −0.1 m: x(t) = −0.1 cos(√(k/m) t).
inline std::pair<System, State> spring_oscillator(double m, double k) {
  System s;
  s.add_body_from_inertia("mass", m, 0.01 * Mat3::Identity());
  s.add_spring({"spring", 0, kWorld, Vec3::Zero(), Vec3::Zero(), k, 0.0, 0.0});
  State st;
  st.bodies.resize(1);
  st.bodies[0].x_space = Vec3(-0.1, 0, 0);
  return {s, st};
}

// The heavy top: one body with a ball joint to the world, against an independent RK4 integration of Euler's
// equations about the pivot, J_p ω̇ + ω × J_p ω = d × m Rᵀg, Ṙ = R j(ω).
struct Top {
  double m = 2.0;
  Mat3 J_com = Vec3(0.10, 0.14, 0.17).asDiagonal();
  Vec3 A = Vec3(0, 0, -0.3);  // pivot in the body frame; d = −A from pivot to centre of mass
  Mat3 R0 = Eigen::AngleAxisd(0.4, Vec3(1, 0.2, 0).normalized()).toRotationMatrix();
  Vec3 omega0 = Vec3(0.5, -0.3, 3.0);
};

/// The top as a multibody system: one body with a ball joint to the world at its pivot, and its initial
/// state.
inline std::pair<System, State> top_system(const Top& top) {
  System s;
  s.add_body_from_inertia("top", top.m, top.J_com);
  s.add_ball("pivot", 0, top.A, kWorld, Vec3::Zero());
  s.set_gravity(Vec3(0, 0, -kG));
  State st;
  st.bodies.resize(1);
  st.bodies[0].R_space_body = top.R0;
  st.bodies[0].x_space = -top.R0 * top.A;
  st.bodies[0].omega_body = top.omega0;
  st.bodies[0].v_space = top.R0 * top.omega0.cross(-top.A);
  return {s, st};
}

inline std::pair<Mat3, Vec3> top_reference(const Top& top, double T, int steps) {
  const Vec3 d = -top.A;
  const Mat3 Jp = top.J_com + top.m * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
  const Mat3 Jp_inv = Jp.inverse();
  const Vec3 g(0, 0, -kG);
  auto f = [&](const Mat3& R, const Vec3& w, Mat3& dR, Vec3& dw) {
    dR = R * so3::hat(w);
    dw = Jp_inv * (d.cross(top.m * (R.transpose() * g)) - w.cross(Jp * w));
  };
  Mat3 R = top.R0;
  Vec3 w = top.omega0;
  const double h = T / steps;
  for (int n = 0; n < steps; ++n) {
    Mat3 k1R, k2R, k3R, k4R;
    Vec3 k1w, k2w, k3w, k4w;
    f(R, w, k1R, k1w);
    f(R + 0.5 * h * k1R, w + 0.5 * h * k1w, k2R, k2w);
    f(R + 0.5 * h * k2R, w + 0.5 * h * k2w, k3R, k3w);
    f(R + h * k3R, w + h * k3w, k4R, k4w);
    R += h / 6 * (k1R + 2 * k2R + 2 * k3R + k4R);
    w += h / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
  }
  return {R, w};
}

// A uniform sphere (radius 0.1 m, mass 2 kg) on a massless rod of length ℓ from a ball joint, turning
// steadily about the vertical at Ω² = g / (ℓ cos θ): the reaction on the body is F = m (Ω² ℓ sin θ
// e_r(inward) + g ẑ), directed from the centre of mass to the pivot, |F| = m g / cos θ.
struct Conical {
  double m = 2.0, radius = 0.1, l = 0.7, theta = 0.5;
  double Omega() const { return std::sqrt(kG / (l * std::cos(theta))); }
  System system() const {
    System s;
    s.add_body("bob", m, (m * radius * radius / 5) * Mat3::Identity());  // K = m r²/5 I for a solid sphere
    s.add_ball("pivot", 0, Vec3(0, 0, l), kWorld, Vec3::Zero());
    s.set_gravity(Vec3(0, 0, -kG));
    return s;
  }
  State state() const {
    State st;
    st.bodies.resize(1);
    BodyState& b = st.bodies[0];
    b.R_space_body = Eigen::AngleAxisd(theta, Vec3::UnitY()).toRotationMatrix();
    b.x_space = -b.R_space_body * Vec3(0, 0, l);  // below the pivot, displaced towards −x
    b.omega_body = b.R_space_body.transpose() * Vec3(0, 0, Omega());
    b.v_space = Vec3(0, 0, Omega()).cross(b.x_space);
    return st;
  }
  Vec3 reaction(const Vec3& x_com) const {  // centripetal m Ω² toward the axis plus the weight
    return m * (-Omega() * Omega() * Vec3(x_com.x(), x_com.y(), 0) + Vec3(0, 0, kG));
  }
};

}  // namespace poinsot::multibody::test
