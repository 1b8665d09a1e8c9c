// The chain of the benchmark, shared by bench_multibody.cpp and the peer comparison (bench/peers/):
// N thin rods (1 m, 1 kg, radius 1 cm, a solid cylinder along the body x axis) joined by ball joints, link
// 0's end (-0.5, 0, 0) pinned to the world origin, link i's (-0.5, 0, 0) to link i-1's (+0.5, 0, 0), gravity
// (0, 0, -9.81) m/s². Released at rest, horizontal along +x.
#pragma once

#include <string>

#include "chain_constants.hpp"
#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/state.hpp"

namespace poinsot::bench {

/// The chain as a poinsot System. K (kg·m², about the centre of mass) = diag(m l²/12, m r²/4, m r²/4), i.e.
/// J = tr(K) I - K = diag(m r²/2, m(3r² + l²)/12, m(3r² + l²)/12).
inline multibody::System rod_chain(int n) {
  multibody::System s;
  const double m = kRodMass, l = kRodLength, r = kRodRadius;
  const Mat3 K = Vec3(m * l * l / 12.0, m * r * r / 4.0, m * r * r / 4.0).asDiagonal();
  for (int i = 0; i < n; ++i) {
    std::string name("link");
    name.append(std::to_string(i));
    s.add_body(name, m, K);
  }
  s.add_ball("pivot", 0, Vec3(-l / 2, 0, 0), multibody::kWorld, Vec3::Zero());
  for (int i = 1; i < n; ++i) {
    std::string name("j");
    name.append(std::to_string(i));
    s.add_ball(name, i, Vec3(-l / 2, 0, 0), i - 1, Vec3(l / 2, 0, 0));
  }
  s.set_gravity(Vec3(0, 0, -kGravity));
  return s;
}

/// The released state: link i's centre at ((i + 1/2) l, 0, 0), R = I, at rest.
inline multibody::State released_chain(int n) {
  multibody::State st;
  st.bodies.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    st.bodies[static_cast<std::size_t>(i)].x_space = Vec3((i + 0.5) * kRodLength, 0, 0);
  return st;
}

}  // namespace poinsot::bench
