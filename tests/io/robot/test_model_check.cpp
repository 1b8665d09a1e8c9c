// Tests of model_check.hpp on the project's own model files (tests/data/models): valid models give no
// finding, each defect is reported with its message, and the geometry's inertia matches closed forms
// (Meriam & Kraige's box, cylinder and sphere formulas, evaluated here by hand).
#include "poinsot/io/robot/model_check.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

using test::expect_has;
using test::max_abs_diff;

std::string data(const std::string& name) {
  return std::string(POINSOT_TEST_DATA_DIR "/models/") + name;
}

std::map<std::string, LinkCheck> by_name(const ModelCheck& c) {
  std::map<std::string, LinkCheck> m;
  for (const LinkCheck& l : c.links)
    m[l.name] = l;
  return m;
}

TEST(ModelCheck, ValidModelsHaveNoFinding) {
  for (const char* file : {"valid_arm.urdf", "valid_arm.xml", "valid_robot.sdf"}) {
    const ModelCheck c = check_model(load_robot_model(data(file)));
    EXPECT_EQ(c.invalid, 0u) << file;
    EXPECT_EQ(c.warnings, 0u) << file;
    for (const LinkCheck& l : c.links) {
      EXPECT_TRUE(l.validity.valid) << file << " " << l.name;
      EXPECT_TRUE(l.warnings.empty()) << file << " " << l.name << ": " << l.warnings.front();
      // Every link with inertial data of these files is meant to match its geometry exactly (same density).
      if (l.has_inertial) {
        ASSERT_TRUE(l.geometry.has_value()) << file << " " << l.name;
        // The STL cube is stored in float: 1e-7 relative; the shapes are closed forms to round-off.
        EXPECT_LE(max_abs_diff(l.inertia_link, l.geometry->props.inertia_com), 1e-7 * l.inertia_link.trace())
            << file << " " << l.name;
      }
    }
  }
}

TEST(ModelCheck, GeometryInertiaOfARotatedCylinderIsTheClosedForm) {
  // upper_arm: cylinder r = 0.05, L = 0.4, m = 3 turned to lie along x: J_xx = m r²/2,
  // J_yy = J_zz = m (3 r² + L²)/12; centre of mass at its centre (0.2, 0, 0); volume π r² L.
  const auto links = by_name(check_model(load_robot_model(data("valid_arm.urdf"))));
  const LinkCheck& arm = links.at("upper_arm");
  ASSERT_TRUE(arm.geometry.has_value());
  const double m = 3, r = 0.05, L = 0.4;
  const Mat3 expected =
      Vec3(m * r * r / 2, m * (3 * r * r + L * L) / 12, m * (3 * r * r + L * L) / 12).asDiagonal();
  EXPECT_LE(max_abs_diff(arm.geometry->props.inertia_com, expected), 1e-15);
  EXPECT_LE(max_abs_diff(arm.geometry->props.com, Vec3(0.2, 0, 0)), 1e-15);
  EXPECT_NEAR(arm.geometry->volume, std::numbers::pi * r * r * L, 1e-17);
  EXPECT_EQ(arm.geometry->source, "collision");
  // Its bounding box: x from 0 to 0.4, |y|, |z| <= r (to round-off of the turned frame).
  EXPECT_LE(max_abs_diff(arm.geometry->box_min, Vec3(0, -r, -r)), 1e-15);
  EXPECT_LE(max_abs_diff(arm.geometry->box_max, Vec3(0.4, r, r)), 1e-15);
  // The mesh link: a 10 cm cube of 2.7 kg, density 2700 kg/m³.
  ASSERT_TRUE(links.at("hand").implied_density.has_value());
  EXPECT_NEAR(*links.at("hand").implied_density, 2700.0, 2700.0 * 1e-6);
}

TEST(ModelCheck, EachDefectIsReportedWithItsMessage) {
  const ModelCheck c = check_model(load_robot_model(data("defects.urdf")));
  const auto links = by_name(c);
  EXPECT_EQ(c.invalid, 3u);
  EXPECT_EQ(c.warnings, 5u);
  EXPECT_EQ(links.at("triangle").validity.condition, "triangle inequality");
  EXPECT_EQ(
      links.at("triangle").validity.message,
      "link triangle inertia: principal moments (100, 100, 250) kg·m² violate the triangle inequality I1 "
      "+ I2 >= I3 (short by 50)");
  EXPECT_EQ(links.at("negative_moment").validity.condition, "negative moment");
  EXPECT_DOUBLE_EQ(links.at("negative_moment").validity.amount, 1.0);
  EXPECT_EQ(links.at("products").validity.condition, "negative moment");  // moments −0.5, 1, 2.5
  expect_has(links.at("products").notes.back(), {"no usable collision or visual geometry"});
  for (const char* name : {"triangle", "negative_moment", "products"})
    EXPECT_TRUE(links.at(name).warnings.empty()) << name;
  const auto only_warning = [&](const std::string& name) {
    const LinkCheck& l = links.at(name);
    EXPECT_TRUE(l.validity.valid) << name;
    EXPECT_EQ(l.warnings.size(), 1u) << name;
    return l.warnings.empty() ? std::string() : l.warnings.front();
  };
  expect_has(only_warning("zero_mass"), {"mass 0 kg", "expected a positive mass"});
  expect_has(only_warning("negative_mass"), {"mass -1 kg is negative"});
  expect_has(only_warning("too_dense"), {"implied density 1e+06 kg/m³", "outside [50, 25000] kg/m³"});
  expect_has(only_warning("units"), {"inertia trace 5000 kg·m²", "1e+06 times", "more than 10×"});
  expect_has(only_warning("com_outside"), {"centre of mass (0.5, 0, 0) m is outside", "bounding box"});
}

TEST(ModelCheck, RepairIsNearestAndValid) {
  const auto links = by_name(check_model(load_robot_model(data("defects.urdf"))));
  // (100, 100, 250) projected onto I1 + I2 >= I3: move along the face normal (1, 1, −1) by 50/3.
  const LinkCheck& t = links.at("triangle");
  ASSERT_TRUE(t.repair.has_value());
  const double d = 50.0 / 3.0;
  EXPECT_LE(max_abs_diff(t.repair->inertia, Mat3(Vec3(100 + d, 100 + d, 250 - d).asDiagonal())), 1e-12);
  EXPECT_NEAR(t.repair->distance, 50.0 / std::sqrt(3.0), 1e-12);
}

TEST(ModelCheck, JsonCarriesTheSameData) {
  const ModelCheck c = check_model(load_robot_model(data("defects.urdf")));
  const nlohmann::json j = nlohmann::json::parse(model_check_json(c));
  EXPECT_EQ(j["format"], "urdf");
  EXPECT_EQ(j["invalid"], 3);
  ASSERT_EQ(j["links"].size(), c.links.size());
  EXPECT_EQ(j["links"][0]["name"], "triangle");
  EXPECT_EQ(j["links"][0]["valid"], false);
  EXPECT_EQ(j["links"][0]["repair"]["distance"].get<double>(), c.links[0].repair->distance);
  EXPECT_EQ(j["links"][0]["principal_moments"][2].get<double>(), 250.0);
  EXPECT_TRUE(j["links"][2]["geometry"].is_null());
}

TEST(ModelCheck, OptionsAreChecked) {
  const RobotModel m = load_robot_model(data("valid_arm.urdf"));
  ModelCheckOptions o;
  o.density_min = 0;
  EXPECT_THROW(check_model(m, o), InvalidInput);
  o = {};
  o.density_max = 10;
  EXPECT_THROW(check_model(m, o), InvalidInput);
  o = {};
  o.ratio_limit = 1;
  EXPECT_THROW(check_model(m, o), InvalidInput);
  EXPECT_THROW(check_model(read_robot_model("<robot name=\"empty\"/>", "e.urdf")), InvalidInput);
}

}  // namespace
}  // namespace poinsot::io
