// The multipliers in a multibody run's page (view_multipliers.hpp): recomputed at every frame from the
// trajectory's rows, they equal at the last frame what the run itself wrote at its final state.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "poinsot/io/run/multibody_run.hpp"
#include "poinsot/io/scenario/multibody_scenario.hpp"
#include "poinsot/io/view/view_page.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

namespace fs = std::filesystem;

/// The rows of reactions.csv after its names line, split at commas (the joint and body names as text).
std::vector<std::vector<std::string>> reaction_rows(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');)
      cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

TEST(ViewMultipliers, LastFrameIsTheRunsReactionsAndEveryFrameHasThem) {
  // The double pendulum for 0.5 s (51 rows): the page keeps 9 significant digits of F and the couple, and the
  // frame's state went through the CSV (the rotation through its quaternion, 1e-16): 1e-8 of the largest.
  const std::string file = POINSOT_SOURCE_DIR "/examples/multibody/double_pendulum.toml";
  multibody::Scenario sc = load_multibody_scenario(file);
  sc.duration = 0.5;
  const fs::path dir = ::poinsot::test::temp_path("poinsot_io_view_multipliers");
  fs::remove_all(dir);
  MultibodyRunOptions o;
  o.out_dir = dir.string();
  run_multibody_scenario(sc, o);
  ViewOptions v;
  v.scenario_path = file;
  const auto data = nlohmann::json::parse(view_data_json(dir.string(), v));
  ASSERT_TRUE(data["model_from_scenario"].get<bool>());
  const long long frames = data["frames"].get<long long>();
  EXPECT_EQ(frames, 51);
  const auto rows = reaction_rows(dir / "reactions.csv");
  ASSERT_EQ(rows.size(), data["joints"].size());
  double largest = 0.0;
  for (const auto& r : rows)
    largest = std::max(largest, std::stod(r[7]));
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const auto& reaction = data["joints"][k]["reaction"];
    ASSERT_EQ(static_cast<long long>(reaction.size()), 6 * frames);
    EXPECT_EQ(data["joints"][k]["name"].get<std::string>(), rows[k][1]);
    for (int c = 0; c < 3; ++c) {
      const double page = reaction[static_cast<std::size_t>(6 * (frames - 1) + c)].get<double>();
      EXPECT_NEAR(page, std::stod(rows[k][static_cast<std::size_t>(4 + c)]), 1e-8 * largest) << k << " " << c;
      const double couple = reaction[static_cast<std::size_t>(6 * (frames - 1) + 3 + c)].get<double>();
      EXPECT_NEAR(couple, std::stod(rows[k][static_cast<std::size_t>(8 + c)]), 1e-8 * largest);
    }
  }
  for (const auto& b : data["bodies"])
    EXPECT_EQ(static_cast<long long>(b["lambda"].size()), 6 * frames);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace poinsot::io
