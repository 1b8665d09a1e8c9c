// Multibody scenario files: TOML → System + initial State (scenario.hpp). Uses toml++.
#include "poinsot/multibody/scenario.hpp"

#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/multibody/constraints.hpp"
#include "poinsot/multibody/kkt_solver.hpp"
#include "poinsot/so3/axis_angle.hpp"
#include "poinsot/so3/projection.hpp"
#include "poinsot/so3/quaternion.hpp"

namespace poinsot::multibody {
namespace {

// Reads fields of one table, with messages "scenario <file>: <where>.<field>: ...".
class Fields {
 public:
  Fields(const toml::table& table, std::string where) : table_(table), where_(std::move(where)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& message) const {
    throw InvalidInput(fmt::format("{}.{}: {}", where_, field, message));
  }
  bool has(const std::string& field) const { return table_.contains(field); }
  const toml::node* node(const std::string& field) const { return table_.get(field); }

  double number(const std::string& field) const {
    const toml::node* n = table_.get(field);
    if (n == nullptr) fail(field, "missing; expected a number");
    const std::optional<double> v = n->value<double>();
    if (!v || !std::isfinite(*v)) fail(field, "expected a finite number");
    return *v;
  }
  double number(const std::string& field, double fallback) const {
    return has(field) ? number(field) : fallback;
  }
  std::string text(const std::string& field) const {
    const toml::node* n = table_.get(field);
    if (n == nullptr) fail(field, "missing; expected a string");
    const std::optional<std::string> v = n->value<std::string>();
    if (!v) fail(field, "expected a string");
    return *v;
  }
  std::string text(const std::string& field, const std::string& fallback) const {
    return has(field) ? text(field) : fallback;
  }
  Vec3 vector(const std::string& field) const { return vector_of(table_.get(field), field); }
  Vec3 vector(const std::string& field, const Vec3& fallback) const {
    return has(field) ? vector(field) : fallback;
  }
  Vec3 vector_of(const toml::node* n, const std::string& field) const {
    const toml::array* a = n == nullptr ? nullptr : n->as_array();
    if (a == nullptr || a->size() != 3) fail(field, "expected an array of 3 numbers");
    Vec3 v;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::optional<double> x = (*a)[k].value<double>();
      if (!x || !std::isfinite(*x)) fail(field, "expected an array of 3 finite numbers");
      v(static_cast<Eigen::Index>(k)) = *x;
    }
    return v;
  }
  // A 3-vector (the diagonal) or a 3×3 array of arrays.
  Mat3 matrix(const std::string& field) const {
    const toml::array* a = table_.get(field) == nullptr ? nullptr : table_.get(field)->as_array();
    if (a == nullptr || a->size() != 3) fail(field, "expected [a, b, c] or a 3×3 array of arrays");
    if ((*a)[0].is_array()) {
      Mat3 m;
      for (std::size_t r = 0; r < 3; ++r)
        m.row(static_cast<Eigen::Index>(r)) = vector_of(&(*a)[r], field).transpose();
      return m;
    }
    return vector(field).asDiagonal();
  }
  const std::string& where() const { return where_; }
  const toml::table& table() const { return table_; }

 private:
  const toml::table& table_;
  std::string where_;
};

const toml::table* table_at(const toml::table& root, const std::string& key) {
  const toml::node* n = root.get(key);
  return n == nullptr ? nullptr : n->as_table();
}

Mat3 body_poinsot(const Fields& f, double mass) {
  const int given = (f.has("inertia") ? 1 : 0) + (f.has("poinsot") ? 1 : 0) + (f.has("shape") ? 1 : 0);
  if (given != 1) f.fail("inertia", "give exactly one of inertia (J), poinsot (K) or shape");
  if (f.has("inertia")) {
    const Mat3 J = f.matrix("inertia");
    return 0.5 * J.trace() * Mat3::Identity() - J;
  }
  if (f.has("poinsot")) return f.matrix("poinsot");
  const toml::table* shape = f.node("shape")->as_table();
  if (shape == nullptr) f.fail("shape", "expected a table { type = ..., ... }");
  const Fields s(*shape, f.where() + ".shape");
  const std::string type = s.text("type");
  if (type == "sphere") {
    const double r = s.number("radius");
    return (mass * r * r / 5.0) * Mat3::Identity();
  }
  if (type == "box") {
    const Vec3 size = s.vector("size");
    return (mass / 12.0) * size.cwiseProduct(size).asDiagonal().toDenseMatrix();
  }
  if (type == "rod" || type == "cylinder") {
    const double l = s.number("length");
    const double r = s.number("radius", 0.0);
    const std::string axis = s.text("axis", "x");
    const int k = axis == "x" ? 0 : axis == "y" ? 1 : axis == "z" ? 2 : -1;
    if (k < 0) s.fail("axis", fmt::format("'{}' is not an axis; expected \"x\", \"y\" or \"z\"", axis));
    Vec3 d = Vec3::Constant(mass * r * r / 4.0);
    d(k) = mass * l * l / 12.0;
    return d.asDiagonal();
  }
  s.fail("type",
         fmt::format("'{}' is not a shape; expected \"rod\", \"cylinder\", \"box\" or \"sphere\"", type));
}

Mat3 body_rotation(const Fields& f) {
  if (f.has("quaternion")) {
    const toml::array* a = f.node("quaternion")->as_array();
    if (a == nullptr || a->size() != 4) f.fail("quaternion", "expected [w, x, y, z]");
    double q[4];
    for (std::size_t k = 0; k < 4; ++k) {
      const std::optional<double> v = (*a)[k].value<double>();
      if (!v) f.fail("quaternion", "expected 4 numbers [w, x, y, z]");
      q[k] = *v;
    }
    return so3::rotation_from_quaternion(Quat(q[0], q[1], q[2], q[3]));
  }
  if (!f.has("rotation")) return Mat3::Identity();
  const toml::node* n = f.node("rotation");
  if (const toml::table* t = n->as_table()) {
    const Fields r(*t, f.where() + ".rotation");
    return so3::rotation_from_axis_angle(r.vector("axis"), r.number("angle"));
  }
  const Mat3 M = f.matrix("rotation");
  if ((M.transpose() * M - Mat3::Identity()).cwiseAbs().maxCoeff() > 1e-9 || M.determinant() < 0) {
    f.fail("rotation",
           fmt::format("{} is not a rotation; expected RᵀR = I to 1e-9 and det R = +1", format_matrix(M)));
  }
  return so3::project_to_so3(M);
}

const BodyState& side(const State& st, int index) {
  return index == kWorld ? world_body_state() : st.bodies[static_cast<std::size_t>(index)];
}

}  // namespace

void project_velocities(const System& system, State& state) {
  if (system.joint_count() == 0) return;
  KktSolver solver(system);
  const auto nj = static_cast<std::size_t>(system.joint_count());
  std::vector<JointJacobian> Ga(nj), Gb(nj);
  for (std::size_t j = 0; j < nj; ++j) {
    const Joint& joint = system.joints()[j];
    joint_jacobians(joint, side(state, joint.body_a), side(state, joint.body_b), Ga[j], Gb[j]);
  }
  solver.factor(Ga, Gb);
  std::vector<Vec6> body(state.bodies.size());
  for (std::size_t i = 0; i < body.size(); ++i) {
    const Body& b = system.bodies()[i];
    body[i] << b.mass * state.bodies[i].v_space, b.inertia * state.bodies[i].omega_body;
  }
  Eigen::VectorXd joint = Eigen::VectorXd::Zero(system.constraint_rows());
  solver.solve(body, joint);  // [M Gᵀ; G 0][v; y] = [M v₀; 0]
  for (std::size_t i = 0; i < body.size(); ++i) {
    state.bodies[i].v_space = body[i].head<3>();
    state.bodies[i].omega_body = body[i].tail<3>();
  }
}

Scenario parse_scenario(const std::string& toml_text, const std::string& source_name) {
  const std::string prefix = fmt::format("scenario {}", source_name);
  toml::table root;
  try {
    root = toml::parse(toml_text, source_name);
  } catch (const toml::parse_error& e) {
    throw InvalidInput(fmt::format("{}: line {}: {}", prefix, e.source().begin.line, e.description()));
  }
  try {
    Scenario sc;
    if (const toml::table* sim = table_at(root, "simulation")) {
      const Fields f(*sim, "simulation");
      sc.dt = f.number("dt", sc.dt);
      sc.duration = f.number("duration", sc.duration);
      const double every = f.number("output_every", sc.output_every);
      if (!(sc.dt > 0)) f.fail("dt", fmt::format("{} s must be > 0", format_number(sc.dt)));
      if (!(sc.duration >= 0))
        f.fail("duration", fmt::format("{} s must be >= 0", format_number(sc.duration)));
      if (!(every >= 1) || every != std::floor(every)) f.fail("output_every", "expected an integer >= 1");
      sc.output_every = static_cast<int>(every);
      sc.system.set_gravity(f.vector("gravity", Vec3::Zero()));
    }
    const toml::array* bodies = root.get("bodies") == nullptr ? nullptr : root.get("bodies")->as_array();
    if (bodies == nullptr || bodies->empty())
      throw InvalidInput("bodies: missing; expected a [[bodies]] array");
    for (std::size_t i = 0; i < bodies->size(); ++i) {
      const toml::table* t = (*bodies)[i].as_table();
      const std::string where = fmt::format("bodies[{}]", i);
      if (t == nullptr) throw InvalidInput(where + ": expected a table");
      const Fields f(*t, where);
      const std::string name = f.text("name", fmt::format("body{}", i));
      const double mass = f.number("mass");
      if (!(mass > 0)) f.fail("mass", fmt::format("{} kg must be > 0", format_number(mass)));
      try {
        sc.system.add_body(name, mass, body_poinsot(f, mass));
      } catch (const InvalidInput& e) {
        throw InvalidInput(fmt::format("{}: {}", where, e.what()));
      }
      BodyState b;
      b.x_space = f.vector("position", Vec3::Zero());
      b.R_space_body = body_rotation(f);
      b.v_space = f.vector("velocity", Vec3::Zero());
      b.omega_body = f.vector("omega_body", Vec3::Zero());
      sc.initial.bodies.push_back(b);
    }
    const State& st = sc.initial;
    const auto body_ref = [&](const Fields& f, const std::string& field, const std::string& fallback) {
      const std::string name = f.text(field, fallback);
      try {
        return sc.system.body_index(name);
      } catch (const InvalidInput&) {
        f.fail(field, fmt::format("no body named '{}'; expected \"world\" or a body's name", name));
      }
    };
    // Default far point: where the near point is at t = 0, in the other body's frame.
    const auto far_point = [&](const Fields& f, int a, const Vec3& pa, int b) {
      if (f.has("point_b")) return f.vector("point_b");
      const BodyState& sa = side(st, a);
      const BodyState& sb = side(st, b);
      return Vec3(sb.R_space_body.transpose() * (sa.x_space + sa.R_space_body * pa - sb.x_space));
    };
    if (const toml::node* n = root.get("joints")) {
      const toml::array* joints = n->as_array();
      if (joints == nullptr) throw InvalidInput("joints: expected a [[joints]] array");
      for (std::size_t j = 0; j < joints->size(); ++j) {
        const toml::table* t = (*joints)[j].as_table();
        const std::string where = fmt::format("joints[{}]", j);
        if (t == nullptr) throw InvalidInput(where + ": expected a table");
        const Fields f(*t, where);
        const std::string name = f.text("name", fmt::format("joint{}", j));
        const int a = body_ref(f, "body_a", "");
        if (a == kWorld) f.fail("body_a", "is the world; expected a body (put the world in body_b)");
        const int b = body_ref(f, "body_b", "world");
        const Vec3 pa = f.vector("point_a", Vec3::Zero());
        const Vec3 pb = far_point(f, a, pa, b);
        const std::string type = f.text("type");
        try {
          if (type == "ball") {
            sc.system.add_ball(name, a, pa, b, pb);
          } else if (type == "hinge") {
            const Vec3 axis_a = f.vector("axis_a");
            const Vec3 axis_b =
                f.has("axis_b")
                    ? f.vector("axis_b")
                    : Vec3(side(st, b).R_space_body.transpose() * (side(st, a).R_space_body * axis_a));
            sc.system.add_hinge(name, a, pa, axis_a, b, pb, axis_b);
          } else if (type == "weld") {
            sc.system.add_weld(name, a, pa, b, pb,
                               side(st, b).R_space_body.transpose() * side(st, a).R_space_body);
          } else {
            f.fail("type",
                   fmt::format("'{}' is not a joint type; expected \"ball\", \"hinge\" or \"weld\"", type));
          }
        } catch (const InvalidInput& e) {
          if (std::string(e.what()).rfind(where, 0) == 0) throw;
          throw InvalidInput(fmt::format("{}: {}", where, e.what()));
        }
      }
    }
    if (const toml::node* n = root.get("springs")) {
      const toml::array* springs = n->as_array();
      if (springs == nullptr) throw InvalidInput("springs: expected a [[springs]] array");
      for (std::size_t k = 0; k < springs->size(); ++k) {
        const toml::table* t = (*springs)[k].as_table();
        const std::string where = fmt::format("springs[{}]", k);
        if (t == nullptr) throw InvalidInput(where + ": expected a table");
        const Fields f(*t, where);
        Spring s;
        s.name = f.text("name", fmt::format("spring{}", k));
        s.body_a = body_ref(f, "body_a", "");
        s.body_b = body_ref(f, "body_b", "world");
        s.point_a = f.vector("point_a", Vec3::Zero());
        s.point_b = f.vector("point_b", Vec3::Zero());
        s.stiffness = f.number("stiffness", 0.0);
        s.damping = f.number("damping", 0.0);
        s.rest_length = f.number("rest_length", 0.0);
        try {
          sc.system.add_spring(s);
        } catch (const InvalidInput& e) {
          throw InvalidInput(fmt::format("{}: {}", where, e.what()));
        }
      }
    }
    if (const toml::node* n = root.get("forces")) {
      const toml::array* forces = n->as_array();
      if (forces == nullptr) throw InvalidInput("forces: expected a [[forces]] array");
      for (std::size_t k = 0; k < forces->size(); ++k) {
        const toml::table* t = (*forces)[k].as_table();
        if (t == nullptr) throw InvalidInput(fmt::format("forces[{}]: expected a table", k));
        const Fields f(*t, fmt::format("forces[{}]", k));
        const int body = body_ref(f, "body", "");
        if (body == kWorld) f.fail("body", "is the world; expected a body");
        sc.system.add_force({body, f.vector("force"), f.vector("point", Vec3::Zero())});
      }
    }
    if (const toml::node* n = root.get("torques")) {
      const toml::array* torques = n->as_array();
      if (torques == nullptr) throw InvalidInput("torques: expected a [[torques]] array");
      for (std::size_t k = 0; k < torques->size(); ++k) {
        const toml::table* t = (*torques)[k].as_table();
        if (t == nullptr) throw InvalidInput(fmt::format("torques[{}]: expected a table", k));
        const Fields f(*t, fmt::format("torques[{}]", k));
        const int body = body_ref(f, "body", "");
        if (body == kWorld) f.fail("body", "is the world; expected a body");
        const std::string frame = f.text("frame", "space");
        if (frame != "space" && frame != "body") {
          f.fail("frame", fmt::format("'{}' is not a frame; expected \"space\" or \"body\"", frame));
        }
        sc.system.add_torque({body, f.vector("torque"), frame == "body"});
      }
    }
    project_velocities(sc.system, sc.initial);
    return sc;
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: {}", prefix, e.what()));
  }
}

Scenario load_scenario(const std::string& toml_path) {
  std::ifstream in(toml_path);
  if (!in)
    throw InvalidInput(
        fmt::format("scenario {}: cannot open the file; expected a readable TOML file", toml_path));
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scenario(text.str(), toml_path);
}

bool is_multibody_scenario(const std::string& toml_path) {
  try {
    const toml::table root = toml::parse_file(toml_path);
    const toml::node* n = root.get("bodies");
    return n != nullptr && n->is_array();
  } catch (const toml::parse_error& e) {
    throw InvalidInput(
        fmt::format("scenario {}: line {}: {}", toml_path, e.source().begin.line, e.description()));
  }
}

}  // namespace poinsot::multibody
