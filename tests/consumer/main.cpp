// Uses the installed library: a quarter turn about z must take x to y. Exit status 0 when it does.
#include <cstdio>

#include <poinsot/so3/exp_log.hpp>
#include <poinsot/so3/quaternion.hpp>
#include <poinsot/version.hpp>

int main() {
  const poinsot::Mat3 R = poinsot::so3::exp_checked(poinsot::Vec3(0.0, 0.0, 1.5707963267948966));
  const poinsot::Quat q = poinsot::so3::quaternion_from_rotation(R);
  const double err = (R * poinsot::Vec3::UnitX() - poinsot::Vec3::UnitY()).norm();
  std::printf("consumer: poinsot %s, quaternion w = %.17g, error %.3g\n", poinsot::kVersion, q.w(), err);
  return err < 1e-15 ? 0 : 1;
}
