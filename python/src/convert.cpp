// Checked conversions between NumPy arrays and Eigen types (see convert.hpp).
#include "convert.hpp"

#include <cstring>

namespace poinsot::python {

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) {
    if (i) s += ", ";
    s += std::to_string(a.shape(i));
  }
  if (a.ndim() == 1) s += ",";
  return s + ")";
}

namespace {
std::string expected_shape_text(const std::vector<py::ssize_t>& shape) {
  std::string s = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) {
    if (i) s += ", ";
    s += shape[i] < 0 ? std::string("n") : std::to_string(shape[i]);
  }
  if (shape.size() == 1) s += ",";
  return s + ")";
}
}  // namespace

py::array_t<double, py::array::c_style | py::array::forcecast> to_float_array(
    const py::handle& obj, const char* what, std::vector<py::ssize_t> shape) {
  py::module_ np = py::module_::import("numpy");
  py::array a;
  try {
    a = np.attr("asarray")(obj);
  } catch (py::error_already_set& e) {
    throw py::value_error(std::string(what) + ": expected an array of shape " + expected_shape_text(shape) +
                          " of real numbers, got an object NumPy cannot read as an array (" +
                          std::string(py::str(e.value())) + ")");
  }
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    throw py::type_error(std::string(what) + ": expected real numbers (float64), got dtype " +
                         std::string(py::str(a.dtype())) + " (" + std::string(py::repr(obj)).substr(0, 60) +
                         ")");
  }
  bool ok = a.ndim() == static_cast<py::ssize_t>(shape.size());
  for (std::size_t i = 0; ok && i < shape.size(); ++i)
    ok = shape[i] < 0 || a.shape(static_cast<py::ssize_t>(i)) == shape[i];
  if (!ok) {
    throw py::value_error(std::string(what) + ": expected an array of shape " + expected_shape_text(shape) +
                          ", got shape " + shape_text(a));
  }
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
}

Vec3 to_vec3(const py::handle& obj, const char* what) {
  auto a = to_float_array(obj, what, {3});
  const double* p = a.data();
  return Vec3(p[0], p[1], p[2]);
}

Eigen::Vector4d to_vec4(const py::handle& obj, const char* what) {
  auto a = to_float_array(obj, what, {4});
  const double* p = a.data();
  return Eigen::Vector4d(p[0], p[1], p[2], p[3]);
}

Mat3 to_mat3(const py::handle& obj, const char* what) {
  auto a = to_float_array(obj, what, {3, 3});
  const double* p = a.data();
  Mat3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      m(i, j) = p[3 * i + j];
  return m;
}

py::array_t<double> from_vec3(const Vec3& v) {
  py::array_t<double> a(3);
  std::memcpy(a.mutable_data(), v.data(), 3 * sizeof(double));
  return a;
}

py::array_t<double> from_vec4(const Eigen::Vector4d& v) {
  py::array_t<double> a(4);
  std::memcpy(a.mutable_data(), v.data(), 4 * sizeof(double));
  return a;
}

py::array_t<double> from_mat3(const Mat3& m) {
  py::array_t<double> a({3, 3});
  double* p = a.mutable_data();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      p[3 * i + j] = m(i, j);
  return a;
}

py::array_t<double> from_quat(const Quat& q) {
  return from_vec4(Eigen::Vector4d(q.w(), q.x(), q.y(), q.z()));
}

py::array_t<double> array_from_buffer(std::vector<double>&& buffer, std::vector<py::ssize_t> shape) {
  auto* owned = new std::vector<double>(std::move(buffer));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>(shape, owned->data(), owner);
}

py::array_t<double> stack_vec3(const std::vector<Vec3>& v) {
  std::vector<double> buf;
  buf.reserve(3 * v.size());
  for (const Vec3& x : v)
    buf.insert(buf.end(), {x[0], x[1], x[2]});
  return array_from_buffer(std::move(buf), {static_cast<py::ssize_t>(v.size()), 3});
}

py::array_t<double> stack_mat3(const std::vector<Mat3>& v) {
  std::vector<double> buf;
  buf.reserve(9 * v.size());
  for (const Mat3& M : v)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        buf.push_back(M(i, j));
  return array_from_buffer(std::move(buf), {static_cast<py::ssize_t>(v.size()), 3, 3});
}

}  // namespace poinsot::python
