// Fuzz harness: the robot-model readers (io/robot/robot_model.hpp: URDF, MJCF, SDF by the root element), the
// check of every link, its JSON and text reports, and both in-place repairs.
#include <string>

#include "fuzz_support.hpp"
#include "poinsot/io/robot/model_check.hpp"
#include "poinsot/io/robot/model_repair.hpp"
#include "poinsot/io/robot/robot_model.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);  // NOLINT: bytes as text
  poinsot::fuzz::expect_clean([&] {
    using namespace poinsot::io;  // NOLINT: harness
    const RobotModel model = read_robot_model(std::move(text), "fuzz.xml", poinsot::fuzz::kNoDir);
    const ModelCheck check = check_model(model);
    model_check_json(check);
    model_check_text(check);
    for (RepairMode mode : {RepairMode::nearest_valid, RepairMode::from_geometry}) {
      poinsot::fuzz::expect_clean([&] {
        const ModelRepair repair = repair_model(model, check, mode);
        model_repair_json(repair);
        // A repaired model must read back.
        read_robot_model(repair.text, "repaired.xml", poinsot::fuzz::kNoDir);
      });
    }
  });
  return 0;
}
