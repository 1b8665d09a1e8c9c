#pragma once
/// @file lambda_tracker.hpp
/// Checks the properties of Λ that Vallée & Dumitriu (2002) prove, state by state along any trajectory,
/// and keeps the worst values (docs/conventions.md C2, C3, C14, C21, C24):
///   - symmetry: ‖Λ − Λᵀ − j(τ_body)‖_F (J), zero for a free body;
///   - Property 1 (corrected C2): the largest eigenvalue of sym(Λ) is ≤ 0 up to round-off (free body);
///   - tr Λ = −2T for every body (T the kinetic energy of the same state, J);
///   - the eigenvalues' variation from their initial values (constant only for axisymmetric free bodies,
///     Theorem; they vary for general bodies, C3);
///   - axisymmetric free bodies: the eigenvalues against the closed forms λ1,2 = (c1 ∓ √Δ)/2,
///     λ3 = −C⟨Ω0,Ω0⟩/2; λ3's eigenvector k × ω(t) (C14); EᵀΛE constant (Property 3);
///   - optionally the integrator's own multipliers (rattle) against the state formula;
///   - the constraint stress ∫σ dv = −RΛRᵀ at the start and its largest von Mises value over the run.
/// Λ is taken from the state by eq. (3.2), with ω̇ from Euler's equations and the torque. K is never
/// inverted. Feeding a state allocates nothing.

#include <memory>
#include <optional>

#include "poinsot/analysis/axisymmetric.hpp"
#include "poinsot/analysis/stress.hpp"
#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/dynamics/torque.hpp"

namespace poinsot::analysis {

struct LambdaTrackerOptions {
  double volume_m3 = 0.0;                ///< m³; > 0 adds the mean stress (Pa) to the report
  double axisymmetry_tolerance = 1e-12;  ///< relative tolerance on equal principal moments
};

/// The closed form of an axisymmetric free body and how far the trajectory's Λ is from it.
struct AxisymmetricCheck {
  AxisymmetricInertia inertia;          ///< A, C (kg·m²), k (body frame)
  double mu = 0.0;                      ///< rad/s
  double r = 0.0;                       ///< rad/s
  double c1 = 0.0;                      ///< J
  double c2 = 0.0;                      ///< J²
  double Delta = 0.0;                   ///< J²
  Vec3 lambda123 = Vec3::Zero();        ///< (λ1, λ2, λ3) by label (J)
  Vec3 eigenvalues = Vec3::Zero();      ///< the same, ascending (J)
  Mat3 constant_matrix = Mat3::Zero();  ///< EᵀΛE, eq. (5.3) (J)
  AxisymmetricSpecialCases special_cases;
  double max_deviation = 0.0;             ///< max over samples of max_i |λi(t) − λi closed| (sorted, J)
  double eigenvector_residual_max = 0.0;  ///< max |Λ v − λ3 v| / |v|, v = k × ω(t) (J)
  double constant_matrix_deviation_max = 0.0;  ///< max ‖E(t)ᵀ Λ(t) E(t) − EᵀΛE‖_F (J)
};

/// The worst values seen along the trajectory.
struct LambdaProperties {
  long long samples = 0;
  double t_initial = 0.0;  ///< s
  double t_final = 0.0;    ///< s
  bool torque_free = true;
  Mat3 lambda_initial = Mat3::Zero();       ///< Λ(t0), J, body frame
  Mat3 lambda_final = Mat3::Zero();         ///< J, body frame
  Vec3 eigenvalues_initial = Vec3::Zero();  ///< ascending, J
  Vec3 eigenvalues_final = Vec3::Zero();    ///< ascending, J
  double lambda_scale = 0.0;                ///< ‖Λ(t0)‖_F (J), to read the errors relatively
  double eigenvalue_max_variation = 0.0;    ///< max_t max_i |λi(t) − λi(t0)| (sorted, J)
  double symmetry_error_max = 0.0;          ///< max ‖Λ − Λᵀ − j(τ)‖_F (J)
  double max_eigenvalue_max = -1e300;  ///< the largest eigenvalue of sym(Λ) seen (J); ≤ 0 for a free body
  double trace_plus_2T_max = 0.0;      ///< max |tr Λ + 2T| (J)
  ConstraintStress stress_initial;  ///< ∫σ dv at t0 (N·m) and the mean stress (Pa) if a volume is known
  double von_mises_max =
      0.0;  ///< largest von Mises value of ∫σ dv (N·m), or of the mean stress (Pa) with a volume
  /// The integrator's multipliers (rattle), when they were given: max ‖Λ_int − Λ_state‖_F (J) and their
  /// own symmetry error.
  bool has_integrator_multiplier = false;
  double integrator_multiplier_deviation_max = 0.0;
  double integrator_multiplier_symmetry_error_max = 0.0;
  /// Present for an axisymmetric torque-free body.
  std::optional<AxisymmetricCheck> closed_form;
};

class LambdaTracker {
 public:
  /// `torque` may be nullptr (torque-free). The initial state is observed at once.
  LambdaTracker(const dynamics::RigidBody& body, std::shared_ptr<const dynamics::TorqueModel> torque,
                const dynamics::State& initial, const LambdaTrackerOptions& options = {});

  /// Adds one state of the trajectory.
  void observe(const dynamics::State& state);
  /// Compares an integrator's own multiplier matrix (J, body frame; rattle's last_multiplier()) with the
  /// state formula at the state `at` where the integrator's value is centred (rattle: the midpoint of its
  /// last step). Does not count as a sample.
  void compare_multiplier(const dynamics::State& at, const Mat3& lambda_integrator_body);

  const LambdaProperties& properties() const { return props_; }

 private:
  dynamics::RigidBody body_;  // a copy: RigidBody is a small value type
  std::shared_ptr<const dynamics::TorqueModel> torque_;
  LambdaTrackerOptions options_;
  std::optional<AxisymmetricLambda> axisymmetric_;
  LambdaProperties props_;
};

}  // namespace poinsot::analysis
