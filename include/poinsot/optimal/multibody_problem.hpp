#pragma once
/// @file multibody_problem.hpp
/// Optimal motions of a multibody system (multibody/model.hpp): drive a system of coupled rigid bodies from
/// one consistent state to another with actuated joints or body torques, minimising the control effort
/// ∫ Σ u_i² dt (N²·m²·s) in a fixed time T, or the time T itself (MultibodyObjective). Solved by the direct
/// transcriptions of multibody_direct.hpp, in rotation-matrix coordinates (the multibody layer's own
/// equations) or in minimal coordinates.
///
/// Controls (`Actuator`), each with a bound |u_i| ≤ u_max (N·m) per component:
/// - `hinge_torque`: a motor in a hinge joint: the torque u about the hinge axis on body a, and −u on body b
///   (1 control; in body a's frame the torque is u·axis_a, in b's −u·axis_b);
/// - `body_torque`: a torque on one body about its centre of mass, body frame (3 controls, e.g. thrusters);
/// - `ball_torque`: three motors in a ball joint: the torque τ (space frame) on body a and −τ on body b
///   (3 controls; internal, like a hinge motor).
///
/// Boundary conditions: the full initial state, and the final state of every coordinate the joints leave
/// free (positions, attitudes, joint configurations and all velocities): `final_state` is a consistent
/// state of the system; the final condition is that the state at T equals it, written on the tangent space
/// of the constraints (multibody_direct.hpp), except for
/// - the angle of each hinge in `free_final_hinges` (its rate across the hinge is still imposed): a reaction
///   wheel's angle at T, say;
/// - the directions fixed by conserved quantities: a free-floating system (no joint to the world, no gravity
///   or constant loads, hinge and ball motors only) keeps its linear momentum P, its angular momentum H about
///   the origin and M x_com − t P, so the final state must have the initial state's, and imposing them again
///   would give dependent rows.
#include <string>
#include <vector>

#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/state.hpp"

namespace poinsot::optimal {

enum class ActuatorKind { hinge_torque, body_torque, ball_torque };

/// minimum_energy: ∫ Σ u_i² dt (N²·m²·s) at the fixed final time. minimum_time: T + ε ∫ Σ u_i² dt (s) with T
/// free (MultibodyProblem::final_time_min … final_time_max) and ε = MultibodyProblem::energy_weight ≥ 0 a
/// regularisation (ε = 0: pure minimum time, whose optimum with bounded torques is bang-bang).
enum class MultibodyObjective { minimum_energy, minimum_time };

struct Actuator {
  ActuatorKind kind = ActuatorKind::hinge_torque;
  int index = 0;            ///< the hinge's or ball's joint index, or the body's index
  double torque_max = 1.0;  ///< N·m, per component, > 0 (may be +inf: unbounded)
  int controls() const { return kind == ActuatorKind::hinge_torque ? 1 : 3; }
};

/// A path constraint on a hinge's rate: |q̇| ≤ rate_max (rad/s) at every collocation point, with q̇ = n·(ω_a −
/// E ω_b) the rate of body a relative to body b about the hinge axis n (body a's frame; E = R_aᵀR_b), the
/// world's ω being 0.
struct RateBound {
  int joint = 0;          ///< the hinge's joint index
  double rate_max = 1.0;  ///< rad/s, > 0
};

/// The no-twist condition of a ball joint (Kane & Scher 1969: the torso bends but does not twist), a path
/// constraint at every collocation point but the first: the relative rotation E = R_aᵀR_b of the joint's
/// bodies is E = C M, where C is the relative rotation of the straight, untwisted configuration and M turns
/// about an axis perpendicular to the symmetry axis s of body a (the swing–twist decomposition of M about s
/// has no twist): s·vee(M − Mᵀ) = 0, which is 4 q₀ (q·s) for M's unit quaternion (q₀, q), so it also holds
/// for a half-turn M: it describes bends below π. Bilinear in R_a and R_b. Rotation-matrix coordinates only.
struct NoTwist {
  int joint = 0;                     ///< a ball joint's index
  Vec3 axis_a = Vec3::UnitX();       ///< s, body a's frame, unit
  Mat3 straight = Mat3::Identity();  ///< C, a rotation
};

struct MultibodyProblem {
  multibody::System system;        ///< ball, hinge, weld and universal joints; gravity, constant loads
  multibody::State initial_state;  ///< consistent (multibody::check_consistent), velocities on the joints
  multibody::State final_state;    ///< consistent target at t = T
  double final_time = 1.0;         ///< T, s (minimum_time: the initial guess of T)
  MultibodyObjective objective = MultibodyObjective::minimum_energy;
  double final_time_min = 0.0;  ///< minimum_time: the lower bound on T (s)
  double final_time_max = 0.0;  ///< minimum_time: the upper bound on T (s)
  double energy_weight = 0.0;   ///< minimum_time: ε, s/(N²·m²·s)
  std::vector<Actuator> actuators;
  int intervals = 20;  ///< Hermite–Simpson intervals
  /// The intervals' lengths as fractions of T (`intervals` of them, each > 0, summing to 1), or empty for
  /// equal intervals (refine_multibody splits them).
  std::vector<double> mesh;
  std::vector<RateBound> rate_bounds;  ///< path constraints on hinge rates (none by default)
  /// Hinges (joint indices) whose angle at T is left free; each one's body_a must be in no other joint.
  std::vector<int> free_final_hinges;
  std::vector<NoTwist> no_twist;  ///< path constraints on ball joints (none by default)
};

/// The index of the hinge joint called `name`. Throws InvalidInput `got "NAME", expected the name of a hinge
/// joint (...)` listing the hinges.
int hinge_index(const multibody::System& system, const std::string& name);
/// The index of the ball joint called `name`; throws as hinge_index does, listing the ball joints.
int ball_index(const multibody::System& system, const std::string& name);
/// The motor of the hinge or ball joint called `name` (a hinge_torque or a ball_torque actuator) with the
/// bound torque_max (N·m, not checked here: validate does). Throws InvalidInput `got "NAME", expected the
/// name of a hinge or ball joint (...)` listing them.
Actuator joint_motor(const multibody::System& system, const std::string& name, double torque_max);

/// The rate q̇ (rad/s) of hinge `joint` at `state` (RateBound's definition).
double hinge_rate(const multibody::System& system, const multibody::State& state, int joint);

/// The twist s·vee(M − Mᵀ) of NoTwist at `state` (dimensionless; 0 without twist).
double twist_residual(const multibody::System& system, const multibody::State& state,
                      const NoTwist& condition);

/// Total number of scalar controls.
int control_count(const MultibodyProblem& problem);

/// Throws InvalidInput, one line naming the field, unless: T > 0 and finite; the mesh is empty or has
/// `intervals` fractions > 0 summing to 1 (to 1e-12); for minimum_time, 0 <
/// final_time_min ≤ final_time ≤ final_time_max < ∞, ε ≥ 0 finite, every torque_max finite (else T → 0),
/// and a free-floating system at zero linear momentum (its conserved M x_com − t P would depend on T); 2 ≤
/// intervals ≤ 2000; the system has no springs and no prismatic joints (their loads or rows are not written
/// for the transcriptions); every actuator names an existing hinge or body and has a bound > 0; there is at
/// least one actuator; both states are consistent (multibody::check_consistent) and have joint velocities
/// below 1e-9 (relative); every hinge axis points the same way on both sides; every rate bound names a hinge,
/// is > 0 and holds at both states; every free final hinge is a hinge whose body_a is in no other joint; a
/// free-floating system's final state has the initial state's P, H and M x_com − t P (to 1e-9 relative);
/// every no-twist condition names a ball joint, has a unit axis and a rotation C (to 1e-9) and holds at both
/// states (1e-9).
void validate(const MultibodyProblem& problem);

}  // namespace poinsot::optimal
