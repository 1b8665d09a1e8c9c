#include "poinsot/io/view/view_page.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "../../../src/io/view/view_assets.hpp"
#include "../../../src/io/view/view_data.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/io/run/run.hpp"
#include "poinsot/io/scenario/scenario.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

namespace fs = std::filesystem;

/// A finished run of the tennis racket (exact solution, 801 samples) in a fresh folder.
fs::path racket_run(const std::string& name) {
  const fs::path dir = ::poinsot::test::temp_path("poinsot_io_view_" + name);
  fs::remove_all(dir);
  const Scenario sc = parse_scenario(R"(
[body]
principal_moments = [0.00121, 0.01638, 0.01748]
[initial]
omega_body = [0.05, 6.2832, 0.05]
[integrator]
method = "exact"
[output]
t_end = 4
sample_dt = 0.005
)");
  RunOptions o;
  o.out_dir = dir.string();
  run_scenario(sc, o);
  return dir;
}

TEST(ViewPage, DataHoldsTheKeptRowsOfTheTrajectoryExactly) {
  const fs::path dir = racket_run("data");
  ViewOptions o;
  o.frames = 300;
  const auto j = nlohmann::json::parse(view_data_json(dir.string(), o));
  EXPECT_EQ(j["kind"], "body");
  EXPECT_EQ(j["samples"], 801);
  EXPECT_EQ(j["stride"], 3);  // ceil(800 / 299)
  const CsvFrames f = read_csv_frames((dir / "trajectory.csv").string(), o.frames);
  ASSERT_EQ(j["t"].size(), f.values.size());
  EXPECT_EQ(f.values.size(), 268u);  // rows 0, 3, ..., 798 and the last, 800
  for (std::size_t i = 0; i < f.values.size(); ++i) {
    EXPECT_EQ(j["t"][i].get<double>(), f.values[i][0]);
    for (int k = 0; k < 4; ++k)
      EXPECT_EQ(j["q"][4 * i + k].get<double>(), f.values[i][1 + k]);  // qw..qz: columns 1-4
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(j["omega_body"][3 * i + k].get<double>(), f.values[i][5 + k]);
  }
  // A free body given by its principal moments: axes = the body's, shapes of 1 kg.
  EXPECT_EQ(j["body"]["mass"], nullptr);
  EXPECT_EQ(j["torque"], "none");
  fs::remove_all(dir);
}

TEST(ViewPage, PageIsWithinItsSizeBoundAndEveryMarkerIsReplaced) {
  if (!view_asset("three.min.js")) GTEST_SKIP() << "built without libjs-three";
  const fs::path dir = racket_run("page");
  ViewOptions o;
  o.frames = 500;
  const std::string path = write_view_page(dir.string(), o);
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string page = ss.str();
  EXPECT_EQ(page.find("<!-- poinsot:"), std::string::npos);
  EXPECT_NE(page.find("THREE"), std::string::npos);
  EXPECT_LE(page.size(), view_page_size_bound(500, 12));
  EXPECT_GT(page.size(), view_asset("three.min.js")->size());
  // Written atomically: no temporary file is left beside it.
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_NE(e.path().filename().string()[0], '.') << e.path();
  fs::remove_all(dir);
}

TEST(ViewPage, RefusesAFolderWithoutAFinishedRunAndFramesOutOfRange) {
  const fs::path dir = ::poinsot::test::temp_path("poinsot_io_view_empty");
  fs::remove_all(dir);
  fs::create_directories(dir);
  EXPECT_THROW(write_view_page(dir.string()), InvalidInput);
  EXPECT_TRUE(fs::is_empty(dir));
  EXPECT_THROW(write_view_page((dir / "none").string()), InvalidInput);
  ViewOptions o;
  o.frames = 1;
  EXPECT_THROW(check_view_options(o), InvalidInput);
  o.frames = kViewFramesMax + 1;
  EXPECT_THROW(check_view_options(o), InvalidInput);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace poinsot::io
