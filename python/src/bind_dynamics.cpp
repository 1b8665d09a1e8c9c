// Bindings of the dynamics layer's model and state: RigidBody, State, the invariants and the torque models,
// including a torque given as a Python callable tau(t, R, omega). Docstrings come from the headers'
// doc comments through the generated docstrings.hpp (python/tools/gen_docstrings.py).
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "docstrings.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/dynamics/torque.hpp"
#include "poinsot/so3/quaternion.hpp"

namespace poinsot::python {

using dynamics::RigidBody;
using dynamics::State;
using dynamics::TorqueModel;

namespace {

// The Python callable is held through a shared_ptr whose deleter takes the GIL: the TorqueModel (and with it
// the std::function) may be destroyed by C++ code that runs without the GIL.
std::shared_ptr<py::function> hold_callable(py::function f) {
  return std::shared_ptr<py::function>(new py::function(std::move(f)), [](py::function* p) {
    py::gil_scoped_acquire gil;
    delete p;
  });
}

}  // namespace

std::shared_ptr<TorqueModel> python_torque(py::function f, bool depends_on_omega, std::string description) {
  auto held = hold_callable(std::move(f));
  TorqueModel::Callback cb = [held](double t, const Mat3& R, const Vec3& omega_body) -> Vec3 {
    // Called from the integrators, possibly with the GIL released by simulate(). A Python exception
    // raised here leaves as py::error_already_set and reaches the caller as the same Python exception.
    py::gil_scoped_acquire gil;
    py::object tau = (*held)(t, from_mat3(R), from_vec3(omega_body));
    return to_vec3(tau, "torque callback: the value returned by tau(t, R, omega)");
  };
  return std::const_pointer_cast<TorqueModel>(
      TorqueModel::callback(std::move(cb), depends_on_omega, std::move(description)));
}

std::shared_ptr<TorqueModel> as_torque(const py::object& torque) {
  if (torque.is_none()) return std::const_pointer_cast<TorqueModel>(TorqueModel::none());
  if (py::isinstance<TorqueModel>(torque)) return torque.cast<std::shared_ptr<TorqueModel>>();
  if (PyCallable_Check(torque.ptr()))
    return python_torque(torque.cast<py::function>(), true, "Python callable");
  throw py::type_error(
      "torque: expected None, a poinsot.TorqueModel or a callable tau(t, R, omega) -> (3,), got " +
      std::string(py::str(py::type::of(torque).attr("__name__"))));
}

State make_state(double time, const py::object& R_space_body, const py::object& quaternion,
                 const py::object& omega_body) {
  State s;
  s.time = time;
  if (!R_space_body.is_none() && !quaternion.is_none())
    throw py::value_error("state: give the orientation as R_space_body or as quaternion, not both");
  if (!R_space_body.is_none()) s.R_space_body = to_mat3(R_space_body, "R_space_body");
  if (!quaternion.is_none()) {
    const Eigen::Vector4d q = to_vec4(quaternion, "quaternion");
    s.R_space_body = so3::rotation_from_quaternion(so3::quaternion_wxyz(q[0], q[1], q[2], q[3]));
  }
  if (!omega_body.is_none()) s.omega_body = to_vec3(omega_body, "omega_body");
  return s;
}

namespace {

/// RigidBody: a body's inertia as the dynamics layer takes it.
void bind_rigid_body(py::module_& m) {
  py::class_<RigidBody>(m, "RigidBody", POINSOT_DOC(file_dynamics_rigid_body))
      .def_static(
          "from_principal_moments",
          [](ArrayLike moments) { return RigidBody::from_principal_moments(to_vec3(moments, "moments")); },
          py::arg("moments"), POINSOT_DOC(dynamics_RigidBody_from_principal_moments))
      .def_static(
          "from_inertia", [](ArrayLike J) { return RigidBody::from_inertia(to_mat3(J, "inertia_com_body")); },
          py::arg("inertia_com_body"), POINSOT_DOC(dynamics_RigidBody_from_inertia))
      .def(
          "with_pivot",
          [](const RigidBody& b, double mass, ArrayLike d) {
            return b.with_pivot(mass, to_vec3(d, "pivot_to_com_body"));
          },
          py::arg("mass"), py::arg("pivot_to_com_body"), POINSOT_DOC(dynamics_RigidBody_with_pivot))
      .def_property_readonly(
          "inertia_com", [](const RigidBody& b) { return from_mat3(b.inertia_com()); },
          POINSOT_DOC(dynamics_RigidBody_inertia_com))
      .def_property_readonly(
          "inertia", [](const RigidBody& b) { return from_mat3(b.inertia()); },
          POINSOT_DOC(dynamics_RigidBody_inertia))
      .def_property_readonly(
          "inertia_inverse", [](const RigidBody& b) { return from_mat3(b.inertia_inverse()); },
          POINSOT_DOC(dynamics_RigidBody_inertia_inverse))
      .def_property_readonly(
          "poinsot", [](const RigidBody& b) { return from_mat3(b.poinsot()); },
          POINSOT_DOC(dynamics_RigidBody_poinsot))
      .def_property_readonly(
          "principal_moments", [](const RigidBody& b) { return from_vec3(b.principal_moments()); },
          POINSOT_DOC(dynamics_RigidBody_principal_moments))
      .def_property_readonly(
          "principal_axes", [](const RigidBody& b) { return from_mat3(b.principal_axes()); },
          POINSOT_DOC(dynamics_RigidBody_principal_axes))
      .def_property_readonly("is_diagonal", &RigidBody::is_diagonal,
                             POINSOT_DOC(dynamics_RigidBody_is_diagonal))
      .def_property_readonly("mass", &RigidBody::mass, POINSOT_DOC(dynamics_RigidBody_mass))
      .def_property_readonly(
          "pivot_to_com", [](const RigidBody& b) { return from_vec3(b.pivot_to_com()); },
          POINSOT_DOC(dynamics_RigidBody_pivot_to_com))
      .def_property_readonly("has_pivot", &RigidBody::has_pivot)
      .def("__repr__", [](const RigidBody& b) {
        std::string s = "RigidBody(principal_moments=" + format_vector(b.principal_moments()) + " kg·m²";
        if (b.has_pivot())
          s += ", mass=" + format_number(b.mass()) + " kg, pivot_to_com=" + format_vector(b.pivot_to_com()) +
               " m";
        return s + ")";
      });
}

/// State: attitude, angular velocity and time.
void bind_body_state(py::module_& m) {
  py::class_<State>(m, "State", POINSOT_DOC(file_dynamics_state))
      .def(py::init(&make_state), py::kw_only(), py::arg("time") = 0.0, py::arg("R_space_body") = py::none(),
           py::arg("quaternion") = py::none(), py::arg("omega_body") = py::none(),
           "A state at time `time` (s) with orientation R_space_body (body → space, 3×3) or quaternion (w, "
           "x, y, "
           "z), and body angular velocity omega_body (rad/s). Defaults: time = 0, R_space_body = I, "
           "omega_body = 0.")
      .def_readwrite("time", &State::time, POINSOT_DOC(dynamics_State_time))
      .def_property(
          "R_space_body", [](const State& s) { return from_mat3(s.R_space_body); },
          [](State& s, ArrayLike R) { s.R_space_body = to_mat3(R, "R_space_body"); },
          POINSOT_DOC(dynamics_State_R_space_body))
      .def_property(
          "omega_body", [](const State& s) { return from_vec3(s.omega_body); },
          [](State& s, ArrayLike w) { s.omega_body = to_vec3(w, "omega_body"); },
          POINSOT_DOC(dynamics_State_omega_body))
      .def(
          "quaternion", [](const State& s) { return from_quat(s.quaternion()); },
          POINSOT_DOC(dynamics_State_quaternion))
      .def(
          "omega_space", [](const State& s) { return from_vec3(s.omega_space()); },
          POINSOT_DOC(dynamics_State_omega_space))
      .def("__repr__", [](const State& s) {
        return "State(time=" + format_number(s.time) + " s, quaternion=" + format_quaternion(s.quaternion()) +
               ", omega_body=" + format_vector(s.omega_body) + " rad/s)";
      });
}

/// Energy, momentum and the checks of a state.
void bind_invariants(py::module_& m) {
  m.def("kinetic_energy", &dynamics::kinetic_energy, py::arg("body"), py::arg("state"),
        POINSOT_DOC(dynamics_kinetic_energy));
  m.def(
      "angular_momentum_body",
      [](const RigidBody& b, const State& s) { return from_vec3(dynamics::angular_momentum_body(b, s)); },
      py::arg("body"), py::arg("state"), POINSOT_DOC(dynamics_angular_momentum_body));
  m.def(
      "angular_momentum_space",
      [](const RigidBody& b, const State& s) { return from_vec3(dynamics::angular_momentum_space(b, s)); },
      py::arg("body"), py::arg("state"), POINSOT_DOC(dynamics_angular_momentum_space));
  m.def(
      "potential_energy",
      [](const RigidBody& b, const State& s, ArrayLike g) {
        return dynamics::potential_energy(b, s, to_vec3(g, "gravity_space"));
      },
      py::arg("body"), py::arg("state"), py::arg("gravity_space"), POINSOT_DOC(dynamics_potential_energy));
  m.def(
      "total_energy",
      [](const RigidBody& b, const State& s, ArrayLike g) {
        return dynamics::total_energy(b, s, to_vec3(g, "gravity_space"));
      },
      py::arg("body"), py::arg("state"), py::arg("gravity_space"), POINSOT_DOC(dynamics_total_energy));
  m.def(
      "validate_state",
      [](const State& s, const std::string& what) { dynamics::validate_state(s, what.c_str()); },
      py::arg("state"), py::arg("what") = "state", POINSOT_DOC(dynamics_validate_state));
}

/// The torque models.
void bind_torque_models(py::module_& m) {
  py::class_<TorqueModel, std::shared_ptr<TorqueModel>>(m, "TorqueModel", POINSOT_DOC(file_dynamics_torque))
      .def(
          "torque_body",
          [](const TorqueModel& tm, double t, ArrayLike R, ArrayLike w) {
            return from_vec3(tm.torque_body(t, to_mat3(R, "R"), to_vec3(w, "omega_body")));
          },
          py::arg("t"), py::arg("R"), py::arg("omega_body"), POINSOT_DOC(dynamics_TorqueModel_torque_body))
      .def_property_readonly("is_zero", &TorqueModel::is_zero, POINSOT_DOC(dynamics_TorqueModel_is_zero))
      .def_property_readonly("depends_on_omega", &TorqueModel::depends_on_omega,
                             POINSOT_DOC(dynamics_TorqueModel_depends_on_omega))
      .def_property_readonly("is_gravity", &TorqueModel::is_gravity,
                             POINSOT_DOC(dynamics_TorqueModel_is_gravity))
      .def_property_readonly(
          "gravity_space", [](const TorqueModel& tm) { return from_vec3(tm.gravity_space()); },
          POINSOT_DOC(dynamics_TorqueModel_gravity_space))
      .def("describe", &TorqueModel::describe, POINSOT_DOC(dynamics_TorqueModel_describe))
      .def("__repr__", [](const TorqueModel& tm) { return "TorqueModel(" + tm.describe() + ")"; })
      .def_static(
          "none", [] { return std::const_pointer_cast<TorqueModel>(TorqueModel::none()); },
          POINSOT_DOC(dynamics_TorqueModel_none))
      .def_static(
          "constant_body",
          [](ArrayLike tau) {
            return std::const_pointer_cast<TorqueModel>(
                TorqueModel::constant_body(to_vec3(tau, "torque_body")));
          },
          py::arg("torque_body"), POINSOT_DOC(dynamics_TorqueModel_constant_body))
      .def_static(
          "constant_space",
          [](ArrayLike tau) {
            return std::const_pointer_cast<TorqueModel>(
                TorqueModel::constant_space(to_vec3(tau, "torque_space")));
          },
          py::arg("torque_space"), POINSOT_DOC(dynamics_TorqueModel_constant_space))
      .def_static(
          "gravity",
          [](const RigidBody& b, ArrayLike g) {
            return std::const_pointer_cast<TorqueModel>(TorqueModel::gravity(b, to_vec3(g, "g_space")));
          },
          py::arg("body"), py::arg("g_space"), POINSOT_DOC(dynamics_TorqueModel_gravity))
      .def_static("callback", &python_torque, py::arg("f"), py::arg("depends_on_omega") = true,
                  py::arg("description") = "Python callable", POINSOT_DOC(dynamics_TorqueModel_Callback));
}

}  // namespace

void bind_dynamics(py::module_& m) {
  bind_rigid_body(m);
  bind_body_state(m);
  bind_invariants(m);
  bind_torque_models(m);
}

}  // namespace poinsot::python
