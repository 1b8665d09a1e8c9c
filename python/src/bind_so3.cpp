// Bindings of the so3 layer as the submodule poinsot.so3. Matrices and vectors are NumPy float64 arrays;
// quaternions are arrays (w, x, y, z).
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "convert.hpp"
#include "docstrings.hpp"
#include "poinsot/so3/axis_angle.hpp"
#include "poinsot/so3/cayley.hpp"
#include "poinsot/so3/distance.hpp"
#include "poinsot/so3/euler_angles.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot/so3/hat.hpp"
#include "poinsot/so3/projection.hpp"
#include "poinsot/so3/quaternion.hpp"

namespace py = pybind11;

namespace poinsot::python {
namespace {
using Vec4 = Eigen::Vector4d;
Quat quat_of(const Vec4& wxyz) {
  return Quat(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
}
Vec4 wxyz_of(const Quat& q) {
  return Vec4(q.w(), q.x(), q.y(), q.z());
}
}  // namespace

void bind_so3(py::module_& parent) {
  auto m = parent.def_submodule("so3",
                                "Rotations: hat/vee, exp/log, quaternions (w, x, y, z), Euler angles, "
                                "Cayley transform, projection onto SO(3). R maps body to space.");
  m.def(
      "hat", [](ArrayLike u) { return from_mat3(so3::hat(to_vec3(u, "u"))); }, py::arg("u"),
      POINSOT_DOC(so3_hat));
  m.def(
      "vee", [](ArrayLike M) { return from_vec3(so3::vee(to_mat3(M, "m"))); }, py::arg("m"),
      POINSOT_DOC(so3_vee));
  m.def(
      "exp", [](ArrayLike v) { return from_mat3(so3::exp_checked(to_vec3(v, "rotvec"))); }, py::arg("rotvec"),
      (std::string(POINSOT_DOC(so3_exp_checked)) + "\n\n" + POINSOT_DOC(so3_exp)).c_str());
  m.def(
      "log", [](ArrayLike R) { return from_vec3(so3::log(to_mat3(R, "R"))); }, py::arg("R"),
      POINSOT_DOC(so3_log));
  m.def(
      "rotation_from_quaternion",
      [](ArrayLike q) { return from_mat3(so3::rotation_from_quaternion(quat_of(to_vec4(q, "q")))); },
      py::arg("q"), POINSOT_DOC(so3_rotation_from_quaternion));
  m.def(
      "quaternion_from_rotation",
      [](ArrayLike R) { return from_vec4(wxyz_of(so3::quaternion_from_rotation(to_mat3(R, "R")))); },
      py::arg("R"), POINSOT_DOC(so3_quaternion_from_rotation));
  m.def(
      "rotation_from_axis_angle",
      [](ArrayLike axis, double angle) {
        return from_mat3(so3::rotation_from_axis_angle(to_vec3(axis, "axis"), angle));
      },
      py::arg("axis"), py::arg("angle"), POINSOT_DOC(so3_rotation_from_axis_angle));
  m.def(
      "rotation_from_euler",
      [](const std::string& seq, ArrayLike angles) {
        return from_mat3(so3::rotation_from_euler(so3::EulerSequence::parse(seq), to_vec3(angles, "angles")));
      },
      py::arg("sequence"), py::arg("angles"),
      (std::string("Intrinsic Euler angles (rad), e.g. ('ZXZ', [phi, theta, psi]).\n\n") +
       POINSOT_DOC(so3_rotation_from_euler) + "\n\n" + POINSOT_DOC(file_so3_euler_angles))
          .c_str());
  m.def(
      "euler_from_rotation",
      [](const std::string& seq, ArrayLike R) {
        return from_vec3(so3::euler_from_rotation(so3::EulerSequence::parse(seq), to_mat3(R, "R")));
      },
      py::arg("sequence"), py::arg("R"), POINSOT_DOC(so3_euler_from_rotation));
  m.def(
      "cayley", [](ArrayLike c) { return from_mat3(so3::cayley(to_vec3(c, "c"))); }, py::arg("c"),
      POINSOT_DOC(so3_cayley));
  m.def(
      "cayley_inverse", [](ArrayLike R) { return from_vec3(so3::cayley_inverse(to_mat3(R, "R"))); },
      py::arg("R"), POINSOT_DOC(so3_cayley_inverse));
  m.def(
      "project_to_so3",
      [](ArrayLike M, double tol) { return from_mat3(so3::project_to_so3(to_mat3(M, "M"), tol)); },
      py::arg("M"), py::arg("max_orthogonality_error") = 0.1, POINSOT_DOC(so3_project_to_so3));
  m.def(
      "orthogonality_error", [](ArrayLike R) { return so3::orthogonality_error(to_mat3(R, "R")); },
      py::arg("R"), POINSOT_DOC(so3_orthogonality_error));
  m.def(
      "angle_between",
      [](ArrayLike R1, ArrayLike R2) { return so3::angle_between(to_mat3(R1, "R1"), to_mat3(R2, "R2")); },
      py::arg("R1"), py::arg("R2"), POINSOT_DOC(so3_angle_between));
}

}  // namespace poinsot::python
