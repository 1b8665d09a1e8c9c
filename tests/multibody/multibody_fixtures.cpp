// The multibody tests' shared systems (multibody_fixtures.hpp), compiled once per test executable rather than
// in every file that includes them.
#include "multibody_fixtures.hpp"

#include <cmath>

#include "poinsot/so3/exp_log.hpp"
#include "poinsot/so3/hat.hpp"
#include "poinsot_test.hpp"

namespace poinsot::multibody::test {

int slowdown() {
  return ::poinsot::test::sanitized() ? 5 : 1;
}

std::string indexed(const char* prefix, int index) {
  std::string s(prefix);
  s.append(std::to_string(index));
  return s;
}

Mat3 rod_poinsot(double m, double l, double r) {
  return Vec3(m * l * l / 12.0, m * r * r / 4.0, m * r * r / 4.0).asDiagonal();
}

System rod_chain(int n, double m, double l, double r, const Vec3& g) {
  System s;
  for (int i = 0; i < n; ++i)
    s.add_body(indexed("link", i), m, rod_poinsot(m, l, r));
  s.add_ball("pivot", 0, Vec3(-l / 2, 0, 0), kWorld, Vec3::Zero());
  for (int i = 1; i < n; ++i)
    s.add_ball(indexed("j", i), i, Vec3(-l / 2, 0, 0), i - 1, Vec3(l / 2, 0, 0));
  s.set_gravity(g);
  return s;
}

State rod_chain_state(int n, double l) {
  State st;
  st.bodies.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    st.bodies[static_cast<std::size_t>(i)].x_space = Vec3((i + 0.5) * l, 0, 0);
  return st;
}

std::pair<System, State> hinge_tree() {
  System tree = rod_chain(3);
  tree.add_body("arm", 1.0, rod_poinsot(1.0, 1.0, 0.01));
  tree.add_hinge("h", 3, Vec3(-0.5, 0, 0), Vec3(0, 1, 0), 1, Vec3(0, 0.1, 0), Vec3(0, 1, 0));
  State st = rod_chain_state(3);
  st.bodies.push_back(BodyState{});
  st.bodies[3].x_space = Vec3(2.0, 0.1, 0);  // the arm's end at link 1's point (1.5, 0.1, 0)
  return {tree, st};
}

std::pair<System, State> four_bar_loop() {
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
    // The bar's axis x_body along e: the rotation about x × e by the angle between them (no end is
    // antiparallel to x here).
    const Vec3 e = (ends[i + 1] - ends[i]).normalized();
    const Vec3 normal = Vec3::UnitX().cross(e);  // |x × e| = sin of the angle
    const double sine = normal.norm();
    st.bodies[i].R_space_body =
        so3::exp(std::atan2(sine, e.x()) * (sine > 0 ? Vec3(normal / sine) : Vec3::UnitZ()));
    st.bodies[i].x_space = 0.5 * (ends[i] + ends[i + 1]);
  }
  return {s, st};
}

std::pair<System, State> spring_oscillator(double m, double k) {
  System s;
  s.add_body_from_inertia("mass", m, 0.01 * Mat3::Identity());
  s.add_spring({"spring", 0, kWorld, Vec3::Zero(), Vec3::Zero(), k, 0.0, 0.0});
  State st;
  st.bodies.resize(1);
  st.bodies[0].x_space = Vec3(-0.1, 0, 0);
  return {s, st};
}

std::pair<System, State> top_system(const Top& top) {
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

std::pair<Mat3, Vec3> top_reference(const Top& top, double T, int steps) {
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

double Conical::Omega() const {
  return std::sqrt(kG / (l * std::cos(theta)));
}

System Conical::system() const {
  System s;
  s.add_body("bob", m, (m * radius * radius / 5) * Mat3::Identity());  // K = m r²/5 I for a solid sphere
  s.add_ball("pivot", 0, Vec3(0, 0, l), kWorld, Vec3::Zero());
  s.set_gravity(Vec3(0, 0, -kG));
  return s;
}

State Conical::state() const {
  State st;
  st.bodies.resize(1);
  BodyState& b = st.bodies[0];
  b.R_space_body = Eigen::AngleAxisd(theta, Vec3::UnitY()).toRotationMatrix();
  b.x_space = -b.R_space_body * Vec3(0, 0, l);  // below the pivot, displaced towards −x
  b.omega_body = b.R_space_body.transpose() * Vec3(0, 0, Omega());
  b.v_space = Vec3(0, 0, Omega()).cross(b.x_space);
  return st;
}

Vec3 Conical::reaction(const Vec3& x_com) const {
  return m * (-Omega() * Omega() * Vec3(x_com.x(), x_com.y(), 0) + Vec3(0, 0, kG));
}

}  // namespace poinsot::multibody::test
