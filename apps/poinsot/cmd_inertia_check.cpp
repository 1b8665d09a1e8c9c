// `poinsot inertia check MODEL`: the inertia of every link of a URDF, MJCF or SDF file — validity with the
// inertia layer's explanation, plausibility against the link's geometry — and, with --repair or
// --from-geometry, a copy of the file with the tensors replaced in place (io/robot/model_repair.hpp).
// Everything is computed and the copy written before anything is printed, so bad input leaves stdout empty
// and no file.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/io/robot/model_check.hpp"
#include "poinsot/io/robot/model_repair.hpp"
#include "poinsot/io/robot/robot_model.hpp"
#include "poinsot/io/run/summary.hpp"

namespace poinsot::cli {
namespace {

struct CheckOptions {
  std::string model;
  bool json = false;
  bool repair = false;
  bool from_geometry = false;
  std::string out;
  std::vector<double> density_range;
  io::ModelCheckOptions check;
  std::size_t max_file_bytes = io::kDefaultMaxModelBytes;
};

void run_check(const CheckOptions& o) {
  if (o.repair && o.from_geometry)
    throw InvalidInput("check: got --repair and --from-geometry; expected at most one");
  if ((o.repair || o.from_geometry) && o.out.empty())
    throw InvalidInput(fmt::format("check: {} needs --out FILE; expected the path of the repaired copy",
                                   o.repair ? "--repair" : "--from-geometry"));
  if (!o.out.empty() && !o.repair && !o.from_geometry)
    throw InvalidInput("check: --out needs --repair or --from-geometry; expected one of them");
  io::ModelCheckOptions options = o.check;
  if (!o.density_range.empty()) {
    options.density_min = o.density_range[0];
    options.density_max = o.density_range[1];
  }
  const io::RobotModel model = io::load_robot_model(o.model, o.max_file_bytes);
  const io::ModelCheck check = io::check_model(model, options);
  std::optional<io::ModelRepair> repair;
  if (o.repair || o.from_geometry) {
    repair = io::repair_model(model, check,
                              o.repair ? io::RepairMode::nearest_valid : io::RepairMode::from_geometry);
    io::write_file_atomic(o.out, repair->text);
  }
  std::string text;
  if (o.json) {
    text = repair ? fmt::format("{{\"check\":{},\"repair\":{}}}\n", io::model_check_json(check),
                                io::model_repair_json(*repair))
                  : io::model_check_json(check) + "\n";
  } else {
    text = io::model_check_text(check);
    if (repair) text += "\n" + io::model_repair_text(*repair) + fmt::format("written: {}\n", o.out);
  }
  fmt::print("{}", text);
}

}  // namespace

void register_inertia_check(CLI::App& inertia) {
  auto o = std::make_shared<CheckOptions>();
  auto* cmd = inertia.add_subcommand(
      "check", "inertia of every link of a robot model (URDF, MJCF, SDF): validity, plausibility, repair");
  cmd->add_option("model", o->model, "robot model file (.urdf, .xml MJCF, .sdf)")->required();
  cmd->add_flag("--json", o->json, "print one JSON object (SI units)");
  cmd->add_flag("--repair", o->repair,
                "write (--out) a copy with each invalid tensor replaced by the nearest valid one");
  cmd->add_flag("--from-geometry", o->from_geometry,
                "write (--out) a copy with each tensor replaced by its geometry's at the link's mass");
  cmd->add_option("--out", o->out, "path of the repaired copy");
  cmd->add_option("--density-range", o->density_range,
                  "plausible densities MIN MAX (kg/m³; default 50 25000)")
      ->expected(2);
  cmd->add_option("--ratio-limit", o->check.ratio_limit,
                  "warn when tr J and the geometry's differ by more than this factor (default 10)");
  cmd->add_option("--validity-tolerance", o->check.validity_tolerance,
                  "relative tolerance (times the trace) of the validity test (default 1e-10)");
  cmd->add_option("--max-file-bytes", o->max_file_bytes, "largest model file read (bytes; default 64 MiB)");
  cmd->add_option("--max-mesh-bytes", o->check.max_mesh_bytes,
                  "largest mesh file read (bytes; default 256 MiB)");
  cmd->add_option("--max-mesh-triangles", o->check.max_mesh_triangles,
                  "most triangles of a mesh (default 5000000)");
  cmd->callback([o] { run_check(*o); });
}

}  // namespace poinsot::cli
