// Fuzz harness: robot files as multibody systems (io/robot/robot_system.hpp): the readers of robot_model.hpp,
// the kinematic trees of URDF, MJCF and SDF, the bodies, joints and initial state, and a few steps of each
// integrator on what was built.
#include <string>

#include "fuzz_support.hpp"
#include "poinsot/io/robot/robot_model.hpp"
#include "poinsot/io/robot/robot_system.hpp"
#include "poinsot/multibody/projected_rk4.hpp"
#include "poinsot/multibody/rattle.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);  // NOLINT: bytes as text
  poinsot::fuzz::expect_clean([&] {
    using namespace poinsot;  // NOLINT: harness
    const io::RobotModel model = io::read_robot_model(std::move(text), "fuzz.xml", poinsot::fuzz::kNoDir);
    for (const bool floating : {false, true}) {
      poinsot::fuzz::expect_clean([&] {
        io::RobotSystemOptions options;
        options.floating_base = floating;
        const multibody::Scenario sc = io::robot_scenario(model, options);
        multibody::State s = sc.initial;
        multibody::Rattle rattle(sc.system, 1e-3);
        for (int k = 0; k < 3; ++k)
          rattle.step(s);
        s = sc.initial;
        multibody::ProjectedRk4 rk4(sc.system, 1e-3);
        for (int k = 0; k < 3; ++k)
          rk4.step(s);
      });
    }
  });
  return 0;
}
