// The multipliers of a multibody run at every frame of its page (see view_multipliers.hpp).
#include "view_multipliers.hpp"

#include <array>

#include "poinsot/multibody/multipliers.hpp"
#include "poinsot/so3/quaternion.hpp"

namespace poinsot::io {

FrameMultipliers frame_multipliers(const multibody::System& system, const CsvFrames& f,
                                   const std::string& path) {
  const std::size_t n = system.bodies().size();
  // Per body the 13 columns x y z qw qx qy qz vx vy vz wx wy wz.
  static constexpr std::array<const char*, 13> kSuffix = {".x",  ".y",  ".z",  ".qw", ".qx", ".qy", ".qz",
                                                          ".vx", ".vy", ".vz", ".wx", ".wy", ".wz"};
  std::vector<std::array<std::size_t, 13>> col(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t c = 0; c < kSuffix.size(); ++c)
      col[i][c] = csv_column(f, system.bodies()[i].name + kSuffix[c], path);
  const std::size_t t_col = csv_column(f, "t", path);

  FrameMultipliers out;
  out.reactions.reserve(f.values.size() * system.joints().size() * 6);
  out.lambda.reserve(f.values.size() * n * 6);
  multibody::State st;
  st.bodies.resize(n);
  for (const std::vector<double>& row : f.values) {
    st.time = row[t_col];
    for (std::size_t i = 0; i < n; ++i) {
      const auto& c = col[i];
      multibody::BodyState& b = st.bodies[i];
      b.x_space = Vec3(row[c[0]], row[c[1]], row[c[2]]);
      b.R_space_body = so3::rotation_from_quaternion(Quat(row[c[3]], row[c[4]], row[c[5]], row[c[6]]));
      b.v_space = Vec3(row[c[7]], row[c[8]], row[c[9]]);
      b.omega_body = Vec3(row[c[10]], row[c[11]], row[c[12]]);
    }
    const multibody::ExactMultipliers ex = multibody::exact_multipliers(system, st);
    for (std::size_t j = 0; j < system.joints().size(); ++j) {
      const Vec3& F = ex.joint_force_space[j];
      const Vec3& C = ex.joint_torque_space[j];
      for (double v : {F.x(), F.y(), F.z(), C.x(), C.y(), C.z()})
        out.reactions.push_back(rounded_for_drawing(v));
    }
    for (const Mat3& L : ex.Lambda_body) {
      const Mat3 S = 0.5 * (L + L.transpose());
      for (double v : {S(0, 0), S(1, 1), S(2, 2), S(0, 1), S(0, 2), S(1, 2)})
        out.lambda.push_back(rounded_for_drawing(v));
    }
  }
  return out;
}

}  // namespace poinsot::io
