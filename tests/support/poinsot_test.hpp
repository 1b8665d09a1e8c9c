#pragma once
// Test helpers shared by every layer's tests: tolerances scaled by the problem's magnitude (as MuJoCo's test
// utilities do), a random source seeded per test, random rotations uniform on SO(3), matrix comparisons
// (absolute and relative) and checks of thrown one-line error messages.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <dlfcn.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/types.hpp"

namespace poinsot::test {

namespace detail {
/// The paths that temp_path handed out in this process; each is removed (file or folder, with its content)
/// when the process exits, unless POINSOT_KEEP_TEST_FILES is set (to look at a failed test's output).
struct TempPaths {
  std::vector<std::filesystem::path> paths;
  TempPaths() = default;
  TempPaths(const TempPaths&) = delete;
  TempPaths& operator=(const TempPaths&) = delete;
  ~TempPaths() {
    if (std::getenv("POINSOT_KEEP_TEST_FILES") != nullptr) return;
    for (const auto& p : paths) {
      std::error_code ignored;
      std::filesystem::remove_all(p, ignored);
    }
  }
};
inline TempPaths& temp_paths() {
  static TempPaths registry;
  return registry;
}
}  // namespace detail

/// A path in the temporary folder that no other test process uses at the same time: NAME followed by this
/// process's id (tests of two build trees, or two CTest jobs, may run side by side on one machine). What the
/// test writes there is removed when the test process exits (detail::TempPaths).
inline std::filesystem::path temp_path(const std::string& name) {
  auto path = std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
  auto& paths = detail::temp_paths().paths;
  if (std::find(paths.begin(), paths.end(), path) == paths.end()) paths.push_back(path);
  return path;
}

/// Whether this test process runs under AddressSanitizer (its runtime is loaded), asked at run time: the CI's
/// sanitizer tree may link test objects compiled without it (tests/CMakeLists.txt,
/// POINSOT_TEST_OBJECTS_FROM). The tests that take minutes there skip with `if (sanitized()) GTEST_SKIP() <<
/// why;`.
inline bool sanitized() {
  static const bool loaded = ::dlsym(RTLD_DEFAULT, "__asan_init") != nullptr;
  return loaded;
}

/// The whole content of a text file ("" when it cannot be read: the test's comparison then fails).
inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline constexpr double kEps = std::numeric_limits<double>::epsilon();  // 2.22e-16

/// The random engine of the running test, seeded from the test's full name (FNV-1a of "Suite.Name", mixed
/// with a fixed constant): each test draws the same numbers whatever the other tests, their order or
/// --gtest_filter, so a failure is reproducible by running that test alone. Reseeded when the running test
/// changes (outside a test: the seed of the empty name).
inline std::mt19937_64& rng() {
  static std::mt19937_64 engine;
  static std::string seeded_for = "\x01";  // no test's name
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info != nullptr ? std::string(info->test_suite_name()) + "." + info->name() : "";
  if (name != seeded_for) {
    std::uint64_t h = 14695981039346656037ull;
    for (const char c : name)
      h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    engine.seed(h ^ 20261121u);
    seeded_for = std::move(name);
  }
  return engine;
}

inline double uniform(double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng());
}

inline Vec3 random_vector(double scale = 1.0) {
  return Vec3(uniform(-scale, scale), uniform(-scale, scale), uniform(-scale, scale));
}

/// A unit vector uniformly distributed on the sphere.
inline Vec3 random_unit_vector() {
  std::normal_distribution<double> n(0.0, 1.0);
  Vec3 v(n(rng()), n(rng()), n(rng()));
  return v.normalized();
}

/// A unit quaternion uniformly distributed on S³, i.e. a rotation uniform on SO(3) (Haar measure).
inline Quat random_quaternion() {
  std::normal_distribution<double> n(0.0, 1.0);
  Quat q(n(rng()), n(rng()), n(rng()), n(rng()));
  q.normalize();
  return q;
}

inline Mat3 random_rotation() {
  return random_quaternion().toRotationMatrix();
}

/// Max-norm of a difference of matrices or vectors.
template <class A, class B>
double max_abs_diff(const A& a, const B& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

/// EXPECTs every piece to occur in `message` (the parts of a one-line error: file, key, value, expectation).
inline void expect_has(const std::string& message, std::initializer_list<std::string> pieces) {
  for (const auto& p : pieces) {
    EXPECT_NE(message.find(p), std::string::npos) << "expected \"" << p << "\" in: " << message;
  }
}

/// The message of the exception of type E that `f()` throws; a test failure (and "") when it throws
/// nothing. An exception of another type propagates (gtest reports it). Also EXPECTs the message to be one
/// line, as every poinsot error is.
template <class E = InvalidInput, class F>
std::string message_of(F&& f, std::string_view what = "the statement") {
  try {
    f();
  } catch (const E& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << "a message of more than one line: " << message;
    return message;
  }
  ADD_FAILURE() << "expected " << what << " to throw";
  return "";
}

/// Absolute comparison of two matrices (or vectors) of the same shape: max |a − b| ≤ tol.
template <class A, class B>
::testing::AssertionResult matrix_near(const A& a, const B& b, double tol) {
  const double d = (a - b).cwiseAbs().maxCoeff();
  if (d <= tol) return ::testing::AssertionSuccess();
  std::ostringstream out;
  out.precision(17);
  out << "max |a - b| = " << d << " > " << tol << "\na =\n" << a << "\nb =\n" << b;
  return ::testing::AssertionFailure() << out.str();
}

/// Relative comparison: max |a − b| ≤ rtol · max |b| (the reference's largest entry sets the scale; an
/// all-zero reference requires a == b).
template <class A, class B>
::testing::AssertionResult matrix_rel_near(const A& a, const B& b, double rtol) {
  return matrix_near(a, b, rtol * b.cwiseAbs().maxCoeff());
}

}  // namespace poinsot::test

/// EXPECT that `statement` throws EXCEPTION whose one-line message contains each of the given pieces:
/// POINSOT_EXPECT_THROWS_MESSAGE(f(x), InvalidInput, "x: got -1", "expected a number > 0").
#define POINSOT_EXPECT_THROWS_MESSAGE(statement, exception, ...) \
  ::poinsot::test::expect_has(                                   \
      ::poinsot::test::message_of<exception>([&] { (void)(statement); }, #statement), {__VA_ARGS__})

/// EXPECT max |a − b| ≤ tol (absolute), printing both on failure.
#define POINSOT_EXPECT_MATRIX_NEAR(a, b, tol) EXPECT_TRUE(::poinsot::test::matrix_near((a), (b), (tol)))
/// EXPECT max |a − b| ≤ rtol · max |b| (relative to the reference b), printing both on failure.
#define POINSOT_EXPECT_MATRIX_REL_NEAR(a, b, rtol) \
  EXPECT_TRUE(::poinsot::test::matrix_rel_near((a), (b), (rtol)))
