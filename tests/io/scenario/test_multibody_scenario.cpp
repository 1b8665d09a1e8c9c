// Multibody scenario files (src/io/scenario/multibody_scenario.cpp): parsing and defaults, error messages,
// every example, and bodies given by the inertia layer (shapes, a mesh, a composite) against closed forms and
// the compound pendulum's small-oscillation period.
#include "poinsot/io/scenario/multibody_scenario.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/inertia/mass_properties.hpp"
#include "poinsot/inertia/mesh.hpp"
#include "poinsot/inertia/mesh_io.hpp"
#include "poinsot/inertia/shapes.hpp"
#include "poinsot/multibody/loads.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/multibody/rattle.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

using multibody::State;

const std::string kMultibodyExamples = std::string(POINSOT_SOURCE_DIR) + "/examples/";

std::string multibody_error_of(const std::string& text) {
  return test::message_of([&] { (void)parse_multibody_scenario(text, "t.toml", kMultibodyExamples); }, text);
}

using test::expect_has;

std::string vec(const Vec3& v) {
  return fmt::format("[{:.17g}, {:.17g}, {:.17g}]", v.x(), v.y(), v.z());
}

std::string mat(const Mat3& m) {
  return fmt::format("[{}, {}, {}]", vec(m.row(0)), vec(m.row(1)), vec(m.row(2)));
}

/// Steps a scenario with RATTLE and returns the states (the initial one first).
std::vector<State> trajectory(const multibody::Scenario& sc, int steps) {
  multibody::Rattle rattle(sc.system, sc.dt);
  std::vector<State> out{sc.initial};
  State st = sc.initial;
  for (int n = 0; n < steps; ++n) {
    rattle.step(st);
    out.push_back(st);
  }
  return out;
}

TEST(MultibodyScenario, ParsesBodiesJointsAndDefaults) {
  const multibody::Scenario sc = parse_multibody_scenario(R"(
[simulation]
dt = 2e-3
duration = 0.5
gravity = [0, 0, -9.81]
[[bodies]]
name = "a"
mass = 2
inertia = [0.1, 0.2, 0.25]
position = [1, 0, 0]
[[bodies]]
name = "b"
mass = 1
shape = { type = "box", size = [0.2, 0.4, 0.6] }
position = [1, 1, 0]
velocity = [0, 0, 5]
[[joints]]
type = "ball"
body_a = "a"
point_a = [0, 0.5, 0]
body_b = "b"
[[joints]]
type = "hinge"
body_a = "a"
point_a = [-1, 0, 0]
axis_a = [0, 0, 1]
)",
                                                          "t.toml");
  EXPECT_EQ(sc.system.body_count(), 2);
  EXPECT_EQ(sc.system.joint_count(), 2);
  EXPECT_DOUBLE_EQ(sc.dt, 2e-3);
  EXPECT_EQ(sc.order, 2);
  EXPECT_EQ(sc.method, multibody::MultibodyMethod::rattle);
  EXPECT_EQ(
      parse_multibody_scenario("[simulation]\norder = 4\n[[bodies]]\nmass = 1\ninertia = [1, 1, 1]\n").order,
      4);
  const multibody::Scenario rk4 =
      parse_multibody_scenario("[simulation]\nmethod = \"rk4\"\n[[bodies]]\nmass = 1\ninertia = [1, 1, 1]\n");
  EXPECT_EQ(rk4.method, multibody::MultibodyMethod::projected_rk4);
  EXPECT_EQ(rk4.order, 4);
  EXPECT_STREQ(multibody::multibody_method_name(rk4.method), "rk4");
  // K of the box: m/12 diag(a², b², c²); K of "a" from J: tr(J)/2 − J.
  EXPECT_NEAR(sc.system.bodies()[1].poinsot(2, 2), 0.36 / 12, 1e-15);
  EXPECT_NEAR(sc.system.bodies()[0].poinsot(0, 0), 0.175, 1e-15);
  // point_b defaulted to where point_a is at t = 0, in b's frame: (1, 0.5, 0) − (1, 1, 0).
  EXPECT_LT((sc.system.joints()[0].point_b - Vec3(0, -0.5, 0)).norm(), 1e-15);
  multibody::check_consistent(sc.system, sc.initial);
  // The initial velocities were projected onto the joints: ġ = 0.
  EXPECT_LT(multibody::constraint_violation(sc.system, sc.initial).joint_velocity, 1e-14);
  EXPECT_GT(sc.initial.bodies[1].v_space.norm(), 0.1);  // but not zeroed: b may still move about the joints
  EXPECT_EQ(sc.source, "t.toml");
  ASSERT_EQ(sc.body_descriptions.size(), 2u);
  expect_has(sc.body_descriptions[1], {"box", "mass 1 kg"});
}

/// Two bodies for the joint tests: a, turned 0.4 rad about z and moving, and b at rest at y = 1 m.
constexpr const char* kTwoBodies = R"(
[[bodies]]
name = "a"
mass = 1
inertia = [0.1, 0.2, 0.25]
rotation = { axis = [0, 0, 1], angle = 0.4 }
velocity = [1, -2, 0.5]
omega_body = [0.3, 0.1, -0.2]
[[bodies]]
name = "b"
mass = 2
inertia = [0.2, 0.2, 0.3]
position = [0, 1, 0]
)";

TEST(MultibodyScenario, ParsesUniversalAndPrismaticJoints) {
  const std::string bodies = kTwoBodies;
  const multibody::Scenario sc = parse_multibody_scenario(bodies + R"(
[[joints]]
type = "universal"
body_a = "a"
point_a = [0, 0, 0.5]
axis_a = [1, 0, 0]
axis_b = [0, 0, 1]
[[joints]]
type = "prismatic"
body_a = "b"
axis_a = [0, 0, 1]
)",
                                                          "t.toml");
  ASSERT_EQ(sc.system.joint_count(), 2);
  EXPECT_EQ(sc.system.joints()[0].type, multibody::JointType::universal);
  EXPECT_EQ(sc.system.joints()[0].rows(), 4);
  EXPECT_EQ(sc.system.joints()[1].type, multibody::JointType::prismatic);
  EXPECT_EQ(sc.system.joints()[1].rows(), 5);
  // Assembled at t = 0 (a's x axis turned about z stays perpendicular to space z; the prismatic joint by its
  // default point b and frozen rotation), and the velocities are projected onto both joints.
  multibody::check_consistent(sc.system, sc.initial);
  EXPECT_LT(multibody::constraint_violation(sc.system, sc.initial).joint_velocity, 1e-14);
  const std::string a = bodies + "[[joints]]\nbody_a = \"a\"\n";
  expect_has(multibody_error_of(a + "type = \"universal\"\naxis_a = [1, 0, 0]\n"),
             {"[joints[0]] axis_b: missing"});
  expect_has(multibody_error_of(a + "type = \"prismatic\"\n"), {"[joints[0]] axis_a: missing"});
  expect_has(multibody_error_of(a + "type = \"prismatic\"\naxis_a = [1, 0, 0]\naxis_b = [1, 0, 0]\n"),
             {"[joints[0]] axis_b: given for a prismatic joint; only hinge or universal joints take axis_b"});
}

TEST(MultibodyScenario, UniversalJointWithOffsetAxes) {
  // Body a (turned 0.4 rad about z, kTwoBodies) hangs from the world by hinges in series: about space z
  // through the default point b, then about a's x axis through point a, 0.25 m away along axis_a × axis_b.
  const std::string bodies = kTwoBodies;
  const multibody::Scenario sc = parse_multibody_scenario(bodies + R"(
[[joints]]
type = "universal"
body_a = "a"
point_a = [0, 0, 0.5]
axis_a = [1, 0, 0]
axis_b = [0, 0, 1]
axis_offset = 0.25
)",
                                                          "t.toml");
  ASSERT_EQ(sc.system.joint_count(), 1);
  const multibody::Joint& j = sc.system.joints()[0];
  EXPECT_EQ(j.axis_offset, 0.25);
  // The default point b is point a less h along e_a × e_b (space frame, e_a = a's x axis turned 0.4 rad).
  const multibody::BodyState& s = sc.initial.bodies[0];
  const Vec3 e_a = s.R_space_body * Vec3::UnitX();
  POINSOT_EXPECT_MATRIX_NEAR(
      j.point_b, Vec3(s.x_space + s.R_space_body * j.point_a - 0.25 * e_a.cross(Vec3::UnitZ())), 1e-15);
  multibody::check_consistent(sc.system, sc.initial);
  EXPECT_LT(multibody::constraint_violation(sc.system, sc.initial).joint_gap, 1e-15);
  EXPECT_LT(multibody::constraint_violation(sc.system, sc.initial).joint_velocity, 1e-14);
  const std::string a = bodies + "[[joints]]\nbody_a = \"a\"\n";
  expect_has(multibody_error_of(a + "type = \"hinge\"\naxis_a = [1, 0, 0]\naxis_offset = 0.1\n"),
             {"[joints[0]] axis_offset: given for a hinge joint; only universal joints take an axis offset"});
}

TEST(MultibodyScenario, JointSpringsOnHingesAndPrismaticJoints) {
  // Body a is turned 0.4 rad about z at t = 0: the hinge's zero is that relative rotation; the prismatic
  // joint's coordinate is the displacement of point_a from point_b (0 with the default point_b).
  const std::string bodies = kTwoBodies;
  const multibody::Scenario sc = parse_multibody_scenario(bodies + R"(
[[joints]]
type = "hinge"
body_a = "a"
axis_a = [0, 0, 1]
stiffness = 3
damping = 0.1
rest_position = -0.2
[[joints]]
type = "prismatic"
body_a = "b"
axis_a = [1, 0, 0]
damping = 0.5
)",
                                                          "t.toml");
  ASSERT_EQ(sc.system.joint_springs().size(), 2u);
  const multibody::JointSpring& hinge = sc.system.joint_springs()[0];
  EXPECT_EQ(hinge.joint, 0);
  EXPECT_EQ(hinge.stiffness, 3.0);
  EXPECT_EQ(hinge.damping, 0.1);
  EXPECT_EQ(hinge.rest_position, -0.2);
  EXPECT_EQ(hinge.R_b_a_zero, sc.initial.bodies[0].R_space_body);
  // At t = 0 the hinge sits at its zero: the spring's energy is ½ k (0 − (−0.2))².
  EXPECT_NEAR(multibody::potential_energy(sc.system, sc.initial.bodies), 0.5 * 3.0 * 0.04, 1e-15);
  const multibody::JointSpring& slide = sc.system.joint_springs()[1];
  EXPECT_EQ(slide.joint, 1);
  EXPECT_EQ(slide.stiffness, 0.0);
  EXPECT_EQ(slide.damping, 0.5);
  const std::string a = bodies + "[[joints]]\nbody_a = \"a\"\n";
  expect_has(
      multibody_error_of(a + "type = \"ball\"\nstiffness = 1\n"),
      {"[joints[0]] stiffness: given for a ball joint; only hinge and prismatic joints take a spring"});
  expect_has(multibody_error_of(a + "type = \"hinge\"\naxis_a = [0, 0, 1]\nrest_position = 1\n"),
             {"[joints[0]] rest_position: given without stiffness"});
  expect_has(multibody_error_of(a + "type = \"hinge\"\naxis_a = [0, 0, 1]\ndamping = -1\n"),
             {"[joints[0]] damping: multibody joint", "damping: got -1"});
}

TEST(MultibodyScenario, ErrorsNameTheFileTheEntryTheFieldTheValueAndTheExpectation) {
  const std::string a = "[[bodies]]\nname = \"a\"\nmass = 1\ninertia = [1, 1, 1]\n";
  expect_has(multibody_error_of("[[bodies]]\nname = \"a\"\nmass = -1\ninertia = [1, 1, 1]\n"),
             {"t.toml:3:8: [bodies[0]] mass: got -1 kg, expected a number > 0"});
  expect_has(multibody_error_of("[[bodies]]\nmass = 1\n"),
             {"t.toml:1:1: [bodies[0]] the inertia (one way to give it) is missing; expected exactly one of "
              "principal_moments, inertia, poinsot, shape, mesh, composite"});
  expect_has(multibody_error_of("[[bodies]]\ninertia = [1, 1, 1]\n"), {"[bodies[0]] mass: missing"});
  expect_has(multibody_error_of(a + "[[joints]]\ntype = \"slider\"\nbody_a = \"a\"\n"),
             {"t.toml:6:8: [joints[0]] type: got \"slider\", expected \"ball\", \"hinge\", \"weld\", "
              "\"universal\" or \"prismatic\""});
  expect_has(multibody_error_of(a + "[[joints]]\ntype = \"ball\"\nbody_a = \"nobody\"\n"),
             {"t.toml:7:10: [joints[0]] body_a: got \"nobody\", expected the name of a body"});
  expect_has(multibody_error_of(a + "[[joints]]\ntype = \"ball\"\nbody_a = \"world\"\n"),
             {"[joints[0]] body_a: got \"world\", expected a body"});
  expect_has(
      multibody_error_of(a + "[[joints]]\ntype = \"ball\"\nbody_a = \"a\"\naxis_a = [0, 0, 1]\n"),
      {"[joints[0]] axis_a: given for a ball joint; only hinge, universal or prismatic joints take an axis"});
  expect_has(multibody_error_of(a + "[[joints]]\ntype = \"hinge\"\nbody_a = \"a\"\n"),
             {"[joints[0]] axis_a: missing"});
  expect_has(multibody_error_of(a + "[[joints]]\ntype = \"hinge\"\nbody_a = \"a\"\naxis_a = [0, 0, 0]\n"),
             {"t.toml:6:8: [joints[0]] type:", "axis", "zero"});
  // J violates the triangle inequality: the model's message, at the key.
  expect_has(multibody_error_of("[[bodies]]\nname = \"a\"\nmass = 1\ninertia = [1, 1, 5]\n"),
             {"t.toml:4:11: [bodies[0]] inertia: multibody body 'a'"});
  expect_has(multibody_error_of("x = [1,\n"), {"t.toml:1:9: TOML syntax error"});
  expect_has(multibody_error_of("[simulation]\ndt = 1e-3\n"), {"[top level] bodies: missing"});
  expect_has(multibody_error_of("bodies = 3\n"),
             {"[top level] bodies: got 3, expected an array of tables [[bodies]]"});
  expect_has(multibody_error_of("[simulation]\ndt = -1\n" + a),
             {"t.toml:2:6: [simulation] dt: got -1 s, expected"});
  expect_has(multibody_error_of("[simulation]\noutput_every = 2.5\n" + a),
             {"[simulation] output_every: got 2.5, expected an integer >= 1"});
  expect_has(multibody_error_of("[simulation]\norder = 3\n" + a),
             {"t.toml:2:9: [simulation] order: got 3, expected 2 (RATTLE) or 4"});
  expect_has(multibody_error_of("[simulation]\nmethod = \"euler\"\n" + a),
             {"t.toml:2:10: [simulation] method: got \"euler\", expected \"rattle\"", "or \"rk4\""});
  expect_has(multibody_error_of("[simulation]\nmethod = \"rk4\"\norder = 2\n" + a),
             {"t.toml:3:9: [simulation] order: applies to method = \"rattle\" only"});
  expect_has(multibody_error_of(a + "colour = \"red\"\n"),
             {"t.toml:5:1: [bodies[0]] unknown key \"colour\"; valid keys:"});
  expect_has(multibody_error_of(a + "quaternion = [0, 0, 0, 0]\n"),
             {"[bodies[0]] quaternion: got a zero quaternion"});
  expect_has(multibody_error_of(a + "rotation = [[1, 0, 0], [0, 1, 0], [0, 0, -1]]\n"),
             {"[bodies[0]] rotation: got", "expected { axis = [x, y, z], angle = a } or a rotation matrix"});
  expect_has(multibody_error_of(a + "rotation = { axis = [0, 0, 0], angle = 1 }\n"),
             {"[bodies[0].rotation] axis: got (0, 0, 0), expected a non-zero vector"});
  expect_has(multibody_error_of(a + "[[torques]]\nbody = \"a\"\ntorque = [1, 0, 0]\nframe = \"moon\"\n"),
             {"[torques[0]] frame: got \"moon\", expected \"space\" or \"body\""});
  expect_has(multibody_error_of(a + "[[forces]]\nbody = \"a\"\n"), {"[forces[0]] force: missing"});
  expect_has(multibody_error_of(a + "[[springs]]\nbody_a = \"a\"\nstiffness = -1\n"),
             {"t.toml:7:13: [springs[0]] stiffness:"});
  // Bodies from the inertia layer: the same messages as a single-body [body], with the entry's name.
  expect_has(multibody_error_of("[[bodies]]\nshape = { type = \"blob\", mass = 1 }\n"),
             {"[bodies[0].shape] type: got \"blob\", expected one of point, rod"});
  expect_has(
      multibody_error_of("[[bodies]]\nshape = { type = \"box\", size = [1, 1, 1] }\n"),
      {"[bodies[0].shape] mass: missing; expected mass (kg) or density in the table, or [bodies[0]] mass"});
  expect_has(
      multibody_error_of("[[bodies]]\nmass = 2\nshape = { type = \"box\", size = [1, 1, 1], mass = 1 }\n"),
      {"t.toml:2:8: [bodies[0]] mass: got 2 kg, but the shape already gives the mass (1 kg)"});
  expect_has(multibody_error_of("[[bodies]]\nshape = { type = \"rod\", length = 1, mass = 1 }\n"),
             {"[bodies[0]] shape:", "give it a radius"});  // an ideal rod has no moment about its axis
  expect_has(
      multibody_error_of(
          "[[bodies]]\nshape = { type = \"cylinder\", radius = 1, length = 1, mass = 1, axis = \"w\" }\n"),
      {"[bodies[0].shape] axis: got \"w\", expected \"x\", \"y\" or \"z\""});
  expect_has(multibody_error_of(
                 "[[bodies]]\nshape = { type = \"box\", size = [1, 1, 1], mass = 1, axis = \"z\" }\n"),
             {"key \"axis\" does not apply to a box"});
  expect_has(multibody_error_of("[[bodies]]\nmesh = { file = \"meshes/none.stl\", density = 1000 }\n"),
             {"t.toml:2:17: [bodies[0].mesh] file:", "none.stl"});
  expect_has(multibody_error_of("[[bodies]]\nmesh = { file = \"meshes/l_bracket.obj\", density = -1 }\n"),
             {"[bodies[0].mesh] density: got -1, expected a number > 0"});
  expect_has(multibody_error_of("[[bodies]]\ncomposite = { file = \"none.toml\" }\n"),
             {"[bodies[0].composite] file:", "none.toml"});
  expect_has(multibody_error_of("[[bodies]]\ncomposite = { }\n"), {"[bodies[0].composite] file: missing"});
  expect_has(multibody_error_of(
                 "[[bodies]]\nmass = 1\ncomposite = { file = \"../tests/data/inertia/wheel.toml\" }\n"),
             {"[bodies[0]] mass: got 1 kg, but the composite already gives the mass"});
  EXPECT_THROW((void)load_multibody_scenario("/nonexistent/file.toml"), InvalidInput);
}

TEST(MultibodyScenario, EveryExampleLoadsAndRuns) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kMultibodyExamples + "multibody/")) {
    if (entry.path().extension() != ".toml") continue;
    ++count;
    SCOPED_TRACE(entry.path().string());
    multibody::Scenario sc = load_multibody_scenario(entry.path().string());
    sc.duration = 50 * sc.dt;  // a smoke run; the physics is tested elsewhere
    const multibody::RunSummary s = multibody::simulate(sc);
    EXPECT_EQ(s.steps, 50);
    EXPECT_LT(s.max_joint_gap, 1e-12);
    EXPECT_LT(s.max_joint_angle, 1e-12);
    if (sc.system.torques().empty()) {  // a constant couple does work and has no potential
      EXPECT_LT(s.max_energy_error, 1e-4 * std::max(1.0, std::abs(s.energy_initial)));
    }
  }
  EXPECT_EQ(count, 6);
}

TEST(MultibodyScenario, LegacyRodIsASolidCylinderAlongBodyX) {
  // The first multibody files gave the mass on the body and a rod with a radius, along x by default: K of a
  // solid cylinder (m, l, r) along x is diag(m l²/12, m r²/4, m r²/4).
  const double m = 1.5, l = 0.8, r = 0.02;
  const auto sc = parse_multibody_scenario(fmt::format(
      "[[bodies]]\nmass = {}\nshape = {{ type = \"rod\", length = {}, radius = {} }}\n", m, l, r));
  const Mat3 K = Vec3(m * l * l / 12, m * r * r / 4, m * r * r / 4).asDiagonal();
  EXPECT_LE(test::max_abs_diff(sc.system.bodies()[0].poinsot, K), 4 * test::kEps * K.norm());
  // The same cylinder along z and along y: the axes permuted.
  const auto along = [&](const char* axis) {
    return parse_multibody_scenario(
               fmt::format("[[bodies]]\nshape = {{ type = \"cylinder\", length = {}, radius = {}, mass = {}, "
                           "axis = \"{}\" }}\n",
                           l, r, m, axis))
        .system.bodies()[0]
        .poinsot;
  };
  EXPECT_LE(std::abs(along("z")(2, 2) - m * l * l / 12), 4 * test::kEps * K.norm());
  EXPECT_LE(std::abs(along("y")(1, 1) - m * l * l / 12), 4 * test::kEps * K.norm());
  EXPECT_LE(std::abs(along("y")(0, 0) - m * r * r / 4), 4 * test::kEps * K.norm());
}

/// A compound pendulum: one body hinged about space y at `pivot_body` (a point of its frame), released
/// `theta0` from hanging straight down; `inertia_keys` gives its inertia. Its frame is turned so that the
/// hinge axis `axis_body` is along space y and com − pivot points down, then by theta0 about y.
std::string pendulum(const std::string& inertia_keys, const Vec3& com_body, const Vec3& pivot_body,
                     const Vec3& axis_body, double theta0, double dt) {
  const Vec3 z = axis_body.normalized();
  const Vec3 u = (com_body - pivot_body - (com_body - pivot_body).dot(z) * z).normalized();
  Mat3 B, A;
  B << u, z.cross(u), z;                               // right-handed
  A << -Vec3::UnitZ(), -Vec3::UnitX(), Vec3::UnitY();  // images: u down, z along y
  const Mat3 R = Eigen::AngleAxisd(theta0, Vec3::UnitY()).toRotationMatrix() * A * B.transpose();
  const Vec3 position = -R * pivot_body;  // the pivot at the origin
  return fmt::format(
      "[simulation]\ndt = {}\ngravity = [0, 0, -9.81]\n[[bodies]]\nname = \"p\"\n{}\nrotation = {}\n"
      "position = {}\n[[joints]]\ntype = \"hinge\"\nbody_a = \"p\"\npoint_a = {}\naxis_a = {}\n",
      dt, inertia_keys, mat(R), vec(position), vec(pivot_body), vec(axis_body));
}

TEST(MultibodyScenario, BoxShapeEqualsItsClosedFormInertiaAlongATrajectory) {
  // A bar 1 m × 4 cm × 2 cm of 1 kg as a shape of the inertia layer, and as its closed-form J [MK]:
  // diag(m(b² + c²), m(a² + c²), m(a² + b²))/12, hinged 0.4 m from its centre. Same model, same motion.
  const double m = 1.0, a = 1.0, b = 0.04, c = 0.02;
  const Vec3 J = Vec3(b * b + c * c, a * a + c * c, a * a + b * b) * (m / 12.0);
  const Vec3 pivot(-0.4, 0, 0);
  const auto shape = parse_multibody_scenario(
      pendulum(fmt::format("shape = {{ type = \"box\", size = [{}, {}, {}], mass = {} }}", a, b, c, m),
               Vec3::Zero(), pivot, Vec3::UnitZ(), 0.5, 1e-3));
  const auto closed = parse_multibody_scenario(pendulum(fmt::format("mass = {}\ninertia = {}", m, vec(J)),
                                                        Vec3::Zero(), pivot, Vec3::UnitZ(), 0.5, 1e-3));
  EXPECT_LE(test::max_abs_diff(shape.system.bodies()[0].inertia, closed.system.bodies()[0].inertia),
            4 * test::kEps * J.norm());
  const auto ts = trajectory(shape, 1000);
  const auto tc = trajectory(closed, 1000);
  double worst = 0.0;
  for (std::size_t n = 0; n < ts.size(); ++n) {
    worst = std::max(worst, (ts[n].bodies[0].x_space - tc[n].bodies[0].x_space).norm());
    worst = std::max(worst, (ts[n].bodies[0].R_space_body - tc[n].bodies[0].R_space_body).norm());
  }
  // Inputs equal to a few ulps; each step's Newton solve converges to 1e-13 relative, and a stable
  // oscillation does not amplify differences exponentially: 1000 steps stay far below 1e-10.
  EXPECT_LT(worst, 1e-10);
}

/// The L-bracket of examples/meshes/l_bracket.obj as two boxes (closed form): an arm 0.12 × 0.03 m and a leg
/// 0.03 × 0.05 m, 0.02 m thick, aluminium 2700 kg/m³; parts' centres in the mesh frame.
struct Part {
  double mass;
  Vec3 size, centre;
};
const double kRho = 2700.0;
const Part kArm{kRho * 0.12 * 0.03 * 0.02, Vec3(0.12, 0.03, 0.02), Vec3(0.06, 0.015, 0.01)};
const Part kLeg{kRho * 0.03 * 0.05 * 0.02, Vec3(0.03, 0.05, 0.02), Vec3(0.015, 0.055, 0.01)};

/// Moment of inertia of the bracket about the axis through `p` along mesh z: Σ m(a² + b²)/12 + m |c − p|²_xy
/// (closed-form box and the parallel-axis theorem).
double bracket_moment_z(const Vec3& p) {
  double sum = 0.0;
  for (const Part& q : {kArm, kLeg}) {
    const Vec3 d = q.centre - p;
    sum += q.mass * (q.size.x() * q.size.x() + q.size.y() * q.size.y()) / 12.0 +
           q.mass * (d.x() * d.x() + d.y() * d.y());
  }
  return sum;
}

Vec3 bracket_com() {
  return (kArm.mass * kArm.centre + kLeg.mass * kLeg.centre) / (kArm.mass + kLeg.mass);
}

/// The small-oscillation period measured from the upward zero crossings of the centre of mass's x (linear
/// interpolation between steps: the motion is nearly straight there).
double measured_period(const multibody::Scenario& sc, int steps) {
  const auto tr = trajectory(sc, steps);
  std::vector<double> crossings;
  for (std::size_t n = 1; n < tr.size(); ++n) {
    const double x0 = tr[n - 1].bodies[0].x_space.x(), x1 = tr[n].bodies[0].x_space.x();
    if (x0 < 0 && x1 >= 0) crossings.push_back(sc.dt * (static_cast<double>(n - 1) + x0 / (x0 - x1)));
  }
  if (crossings.size() < 2) return 0.0;
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

TEST(MultibodyScenario, MeshBodyHasTheInertiaLayersMassPropertiesAndPointsInTheMeshFrame) {
  const Vec3 pivot(0.015, 0.065, 0.01);  // a hole in the leg, mesh frame
  const auto sc =
      parse_multibody_scenario(pendulum("mesh = { file = \"meshes/l_bracket.obj\", density = 2700.0 }",
                                        bracket_com(), pivot, Vec3::UnitZ(), 0.2, 1e-3),
                               "t.toml", kMultibodyExamples);
  const inertia::MassProperties mp =
      inertia::mesh_mass_properties(inertia::load_mesh(kMultibodyExamples + "meshes/l_bracket.obj"), 2700.0);
  const multibody::Body& body = sc.system.bodies()[0];
  // The same code path as the inertia layer: equal to round-off of K = tr(J)/2 − J.
  EXPECT_EQ(body.mass, mp.mass);
  EXPECT_LE(test::max_abs_diff(body.poinsot, mp.poinsot_com()), 4 * test::kEps * mp.inertia_com.norm());
  // Against the closed form of two boxes: assimp stores vertices in single precision (6e-8 relative), and J
  // goes as the fifth power of lengths: 1e-6 relative leaves a margin.
  EXPECT_NEAR(body.mass, kArm.mass + kLeg.mass, 1e-6 * body.mass);
  EXPECT_LE((mp.com - bracket_com()).norm(), 1e-8);
  // The joint point was given in the mesh frame: the model has it from the centre of mass.
  EXPECT_LE((sc.system.joints()[0].point_a - (pivot - mp.com)).norm(), 1e-15);
  // The pivot is at the origin of space, and the centre of mass at position + R c, |c − pivot| from it.
  const multibody::BodyState& s0 = sc.initial.bodies[0];
  EXPECT_LE((s0.x_space + s0.R_space_body * sc.system.joints()[0].point_a).norm(), 1e-15);
  EXPECT_NEAR(s0.x_space.norm(), (mp.com - pivot).norm(), 1e-15);
  expect_has(sc.body_descriptions[0], {"l_bracket.obj", "centre of mass", "mesh frame"});
}

TEST(MultibodyScenario, OmittedPointsAreTheCentreOfMassGivenOnesAreInTheBodysFrame) {
  // A free mesh body pushed by a constant force: without a point the force acts at the centre of mass (no
  // rotation, ẍ = F/m exactly under RATTLE); at the mesh's origin (0, 0, 0) it also turns the body, with
  // the torque (0 − c) × F about the centre of mass.
  const std::string body =
      "[[bodies]]\nname = \"b\"\nmesh = { file = \"meshes/l_bracket.obj\", density = 2700.0 }\n";
  const auto at_com = parse_multibody_scenario(body + "[[forces]]\nbody = \"b\"\nforce = [0, 0.01, 0]\n",
                                               "t.toml", kMultibodyExamples);
  const auto at_origin =
      parse_multibody_scenario(body + "[[forces]]\nbody = \"b\"\nforce = [0, 0.01, 0]\npoint = [0, 0, 0]\n",
                               "t.toml", kMultibodyExamples);
  const Vec3 c = at_com.initial.bodies[0].x_space;  // position 0, R = I: the centre of mass at c
  EXPECT_EQ(at_com.system.forces()[0].point_body, Vec3::Zero());
  EXPECT_EQ(at_origin.system.forces()[0].point_body, Vec3(-c));
  const auto a = trajectory(at_com, 100);
  EXPECT_EQ(a.back().bodies[0].omega_body, Vec3::Zero());
  // Verlet is exact for a constant acceleration: x = c + F t²/(2m) at t = 0.1 s, to round-off.
  const Vec3 x = c + Vec3(0, 0.01, 0) * (0.01 / (2 * at_com.system.bodies()[0].mass));
  EXPECT_LE((a.back().bodies[0].x_space - x).norm(), 1e-15);
  const auto b = trajectory(at_origin, 100);
  // Euler's equation at t = 0: J ω̇ = (−c) × F, z component only (F = 0.01 N along y; ω̇ ≈ 1 rad/s²).
  const Vec3 torque = Vec3(-c).cross(Vec3(0, 0.01, 0));
  const Vec3 omega_dot = at_origin.system.bodies()[0].inertia_inverse * torque;
  // After 0.1 s the rate is ω̇ t to first order: the body has turned by ω̇ t²/2 ≈ 5e-3 rad (the space-fixed
  // force turns by as much in the body frame) and ω × Jω is of relative size ω t ≈ 1e-2 at most.
  EXPECT_NEAR(b.back().bodies[0].omega_body.z(), 0.1 * omega_dot.z(), 1e-2 * std::abs(0.1 * omega_dot.z()));
}

TEST(MultibodyScenario, MeshPendulumHasTheCompoundPendulumPeriod) {
  // T = 2π √(I_pivot / (m g d)) with I_pivot about the hinge through the hole (parallel-axis theorem on
  // the two boxes) and d = |c − pivot|. RATTLE's period error is O(h²): for the Störmer-Verlet scheme on
  // ẍ = −ω² x it is (ωh)²/24 to leading order (cos ω̃h = 1 − (ωh)²/2). Measured: see the two step sizes.
  const Vec3 pivot(0.015, 0.065, 0.01);
  const double m = kArm.mass + kLeg.mass, g = 9.81;
  const double d = (bracket_com() - pivot).norm();
  const double I = bracket_moment_z(pivot);
  const double T = 2 * std::numbers::pi * std::sqrt(I / (m * g * d));
  const double omega = 2 * std::numbers::pi / T;
  const double theta0 = 1e-3;  // amplitude correction θ0²/16 = 6e-8 relative
  std::vector<double> errors;
  for (const double h : {2e-3, 1e-3}) {
    const auto sc =
        parse_multibody_scenario(pendulum("mesh = { file = \"meshes/l_bracket.obj\", density = 2700.0 }",
                                          bracket_com(), pivot, Vec3::UnitZ(), theta0, h),
                                 "t.toml", kMultibodyExamples);
    const double Th = measured_period(sc, static_cast<int>(std::lround(3.2 * T / h)));
    errors.push_back((Th - T) / T);
    // RATTLE's period is short by the Störmer-Verlet amount (ωh)²/24 (ω̃ = (2/h) asin(ωh/2)) and the finite
    // amplitude lengthens it by θ0²/16. What is left: the next order 3(ωh)⁴/640 ~ 1e-9, the float vertices
    // of the mesh (6e-8 relative in lengths, a few 1e-8 in T) and the linear interpolation of the crossings
    // (~1e-9): 1e-7. Measured: −1.926e-5 (h = 2 ms) and −4.775e-6 (h = 1 ms) against the predicted
    // −1.926e-5 and −4.767e-6.
    const double predicted = -(omega * h) * (omega * h) / 24 + theta0 * theta0 / 16;
    EXPECT_NEAR((Th - T) / T, predicted, 1e-7) << "h = " << h;
  }
  // Second order: halving h divides the error by about 4.
  EXPECT_NEAR(errors[0] / errors[1], 4.0, 0.5);
}

TEST(MultibodyScenario, CompositeBodyEqualsTheMeshItDescribes) {
  // The bracket as a composite body file of two boxes: the same mass properties as the mesh (to its float
  // vertices, 1e-6), the same centre-of-mass offset, and the same pendulum.
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "mb_composite";
  std::filesystem::create_directories(dir);
  {
    std::ofstream out(dir / "bracket.toml");
    for (const Part& q : {kArm, kLeg}) {
      out << fmt::format("[[part]]\nshape = \"box\"\nsize = {}\ndensity = 2700\nposition = {}\n", vec(q.size),
                         vec(q.centre));
    }
  }
  const Vec3 pivot(0.015, 0.065, 0.01);
  const auto composite = parse_multibody_scenario(
      pendulum("composite = { file = \"bracket.toml\" }", bracket_com(), pivot, Vec3::UnitZ(), 0.3, 1e-3),
      "t.toml", dir.string());
  const auto mesh =
      parse_multibody_scenario(pendulum("mesh = { file = \"meshes/l_bracket.obj\", density = 2700.0 }",
                                        bracket_com(), pivot, Vec3::UnitZ(), 0.3, 1e-3),
                               "t.toml", kMultibodyExamples);
  const multibody::Body& bc = composite.system.bodies()[0];
  const multibody::Body& bm = mesh.system.bodies()[0];
  EXPECT_NEAR(bc.mass, bm.mass, 1e-6 * bm.mass);
  EXPECT_LE(test::max_abs_diff(bc.inertia, bm.inertia), 1e-6 * bm.inertia.norm());
  EXPECT_LE((composite.system.joints()[0].point_a - mesh.system.joints()[0].point_a).norm(), 1e-8);
  const auto tc = trajectory(composite, 600);
  const auto tm = trajectory(mesh, 600);
  // Relative inertia differences of 1e-6 change the frequency by 1e-6: after ~1 period the positions
  // differ by about 1e-6 × 2π × |x| ~ 1e-7 m.
  EXPECT_LT((tc.back().bodies[0].x_space - tm.back().bodies[0].x_space).norm(), 1e-6);
  expect_has(composite.body_descriptions[0], {"composite", "2 parts"});
}

}  // namespace
}  // namespace poinsot::io
