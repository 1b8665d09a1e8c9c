#pragma once
// Systems shared by the multibody tests: rods, chains, a body with a ball joint to the world. Defined in
// multibody_fixtures.cpp, compiled once for each test executable that uses them (tests/CMakeLists.txt).
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/state.hpp"

namespace poinsot::multibody::test {

/// Long runs are shortened by this factor under the sanitizers (the instrumented library is many times
/// slower); the full-length figures are in docs/measurements/multibody.md, "Long runs".
int slowdown();

/// prefix + index (avoids GCC 12's false -Wrestrict on "literal" + std::to_string).
std::string indexed(const char* prefix, int index);

inline constexpr double kG = 9.81;  ///< m/s², the gravity of the fixtures below

/// K about the centre of mass of a solid cylinder (mass m, length l along body x, radius r): ∫ρ X⊗X.
Mat3 rod_poinsot(double m, double l, double r);

/// A chain of n rods (length l, mass m, radius r) along +x from the origin, the first hung from the world at
/// the origin by a ball joint, the others joined end to end; gravity −kG ẑ. At rest, horizontal.
System rod_chain(int n, double m = 1.0, double l = 1.0, double r = 0.01, const Vec3& g = Vec3(0, 0, -kG));

/// The rest state of rod_chain(n, ·, l): the rods' centres at ((i + ½) l, 0, 0), unrotated.
State rod_chain_state(int n, double l = 1.0);

/// A tree that is not a chain: three rods hung from the world (rod_chain(3)) and a fourth, the "arm", on a
/// hinge about y from link 1's point (0, 0.1, 0); at rest, horizontal. Solved by Baraff's tree order.
std::pair<System, State> hinge_tree();

/// A spatial four-bar: three bars (1 m, 1 kg) joined by ball joints, both ends held at fixed points of the
/// world (a loop through the world: sparse LU), at rest, under an oblique gravity (0, −g, −3) m/s².
std::pair<System, State> four_bar_loop();

/// A body of mass m on a spring of stiffness k (rest length 0) to the world origin, no gravity, released at
/// rest from x = −0.1 m: x(t) = −0.1 cos(√(k/m) t).
std::pair<System, State> spring_oscillator(double m, double k);

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
std::pair<System, State> top_system(const Top& top);

/// (R(T), ω(T)) of the top by classical RK4 of Euler's equations about the pivot in `steps` steps.
std::pair<Mat3, Vec3> top_reference(const Top& top, double T, int steps);

// A uniform sphere (radius 0.1 m, mass 2 kg) on a massless rod of length ℓ from a ball joint, turning
// steadily about the vertical at Ω² = g / (ℓ cos θ): the reaction on the body is F = m (Ω² ℓ sin θ
// e_r(inward) + g ẑ), directed from the centre of mass to the pivot, |F| = m g / cos θ.
struct Conical {
  double m = 2.0, radius = 0.1, l = 0.7, theta = 0.5;
  double Omega() const;
  System system() const;
  State state() const;
  /// The centripetal m Ω² toward the axis plus the weight, at the centre of mass x_com.
  Vec3 reaction(const Vec3& x_com) const;
};

}  // namespace poinsot::multibody::test
