#pragma once
/// @file model.hpp
/// The constant model of a multibody system in rotation-matrix coordinates (docs/multibody_theory.md §1).
///
/// Each body has 12 coordinates: the position `x` of its centre of mass (space frame, m) and its rotation `R`
/// (body → space, the nine entries are unknowns), with constant mass data: the mass `m` (kg) and the Poinsot
/// tensor `K = ∫ρ X⊗X` about the centre of mass in the body frame (kg·m², docs/conventions.md; `J = tr(K)·I −
/// K`). The kinetic energy `½ m|ẋ|² + ½ tr(Ṙ K Ṙᵀ)` has the constant mass matrix `blockdiag(m I₃, K ⊗ I₃)`,
/// and every constraint enters through a Lagrange multiplier (Vallée & Dumitriu 2002, eq. 1.1 extended to
/// many bodies):
///
///     m ẍ = f + Gₓᵀ λ,        R̈ K = R Λ + F_R + G_Rᵀ λ,        RᵀR = I,  g(x, R) = 0,
///
/// where `Λ` (symmetric, J) is the body's orthogonality multiplier and `λ` the joints' reactions.
///
/// Joints (all holonomic, all written in the 12 coordinates; their kinematics in constraints.hpp, the list of
/// types in joint_types.hpp):
/// - ball: `x_a + R_a A − x_b − R_b B = 0` (3 rows; multiplier = force on body a from b, space frame, N);
/// - hinge: ball + `(R_a p_k)·(R_b u_b) = 0` for two unit vectors p_1, p_2 ⟂ u_a (2 rows, torques N·m);
/// - universal: ball + one such row, `(R_a p)·(R_b u) = 0` for the two cross-pin axes (p in a, u in b);
///   with an offset h between the axes (two hinges in series about different points), the point rows are
///   `x_a + R_a A − x_b − R_b B − h (R_a p) × (R_b u) = 0`: A on axis a, B on axis b, h their distance along
///   the common normal;
/// - weld: ball + three such perpendicularity rows that freeze the relative rotation;
/// - prismatic: the weld's three rotation rows, and point A on the line through B along the axis s (fixed in
///   b): `(R_b n_k)·(x_a + R_a A − x_b) − n_k·B = 0` for the two unit normals n_1, n_2 ⟂ s (2 rows, N).
/// Body b may be the world (index `kWorld`; its point B is then given in the space frame).
///
/// Loads: uniform gravity, constant forces at body points, constant torques, linear spring-dampers between
/// points and along the coordinate of a hinge or prismatic joint. Like Pinocchio and MuJoCo, the model is
/// built once and validated, then read by the integrator; the mutable State lives apart (state.hpp).

#include <array>
#include <string>
#include <vector>

#include "poinsot/core/types.hpp"

namespace poinsot::multibody {

inline constexpr int kWorld = -1;  ///< body index of the fixed world frame (x = 0, R = I)

/// Constant data of one rigid body.
struct Body {
  std::string name;
  double mass = 1.0;                ///< m, kg
  Mat3 poinsot = Mat3::Identity();  ///< K = ∫ρ X⊗X about the centre of mass, body frame, kg·m²
  Mat3 inertia = Mat3::Identity();  ///< J = tr(K)·I − K about the centre of mass, body frame, kg·m²
  Mat3 inertia_inverse = Mat3::Identity();  ///< J⁻¹ (J must be positive definite; K may be singular)
};

/// The joint types; joint_types.hpp gives each its name, rows and axes.
enum class JointType { ball, hinge, weld, universal, prismatic };

/// One joint. Rows: the translation rows (3 point rows, or 2 line rows when `sliding`), then
/// `perpendicular_count` rows `(R_a p_k)·(R_b u_k) = 0` (constraints.hpp).
struct Joint {
  std::string name;
  JointType type = JointType::ball;
  int body_a = 0;               ///< index of body a (never the world)
  int body_b = kWorld;          ///< index of body b or kWorld
  Vec3 point_a = Vec3::Zero();  ///< joint point in body a's frame, from its centre of mass, m
  Vec3 point_b = Vec3::Zero();  ///< joint point in body b's frame (space frame for the world), m
  bool sliding = false;         ///< point a on a line through point b (2 rows) instead of on point b (3 rows)
  std::array<Vec3, 2> n_b{};    ///< sliding: unit normals of the line, b's frame (space for the world)
  int perpendicular_count = 0;  ///< 0 (ball), 1 (universal), 2 (hinge), 3 (weld, prismatic)
  std::array<Vec3, 3> p_a{};    ///< unit vectors fixed in body a
  std::array<Vec3, 3> u_b{};    ///< unit vectors fixed in body b (space frame for the world)
  /// Universal joints: h, m, the distance from axis b (through point B) to axis a (through point A) along
  /// their common normal (R_a p_a[0]) × (R_b u_b[0]); 0 when the axes meet (point rows, constraints.hpp).
  double axis_offset = 0.0;
  int translation_rows() const { return sliding ? 2 : 3; }
  int rows() const { return translation_rows() + perpendicular_count; }
  /// A hinge's axis in body a's frame (unit): p_a[0] × p_a[1], the two unit vectors that the hinge's rows
  /// keep perpendicular to its axis in body b (p_a[1] = axis × p_a[0]). Hinges only.
  Vec3 hinge_axis_a() const { return p_a[0].cross(p_a[1]); }
  /// A sliding joint's line direction in body b's frame (space frame for the world; unit): n_b[0] × n_b[1].
  Vec3 slide_axis_b() const { return n_b[0].cross(n_b[1]); }
};

/// A linear spring-damper between a point of body a and a point of body b (or of the world):
/// force on a = −(k (ℓ − ℓ₀) + c ℓ̇) e, with e the unit vector from the point on b to the point on a.
struct Spring {
  std::string name;
  int body_a = 0;
  int body_b = kWorld;
  Vec3 point_a = Vec3::Zero();  ///< m, body a frame
  Vec3 point_b = Vec3::Zero();  ///< m, body b frame (space frame for the world)
  double stiffness = 0.0;       ///< k, N/m
  double damping = 0.0;         ///< c, N·s/m
  double rest_length = 0.0;     ///< ℓ₀, m
};

/// A linear spring-damper along the coordinate q of a hinge or prismatic joint (joint_coordinates.hpp), or
/// along one of the two angles of a universal joint: the generalized force Q = −k (q − q_rest) − c q̇ acts on
/// body a (a torque Q about the hinge axis, N·m, or a force Q along the sliding axis at point a, N) and −Q on
/// body b. Its potential is ½ k (q − q_rest)². A hinge's deflection q − q_rest is measured within half a
/// turn, (−π, π]: like a torsion spring about its rest angle, the spring does not count the turns.
///
/// Universal joint (cross-pin axis e_a fixed in body a, e_b fixed in body b): its relative rotations are
/// S = R_bᵀR_a = Rot(e_b, q_b) · R_b_a_zero · Rot(e_a, q_a), two hinges in series, the first about e_b, the
/// second about e_a (MuJoCo's two hinges of one body about one point). With c = R_b_a_zeroᵀ e_b and
/// M = R_b_a_zeroᵀ S: q_b = atan2(v·(c × e_a), v·e_a) with v = M e_a, q_a = atan2(w·(c × e_a), w·c) with
/// w = Mᵀc; the rates q̇_a = e_a·ω, q̇_b = w·ω of the relative angular velocity ω = ω_a − Sᵀω_b (body a
/// frame), and the torque on body a is Q e_a (coordinate a) or Q w (coordinate b): since w ⊥ e_a its power is
/// Q q̇, so the spring is conservative with the potential above.
///
/// Ball joint standing for three hinges in series (MuJoCo's three hinges of one body about one point), their
/// axes e₁, e₂, e₃ in body a's frame at q = 0 (`hinge_axes`, e₁ ⟂ e₂, e₂ ⟂ e₃, e₃ ≠ ±e₁): M = R_b_a_zeroᵀS =
/// Rot(e₁, q₁) Rot(e₂, q₂) Rot(e₃, q₃). With λ = atan2((e₁ × e₂)·e₃, e₁·e₃): cos(q₂ − λ) = e₁·M e₃ gives
/// q₂ = λ ∓ acos(e₁·M e₃) (the branch through q₂ = 0, |q₂ − λ| ≤ π); q₁ turns Rot(e₂, q₂) e₃ into M e₃ about
/// e₁, q₃ turns Mᵀe₁ into Rot(e₂, q₂)ᵀe₁ about e₃. The rates solve ω = E q̇ with
/// E = [Rot(e₃, q₃)ᵀRot(e₂, q₂)ᵀe₁, Rot(e₃, q₃)ᵀe₂, e₃], and the torque on body a is E⁻ᵀ Q e_k, so that its
/// power is Q q̇_k: conservative again. E is singular where e₁ and the turned e₃ align (q₂ − λ = 0 or π, the
/// hinges' gimbal lock; det E = sin(λ − q₂)), where the angles are undefined; applied_loads throws
/// ComputationFailed within 1e-6 rad of it.
struct JointSpring {
  /// Which angle the spring acts on: a universal joint's q_a (about e_a) or q_b (about e_b); a ball joint's
  /// q₁, q₂ or q₃ (its three hinges, first to third).
  enum class Coordinate { a, b, first, second, third };
  int joint = 0;                          ///< index of a hinge, prismatic, universal or ball joint
  Coordinate coordinate = Coordinate::a;  ///< universal joints: a or b; ball joints: first, second or third
  double stiffness = 0.0;                 ///< k: N·m/rad (hinge) or N/m (prismatic)
  double damping = 0.0;                   ///< c: N·m·s/rad (hinge) or N·s/m (prismatic)
  double rest_position = 0.0;             ///< q_rest: rad or m
  /// Hinge: the relative rotation R_bᵀR_a at which q = 0; it must carry the axis of a onto the axis of b.
  /// Universal: the one at which q_a = q_b = 0; it must carry e_a perpendicular to e_b. Ball: the one at
  /// which q₁ = q₂ = q₃ = 0.
  Mat3 R_b_a_zero = Mat3::Identity();
  /// Ball: the three hinges' axes e₁, e₂, e₃ (body a's frame at q = 0; non-zero, normalised when added).
  std::array<Vec3, 3> hinge_axes{};
  /// Prismatic: q when point a is at point b (m); q grows as point a moves along the axis.
  double offset = 0.0;
};

/// The name of a joint spring's coordinate: "a", "b", "first", "second" or "third".
const char* joint_spring_coordinate_name(JointSpring::Coordinate coordinate);

/// A constant force (space frame, N) applied at a point of a body (body frame, m from the centre of mass).
struct ConstantForce {
  int body = 0;
  Vec3 force_space = Vec3::Zero();
  Vec3 point_body = Vec3::Zero();
};

/// A constant torque (N·m) on a body, given in the space frame or in the body frame.
struct ConstantTorque {
  int body = 0;
  Vec3 torque = Vec3::Zero();
  bool in_body_frame = false;
};

/// The model: bodies, joints, loads. Built with the add_ functions, which validate their input and throw
/// InvalidInput with a one-line message naming the field.
class System {
 public:
  /// Adds a body of mass `mass` (kg) and Poinsot tensor `poinsot_com_body` = K about its centre of mass (body
  /// frame, kg·m²). K must be symmetric positive semi-definite (it may be singular: laminae) and J = tr(K)I −
  /// K positive definite (an ideal zero-thickness rod has no moment about its axis: give it a radius).
  /// Returns the body's index.
  int add_body(const std::string& name, double mass, const Mat3& poinsot_com_body);
  /// Same with the classical inertia tensor J about the centre of mass (body frame, kg·m²): K = tr(J)/2·I −
  /// J.
  int add_body_from_inertia(const std::string& name, double mass, const Mat3& inertia_com_body);

  /// Ball joint: point_a on body a coincides with point_b on body b (or a fixed point of space if b =
  /// kWorld).
  int add_ball(const std::string& name, int body_a, const Vec3& point_a, int body_b, const Vec3& point_b);
  /// Hinge (revolute) joint: ball joint plus the axis `axis_a` (body a frame) kept parallel to `axis_b` (body
  /// b frame, or space frame). Axes need not be unit; they must be non-zero.
  int add_hinge(const std::string& name, int body_a, const Vec3& point_a, const Vec3& axis_a, int body_b,
                const Vec3& point_b, const Vec3& axis_b);
  /// Weld joint: ball joint plus fixed relative rotation `R_b_a = R_bᵀ R_a` (R_a = R_b R_b_a).
  int add_weld(const std::string& name, int body_a, const Vec3& point_a, int body_b, const Vec3& point_b,
               const Mat3& R_b_a);
  /// Universal (Cardan, Hooke) joint: ball joint plus the cross-pin axis `axis_a` (body a frame) kept
  /// perpendicular to `axis_b` (body b frame, or space frame): two rotational degrees of freedom. Axes need
  /// not be unit; they must be non-zero (the assembled state must have them perpendicular).
  ///
  /// With `axis_offset` h ≠ 0 (m) the axes do not meet: two hinges in series, the first about `axis_b`
  /// through `point_b`, the second about `axis_a` through `point_a`, the second's axis at the distance h from
  /// the first's along the common normal e_a × e_b (space frame: (R_a axis_a) × (R_b axis_b), unit): point a
  /// is at point b + h e_a × e_b (MuJoCo's two hinges of one body about different points, such as a
  /// humanoid's ankle). Throws InvalidInput for a non-finite offset.
  int add_universal(const std::string& name, int body_a, const Vec3& point_a, const Vec3& axis_a, int body_b,
                    const Vec3& point_b, const Vec3& axis_b, double axis_offset = 0.0);
  /// Prismatic (slider) joint: the relative rotation fixed at `R_b_a = R_bᵀ R_a` as for a weld, and point_a
  /// kept on the line through point_b along `axis_a` (body a frame, the sliding direction; fixed in b as
  /// R_b_a axis_a): one translational degree of freedom. The axis must be non-zero.
  int add_prismatic(const std::string& name, int body_a, const Vec3& point_a, const Vec3& axis_a, int body_b,
                    const Vec3& point_b, const Mat3& R_b_a);

  int add_spring(const Spring& spring);
  /// Adds a spring-damper on the coordinate of a hinge or a prismatic joint, on one angle of a universal
  /// joint, or on one of the three hinge angles that a ball joint stands for (its index `joint`). Throws
  /// InvalidInput for another joint type, a coordinate of another joint type, a negative stiffness or
  /// damping, a non-finite value, a hinge's R_b_a_zero that is not a rotation carrying axis a onto axis b, a
  /// universal joint's that does not carry e_a perpendicular to e_b (to 1e-6), or a ball joint's hinge axes
  /// that are zero, not perpendicular in sequence (e₁·e₂, e₂·e₃ within 1e-9) or with e₃ = ±e₁ (|(e₁ × e₂)·e₃|
  /// below 1e-6).
  int add_joint_spring(const JointSpring& spring);
  void add_force(const ConstantForce& force);
  void add_torque(const ConstantTorque& torque);
  /// Uniform gravitational acceleration, space frame, m/s² (e.g. (0, 0, −9.81)).
  void set_gravity(const Vec3& gravity_space);

  int body_count() const { return static_cast<int>(bodies_.size()); }
  int joint_count() const { return static_cast<int>(joints_.size()); }
  const std::vector<Body>& bodies() const { return bodies_; }
  const std::vector<Joint>& joints() const { return joints_; }
  const std::vector<Spring>& springs() const { return springs_; }
  const std::vector<JointSpring>& joint_springs() const { return joint_springs_; }
  const std::vector<ConstantForce>& forces() const { return forces_; }
  const std::vector<ConstantTorque>& torques() const { return torques_; }
  const Vec3& gravity() const { return gravity_; }
  /// Index of the body called `name`, or kWorld for "world"; throws InvalidInput if there is none.
  int body_index(const std::string& name) const;
  /// Total number of joint constraint rows.
  int constraint_rows() const;
  /// A length (m) setting the scale of position tolerances: the largest joint lever arm or body radius of
  /// gyration, at least 1e-3 m.
  double length_scale() const;

 private:
  void check_body_index(const std::string& what, int index, bool world_allowed) const;
  int add_joint(Joint joint);

  std::vector<Body> bodies_;
  std::vector<Joint> joints_;
  std::vector<Spring> springs_;
  std::vector<JointSpring> joint_springs_;
  std::vector<ConstantForce> forces_;
  std::vector<ConstantTorque> torques_;
  Vec3 gravity_ = Vec3::Zero();
};

}  // namespace poinsot::multibody
