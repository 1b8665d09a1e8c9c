// MJCF <include>: the included files' bodies against the same model written in one file (the same bodies,
// joints and motion, bit for bit), messages that name the included file and its line, and the bad includes.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot/io/robot/model_check.hpp"
#include "poinsot/io/robot/robot_model.hpp"
#include "poinsot/io/robot/robot_system.hpp"
#include "poinsot/multibody/rattle.hpp"
#include "poinsot/multibody/scenario.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

using test::expect_has;
using test::message_of;

void write(const std::filesystem::path& p, const std::string& text) {
  std::filesystem::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

// A pendulum of two links: the upper in parts/upper.xml, which includes parts/lower.xml (a path relative to
// the main file's folder, as MuJoCo resolves it), the options in parts/options.xml at the top level.
const std::string kMain =
    "<mujoco model=\"two\">\n"
    "  <!-- <include file=\"not_read.xml\"/> -->\n"
    "  <include file=\"parts/options.xml\"/>\n"
    "  <worldbody>\n"
    "    <include file=\"parts/upper.xml\"></include>\n"
    "  </worldbody>\n"
    "</mujoco>\n";
const std::string kOptions = "<mujoco>\n  <option gravity=\"0 0 -1.62\"/>\n</mujoco>\n";
const std::string kUpper =
    "<mujoco>\n"
    "  <body name=\"upper\" pos=\"0 0 1\">\n"
    "    <joint name=\"shoulder\" axis=\"0 1 0\"/>\n"
    "    <geom type=\"capsule\" fromto=\"0 0 0 0.3 0 0\" size=\"0.02\"/>\n"
    "    <include file=\"parts/lower.xml\"/>\n"
    "  </body>\n"
    "</mujoco>\n";
const std::string kLower =
    "<mujoco>\n"
    "  <body name=\"lower\" pos=\"0.3 0 0\">\n"
    "    <joint name=\"elbow\" axis=\"0 1 0\"/>\n"
    "    <geom type=\"sphere\" size=\"0.04\" pos=\"0.2 0 0\"/>\n"
    "  </body>\n"
    "</mujoco>\n";
// The same model in one file.
const std::string kWhole =
    "<mujoco model=\"two\">\n"
    "  <option gravity=\"0 0 -1.62\"/>\n"
    "  <worldbody>\n"
    "  <body name=\"upper\" pos=\"0 0 1\">\n"
    "    <joint name=\"shoulder\" axis=\"0 1 0\"/>\n"
    "    <geom type=\"capsule\" fromto=\"0 0 0 0.3 0 0\" size=\"0.02\"/>\n"
    "  <body name=\"lower\" pos=\"0.3 0 0\">\n"
    "    <joint name=\"elbow\" axis=\"0 1 0\"/>\n"
    "    <geom type=\"sphere\" size=\"0.04\" pos=\"0.2 0 0\"/>\n"
    "  </body>\n"
    "  </body>\n"
    "  </worldbody>\n"
    "</mujoco>\n";

std::filesystem::path model_folder() {
  const std::filesystem::path dir = test::temp_path("mjcf_include");
  write(dir / "two.xml", kMain);
  write(dir / "parts" / "options.xml", kOptions);
  write(dir / "parts" / "upper.xml", kUpper);
  write(dir / "parts" / "lower.xml", kLower);
  write(dir / "whole.xml", kWhole);
  return dir;
}

TEST(MjcfInclude, IncludedBodiesAreThoseOfTheSameModelInOneFile) {
  const std::filesystem::path dir = model_folder();
  const multibody::Scenario split = load_robot_scenario((dir / "two.xml").string());
  const multibody::Scenario whole = load_robot_scenario((dir / "whole.xml").string());
  ASSERT_EQ(split.system.body_count(), 2);
  EXPECT_EQ(split.system.bodies()[1].name, "lower");
  EXPECT_EQ(split.system.gravity(), Vec3(0, 0, -1.62));
  multibody::Rattle a(split.system, 1e-3), b(whole.system, 1e-3);
  multibody::State sa = split.initial, sb = whole.initial;
  sa.bodies[1].omega_body = sb.bodies[1].omega_body = Vec3(0, 2.0, 0);
  multibody::project_velocities(split.system, sa);
  multibody::project_velocities(whole.system, sb);
  for (int k = 0; k < 300; ++k) {
    a.step(sa);
    b.step(sb);
  }
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(sa.bodies[i].x_space, sb.bodies[i].x_space);
    EXPECT_EQ(sa.bodies[i].R_space_body, sb.bodies[i].R_space_body);
  }
  // Each link is found in its own file: the lower link at line 2 of parts/lower.xml.
  const RobotModel model = load_robot_model((dir / "two.xml").string());
  const ModelCheck check = check_model(model);
  ASSERT_EQ(check.links.size(), 2u);
  EXPECT_EQ(check.links[1].line, 2);
  EXPECT_EQ(std::filesystem::path(check.links[1].file).filename(), "lower.xml");
  EXPECT_EQ(check.links[0].line, 2);
  EXPECT_EQ(std::filesystem::path(check.links[0].file).filename(), "upper.xml");
}

TEST(MjcfInclude, MessagesNameTheIncludedFileAndItsLine) {
  const std::filesystem::path dir = model_folder();
  write(dir / "parts" / "lower.xml",
        "<mujoco>\n  <body name=\"lower\" pos=\"0.3 0 0\">\n\n    <joint name=\"elbow\" axis=\"0 0 0\"/>\n"
        "    <geom type=\"sphere\" size=\"0.04\"/>\n  </body>\n</mujoco>\n");
  expect_has(message_of([&] { load_robot_scenario((dir / "two.xml").string()); }),
             {"lower.xml:4: <joint> name=\"elbow\" axis: zero length"});
}

TEST(MjcfInclude, BadIncludesAreRefusedWithTheirPlace) {
  const std::filesystem::path dir = model_folder();
  const auto error_of = [&](const std::string& upper) {
    write(dir / "parts" / "upper.xml", upper);
    return message_of([&] { load_robot_model((dir / "two.xml").string()); });
  };
  const std::string head = "<mujoco>\n  <body name=\"upper\">\n    <geom type=\"sphere\" size=\"0.1\"/>\n";
  expect_has(error_of(head + "    <include file=\"parts/none.xml\"/>\n  </body>\n</mujoco>\n"),
             {"upper.xml:4: <include file=\"parts/none.xml\">", "none.xml"});
  expect_has(
      error_of(head + "    <include file=\"parts/options.xml\"/>\n  </body>\n</mujoco>\n"),
      {"upper.xml:4: <include file=\"parts/options.xml\">", "is included already; expected each file once"});
  expect_has(error_of(head + "    <include/>\n  </body>\n</mujoco>\n"),
             {"upper.xml:4: <include>: no file; expected file=\"PATH\""});
  expect_has(
      error_of(head + "    <include file=\"parts/lower.xml\"><body/></include>\n  </body>\n</mujoco>\n"),
      {"upper.xml:4: <include file=\"parts/lower.xml\">: has content; expected an empty element"});
  write(dir / "parts" / "broken.xml", "<mujoco>\n<body>\n</mujoco>\n");
  expect_has(error_of(head + "    <include file=\"parts/broken.xml\"/>\n  </body>\n</mujoco>\n"),
             {"upper.xml:4: <include file=\"parts/broken.xml\">", "broken.xml:", "XML error"});
  // The limit on the model's size holds for each included file.
  write(dir / "parts" / "big.xml", "<mujoco>\n<!-- " + std::string(5000, 'x') + " -->\n</mujoco>\n");
  write(dir / "parts" / "upper.xml", head + "    <include file=\"parts/big.xml\"/>\n  </body>\n</mujoco>\n");
  expect_has(message_of([&] { load_robot_model((dir / "two.xml").string(), 1000); }),
             {"upper.xml:4: <include file=\"parts/big.xml\">", "--max-file-bytes"});
  EXPECT_NO_THROW(load_robot_model((dir / "two.xml").string(), 10000));
  // A file that includes itself is included twice.
  expect_has(error_of(head + "    <include file=\"parts/upper.xml\"/>\n  </body>\n</mujoco>\n"),
             {"is included already"});
}

TEST(MjcfInclude, MujocosHumanoid100LoadsWithItsIncludedHumanoid) {
  const std::string path = "/usr/share/mujoco/model/humanoid100/humanoid100.xml";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "MuJoCo's sample models are not installed";
  const multibody::Scenario sc = load_robot_scenario(path);
  // The humanoid (16 bodies) and 100 free objects.
  EXPECT_EQ(sc.system.body_count(), 116);
  EXPECT_GE(sc.system.body_index("right_foot"), 0);
}

}  // namespace
}  // namespace poinsot::io
