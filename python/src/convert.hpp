#pragma once
// Checked conversions between NumPy arrays (or anything np.asarray accepts) and poinsot's Eigen types.
//
// Arguments arrive as `ArrayLike` (any Python object; the signature shows `numpy.typing.ArrayLike`) and are
// converted by `to_vec3(obj, "omega_body")` and friends, which raise
//   TypeError  "omega_body: expected real numbers (float64), got dtype complex128"
//   ValueError "omega_body: expected an array of shape (3,), got shape (4,)"
// naming the argument, so a wrong array never produces pybind11's generic "incompatible function arguments".
// Results go back as fresh float64 arrays (row-major, C order), or as views of a C++ buffer owned by a
// capsule.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <utility>
#include <vector>

#include "poinsot/core/types.hpp"

namespace poinsot::python {

namespace py = pybind11;

/// Any Python object, to be converted by to_vec3 / to_mat3 / ... with the argument's name in the errors.
struct ArrayLike {
  py::object obj;
};

std::string shape_text(const py::array& a);
/// np.asarray(obj) checked to hold real numbers (integer or floating dtype) and to have `shape`
/// (-1 = any extent), then cast to float64 (C order).
py::array_t<double, py::array::c_style | py::array::forcecast> to_float_array(const py::handle& obj,
                                                                              const char* what,
                                                                              std::vector<py::ssize_t> shape);

Vec3 to_vec3(const py::handle& obj, const char* what);
Mat3 to_mat3(const py::handle& obj, const char* what);
Eigen::Vector4d to_vec4(const py::handle& obj, const char* what);
inline Vec3 to_vec3(const ArrayLike& a, const char* what) {
  return to_vec3(a.obj, what);
}
inline Mat3 to_mat3(const ArrayLike& a, const char* what) {
  return to_mat3(a.obj, what);
}
inline Eigen::Vector4d to_vec4(const ArrayLike& a, const char* what) {
  return to_vec4(a.obj, what);
}

py::array_t<double> from_vec3(const Vec3& v);
py::array_t<double> from_vec4(const Eigen::Vector4d& v);
py::array_t<double> from_mat3(const Mat3& m);
/// (w, x, y, z) of a quaternion.
py::array_t<double> from_quat(const Quat& q);

/// Hands a std::vector<double> to NumPy without copying: the array's memory is the vector's, owned by a
/// capsule that deletes the vector when the last array referring to it goes away.
py::array_t<double> array_from_buffer(std::vector<double>&& buffer, std::vector<py::ssize_t> shape);

/// The vectors stacked as an (N, 3) array.
py::array_t<double> stack_vec3(const std::vector<Vec3>& v);

/// The matrices stacked as an (N, 3, 3) array, row by row.
py::array_t<double> stack_mat3(const std::vector<Mat3>& v);

}  // namespace poinsot::python

namespace pybind11::detail {
template <>
struct type_caster<poinsot::python::ArrayLike> {
  PYBIND11_TYPE_CASTER(poinsot::python::ArrayLike, const_name("numpy.typing.ArrayLike"));
  bool load(handle src, bool) {
    if (!src) return false;
    value.obj = reinterpret_borrow<object>(src);
    return true;
  }
  static handle cast(const poinsot::python::ArrayLike& a, return_value_policy, handle) {
    return a.obj.inc_ref();
  }
};
}  // namespace pybind11::detail
