#pragma once
// Systems shared by the multibody tests: rods, chains, a body with a ball joint to the world.
#include <string>

#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/state.hpp"

namespace poinsot::multibody::test {

/// Long runs are shortened by this factor in sanitizer builds (Debug + ASan is ~100x slower than Release with
/// Eigen); the full-length figures are in docs/multibody.md.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr int kSlowdown = 5;
#else
inline constexpr int kSlowdown = 1;
#endif

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

}  // namespace poinsot::multibody::test
