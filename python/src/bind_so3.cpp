// Bindings of the so3 layer as the submodule poinsot.so3. Matrices and vectors are NumPy float64 arrays;
// quaternions are arrays (w, x, y, z).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
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
  m.def("hat", &so3::hat, py::arg("u"), "j(u): the skew matrix with hat(u) @ v == cross(u, v).");
  m.def("vee", &so3::vee, py::arg("m"), "Inverse of hat (vector of the skew part of m).");
  m.def("exp", &so3::exp_checked, py::arg("rotvec"),
        "Rodrigues: rotation matrix of the rotation vector (rad).");
  m.def("log", &so3::log, py::arg("R"), "Rotation vector (angle in [0, pi] times axis) of the rotation R.");
  m.def(
      "rotation_from_quaternion", [](const Vec4& q) { return so3::rotation_from_quaternion(quat_of(q)); },
      py::arg("q"), "Rotation matrix of the quaternion (w, x, y, z), normalised first.");
  m.def(
      "quaternion_from_rotation", [](const Mat3& R) { return wxyz_of(so3::quaternion_from_rotation(R)); },
      py::arg("R"), "Canonical unit quaternion (w, x, y, z), w >= 0, of the rotation R.");
  m.def("rotation_from_axis_angle", &so3::rotation_from_axis_angle, py::arg("axis"), py::arg("angle"),
        "Rotation by angle (rad) about axis (right-hand rule).");
  m.def(
      "rotation_from_euler",
      [](const std::string& seq, const Vec3& angles) {
        return so3::rotation_from_euler(so3::EulerSequence::parse(seq), angles);
      },
      py::arg("sequence"), py::arg("angles"), "Intrinsic Euler angles, e.g. ('ZXZ', [phi, theta, psi]).");
  m.def(
      "euler_from_rotation",
      [](const std::string& seq, const Mat3& R) {
        return so3::euler_from_rotation(so3::EulerSequence::parse(seq), R);
      },
      py::arg("sequence"), py::arg("R"), "Intrinsic Euler angles of R in the named sequence.");
  m.def("cayley", &so3::cayley, py::arg("c"), "Cayley transform (I - j(c))^-1 (I + j(c)).");
  m.def("cayley_inverse", &so3::cayley_inverse, py::arg("R"), "Gibbs vector of R.");
  m.def("project_to_so3", &so3::project_to_so3, py::arg("M"), py::arg("max_orthogonality_error") = 0.1,
        "Nearest rotation (orthogonal polar factor) of a nearly orthogonal matrix.");
  m.def("orthogonality_error", &so3::orthogonality_error, py::arg("R"), "Frobenius norm of R^T R - I.");
  m.def("angle_between", py::overload_cast<const Mat3&, const Mat3&>(&so3::angle_between), py::arg("R1"),
        py::arg("R2"), "Angle (rad) of the rotation R1^T R2.");
}

}  // namespace poinsot::python
