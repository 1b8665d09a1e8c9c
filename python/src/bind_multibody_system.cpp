// Bindings of poinsot.multibody.System: the model of bodies, joints and loads (multibody/model.hpp,
// loads.hpp). Bodies are named by index or by name ("world" or poinsot.multibody.WORLD for the fixed frame).
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "docstrings.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/inertia/mass_properties.hpp"
#include "poinsot/io/robot/robot_system.hpp"
#include "poinsot/multibody/loads.hpp"
#include "poinsot/multibody/model.hpp"

namespace poinsot::python {

namespace mb = poinsot::multibody;

namespace {

// A body given by index (int, WORLD = -1) or by name (str, "world"); the System validates the index.
int body_ref(const mb::System& s, const py::handle& body, const char* what) {
  if (py::isinstance<py::str>(body)) return s.body_index(body.cast<std::string>());
  if (py::isinstance<py::int_>(body)) return body.cast<int>();
  throw py::type_error(std::string(what) + ": expected a body index (int) or a body name (str), got " +
                       std::string(py::str(py::type::of(body).attr("__name__"))));
}

/// The System class and its bodies: construction, robot files, add_body*.
void bind_system_bodies(py::class_<mb::System>& system) {
  system.def(py::init<>(), "An empty system: no bodies, no joints, no gravity.")
      .def_static(
          "from_file", [](const std::string& path) { return io::load_robot_scenario(path).system; },
          py::arg("path"),
          (std::string("The system of a robot file (URDF, MJCF, SDF) at its file pose; "
                       "multibody.load_robot gives its initial state too. ") +
           POINSOT_DOC(io_robot_scenario))
              .c_str())
      .def(
          "add_body",
          [](mb::System& s, const std::string& name, double mass, ArrayLike K) {
            return s.add_body(name, mass, to_mat3(K, "poinsot_com_body"));
          },
          py::arg("name"), py::arg("mass"), py::arg("poinsot_com_body"),
          POINSOT_DOC(multibody_System_add_body))
      .def(
          "add_body_from_inertia",
          [](mb::System& s, const std::string& name, double mass, ArrayLike J) {
            return s.add_body_from_inertia(name, mass, to_mat3(J, "inertia_com_body"));
          },
          py::arg("name"), py::arg("mass"), py::arg("inertia_com_body"),
          POINSOT_DOC(multibody_System_add_body_from_inertia))
      .def(
          "add_body_from_mass_properties",
          [](mb::System& s, const std::string& name, const inertia::MassProperties& p) {
            return s.add_body_from_inertia(name, p.mass, p.inertia_com);
          },
          py::arg("name"), py::arg("mass_properties"),
          "Adds a body from the inertia layer's MassProperties (a shape, a mesh, a composite: "
          "poinsot.inertia): its mass (kg) and J about its centre of mass (kg·m²), in the axes of the frame "
          "F they were given in. The body's frame has F's axes and its origin at the centre of mass: its "
          "x_space is the centre of mass, and a point p given in F is p − center_of_mass in the body frame. "
          "Returns the body's index.");
}

/// System: the joints (ball, hinge, weld, universal, prismatic).
void bind_system_joints(py::class_<mb::System>& system) {
  system
      .def(
          "add_ball",
          [](mb::System& s, const std::string& name, const py::object& a, ArrayLike pa, const py::object& b,
             ArrayLike pb) {
            return s.add_ball(name, body_ref(s, a, "body_a"), to_vec3(pa, "point_a"),
                              body_ref(s, b, "body_b"),
                              pb.obj.is_none() ? Vec3::Zero().eval() : to_vec3(pb, "point_b"));
          },
          py::arg("name"), py::arg("body_a"), py::arg("point_a"), py::arg("body_b") = mb::kWorld,
          py::arg("point_b") = py::none(), POINSOT_DOC(multibody_System_add_ball))
      .def(
          "add_hinge",
          [](mb::System& s, const std::string& name, const py::object& a, ArrayLike pa, ArrayLike axis_a,
             const py::object& b, ArrayLike pb, ArrayLike axis_b) {
            return s.add_hinge(name, body_ref(s, a, "body_a"), to_vec3(pa, "point_a"),
                               to_vec3(axis_a, "axis_a"), body_ref(s, b, "body_b"), to_vec3(pb, "point_b"),
                               to_vec3(axis_b, "axis_b"));
          },
          py::arg("name"), py::arg("body_a"), py::arg("point_a"), py::arg("axis_a"), py::arg("body_b"),
          py::arg("point_b"), py::arg("axis_b"), POINSOT_DOC(multibody_System_add_hinge))
      .def(
          "add_weld",
          [](mb::System& s, const std::string& name, const py::object& a, ArrayLike pa, const py::object& b,
             ArrayLike pb, ArrayLike R_b_a) {
            return s.add_weld(name, body_ref(s, a, "body_a"), to_vec3(pa, "point_a"),
                              body_ref(s, b, "body_b"), to_vec3(pb, "point_b"), to_mat3(R_b_a, "R_b_a"));
          },
          py::arg("name"), py::arg("body_a"), py::arg("point_a"), py::arg("body_b"), py::arg("point_b"),
          py::arg("R_b_a"), POINSOT_DOC(multibody_System_add_weld))
      .def(
          "add_universal",
          [](mb::System& s, const std::string& name, const py::object& a, ArrayLike pa, ArrayLike axis_a,
             const py::object& b, ArrayLike pb, ArrayLike axis_b, double axis_offset) {
            return s.add_universal(name, body_ref(s, a, "body_a"), to_vec3(pa, "point_a"),
                                   to_vec3(axis_a, "axis_a"), body_ref(s, b, "body_b"),
                                   to_vec3(pb, "point_b"), to_vec3(axis_b, "axis_b"), axis_offset);
          },
          py::arg("name"), py::arg("body_a"), py::arg("point_a"), py::arg("axis_a"), py::arg("body_b"),
          py::arg("point_b"), py::arg("axis_b"), py::arg("axis_offset") = 0.0,
          POINSOT_DOC(multibody_System_add_universal))
      .def(
          "add_prismatic",
          [](mb::System& s, const std::string& name, const py::object& a, ArrayLike pa, ArrayLike axis_a,
             const py::object& b, ArrayLike pb, ArrayLike R_b_a) {
            return s.add_prismatic(name, body_ref(s, a, "body_a"), to_vec3(pa, "point_a"),
                                   to_vec3(axis_a, "axis_a"), body_ref(s, b, "body_b"),
                                   to_vec3(pb, "point_b"), to_mat3(R_b_a, "R_b_a"));
          },
          py::arg("name"), py::arg("body_a"), py::arg("point_a"), py::arg("axis_a"), py::arg("body_b"),
          py::arg("point_b"), py::arg("R_b_a"), POINSOT_DOC(multibody_System_add_prismatic));
}

/// System: the loads (springs between points, joint springs, constant forces and torques).
void bind_system_loads(py::class_<mb::System>& system) {
  system
      .def(
          "add_spring",
          [](mb::System& s, const std::string& name, const py::object& a, ArrayLike pa, const py::object& b,
             ArrayLike pb, double stiffness, double damping, double rest_length) {
            mb::Spring sp;
            sp.name = name;
            sp.body_a = body_ref(s, a, "body_a");
            sp.point_a = to_vec3(pa, "point_a");
            sp.body_b = body_ref(s, b, "body_b");
            sp.point_b = to_vec3(pb, "point_b");
            sp.stiffness = stiffness;
            sp.damping = damping;
            sp.rest_length = rest_length;
            return s.add_spring(sp);
          },
          py::arg("name"), py::arg("body_a"), py::arg("point_a"), py::arg("body_b"), py::arg("point_b"),
          py::kw_only(), py::arg("stiffness"), py::arg("damping") = 0.0, py::arg("rest_length") = 0.0,
          POINSOT_DOC(multibody_Spring))
      .def(
          "add_joint_spring",
          [](mb::System& s, int joint, double stiffness, double damping, double rest_position,
             const py::object& R_b_a_zero, double offset, const std::string& coordinate,
             const py::object& hinge_axes) {
            mb::JointSpring sp;
            sp.joint = joint;
            using C = mb::JointSpring::Coordinate;
            bool known = false;
            for (const C c : {C::a, C::b, C::first, C::second, C::third}) {
              if (coordinate == mb::joint_spring_coordinate_name(c)) {
                sp.coordinate = c;
                known = true;
              }
            }
            if (!known) {
              throw InvalidInput(
                  "add_joint_spring: coordinate: got \"" + coordinate +
                  "\"; expected \"a\" or \"b\" (a universal joint's angle about axis a or b) or "
                  "\"first\", \"second\" or \"third\" (a ball joint's hinge)");
            }
            if (!hinge_axes.is_none()) {
              const Mat3 axes = to_mat3(hinge_axes, "hinge_axes");
              for (int k = 0; k < 3; ++k)
                sp.hinge_axes[static_cast<std::size_t>(k)] = axes.row(k).transpose();
            }
            sp.stiffness = stiffness;
            sp.damping = damping;
            sp.rest_position = rest_position;
            if (!R_b_a_zero.is_none()) sp.R_b_a_zero = to_mat3(R_b_a_zero, "R_b_a_zero");
            sp.offset = offset;
            return s.add_joint_spring(sp);
          },
          py::arg("joint"), py::kw_only(), py::arg("stiffness") = 0.0, py::arg("damping") = 0.0,
          py::arg("rest_position") = 0.0, py::arg("R_b_a_zero") = py::none(), py::arg("offset") = 0.0,
          py::arg("coordinate") = "a", py::arg("hinge_axes") = py::none(),
          (std::string(POINSOT_DOC(multibody_System_add_joint_spring)) +
           "\n\ncoordinate: \"a\" or \"b\", the angle of a universal joint the spring acts on; \"first\", "
           "\"second\" or \"third\", the hinge of a ball joint.\nhinge_axes: a ball joint's three hinge axes "
           "e₁, "
           "e₂, e₃ as the rows of a 3 × 3 array (body a's frame at q = 0).\n\n" +
           POINSOT_DOC(multibody_JointSpring))
              .c_str())
      .def(
          "add_force",
          [](mb::System& s, const py::object& body, ArrayLike f, ArrayLike p) {
            mb::ConstantForce c;
            c.body = body_ref(s, body, "body");
            c.force_space = to_vec3(f, "force_space");
            if (!p.obj.is_none()) c.point_body = to_vec3(p, "point_body");
            s.add_force(c);
          },
          py::arg("body"), py::arg("force_space"), py::arg("point_body") = py::none(),
          POINSOT_DOC(multibody_ConstantForce))
      .def(
          "add_torque",
          [](mb::System& s, const py::object& body, ArrayLike tau, bool in_body_frame) {
            mb::ConstantTorque c;
            c.body = body_ref(s, body, "body");
            c.torque = to_vec3(tau, "torque");
            c.in_body_frame = in_body_frame;
            s.add_torque(c);
          },
          py::arg("body"), py::arg("torque"), py::kw_only(), py::arg("in_body_frame") = false,
          POINSOT_DOC(multibody_ConstantTorque));
}

/// System: gravity, names, masses and tensors, indices, rows and length scale.
void bind_system_queries(py::class_<mb::System>& system) {
  system
      .def_property(
          "gravity", [](const mb::System& s) { return from_vec3(s.gravity()); },
          [](mb::System& s, ArrayLike g) { s.set_gravity(to_vec3(g, "gravity_space")); },
          POINSOT_DOC(multibody_System_set_gravity))
      .def_property_readonly("body_count", &mb::System::body_count, "Number of bodies.")
      .def_property_readonly("joint_count", &mb::System::joint_count, "Number of joints.")
      .def_property_readonly(
          "body_names",
          [](const mb::System& s) {
            std::vector<std::string> n;
            for (const auto& b : s.bodies())
              n.push_back(b.name);
            return n;
          },
          "The bodies' names, in index order.")
      .def_property_readonly(
          "joint_names",
          [](const mb::System& s) {
            std::vector<std::string> n;
            for (const auto& j : s.joints())
              n.push_back(j.name);
            return n;
          },
          "The joints' names, in index order.")
      .def_property_readonly(
          "masses",
          [](const mb::System& s) {
            std::vector<double> v;
            for (const auto& b : s.bodies())
              v.push_back(b.mass);
            return array_from_buffer(std::move(v), {s.body_count()});
          },
          POINSOT_DOC(multibody_Body_mass))
      .def_property_readonly(
          "poinsot_tensors",
          [](const mb::System& s) {
            std::vector<Mat3> v;
            for (const auto& b : s.bodies())
              v.push_back(b.poinsot);
            return stack_mat3(v);
          },
          POINSOT_DOC(multibody_Body_poinsot))
      .def_property_readonly(
          "inertia_tensors",
          [](const mb::System& s) {
            std::vector<Mat3> v;
            for (const auto& b : s.bodies())
              v.push_back(b.inertia);
            return stack_mat3(v);
          },
          POINSOT_DOC(multibody_Body_inertia))
      .def("body_index", &mb::System::body_index, py::arg("name"), POINSOT_DOC(multibody_System_body_index))
      .def("constraint_rows", &mb::System::constraint_rows, POINSOT_DOC(multibody_System_constraint_rows))
      .def("length_scale", &mb::System::length_scale, POINSOT_DOC(multibody_System_length_scale))
      .def("__repr__", [](const mb::System& s) {
        return "System(bodies=" + std::to_string(s.body_count()) +
               ", joints=" + std::to_string(s.joint_count()) + ", gravity=" + format_vector(s.gravity()) +
               " m/s²)";
      });
}

}  // namespace

void bind_multibody_system(py::module_& m) {
  py::class_<mb::System> system(m, "System", POINSOT_DOC(multibody_System));
  bind_system_bodies(system);
  bind_system_joints(system);
  bind_system_loads(system);
  bind_system_queries(system);
}

}  // namespace poinsot::python
