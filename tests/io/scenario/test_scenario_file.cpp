// scenario_file.hpp: one parse, either kind of scenario.
#include "poinsot/io/scenario/scenario_file.hpp"

#include <filesystem>
#include <fstream>
#include <variant>

#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

const std::string kExamples = std::string(POINSOT_SOURCE_DIR) + "/examples/";

TEST(ScenarioFile, EachKindIsReadByItsReader) {
  const AnyScenario single = load_any_scenario(kExamples + "mesh_body.toml");
  ASSERT_TRUE(std::holds_alternative<Scenario>(single));
  EXPECT_EQ(std::get<Scenario>(single).name, "mesh_body");  // named after the file, as load_scenario does
  // The same body as the single-body reader gives (the mesh relative to the file's folder).
  EXPECT_EQ(std::get<Scenario>(single).body.inertia(),
            load_scenario(kExamples + "mesh_body.toml").body.inertia());

  const AnyScenario multi = load_any_scenario(kExamples + "multibody/double_pendulum.toml");
  ASSERT_TRUE(std::holds_alternative<multibody::Scenario>(multi));
  EXPECT_EQ(std::get<multibody::Scenario>(multi).system.body_count(), 2);
  EXPECT_TRUE(is_multibody_scenario(kExamples + "multibody/double_pendulum.toml"));
  EXPECT_FALSE(is_multibody_scenario(kExamples + "tennis_racket.toml"));

  // Relative files of a multibody scenario are taken from its folder.
  const AnyScenario mesh = load_any_scenario(kExamples + "multibody/l_bracket_hinge.toml");
  ASSERT_TRUE(std::holds_alternative<multibody::Scenario>(mesh));
  EXPECT_NEAR(std::get<multibody::Scenario>(mesh).system.bodies()[0].mass, 2700.0 * 1.02e-4, 1e-6);
}

TEST(ScenarioFile, ErrorsAreTheReadersOnes) {
  const auto message = [](const std::string& text) {
    return test::message_of([&] { (void)parse_any_scenario(text, "f.toml"); });
  };
  EXPECT_EQ(message("a = [1,\n").rfind("f.toml:1:9: TOML syntax error", 0), 0u);
  // A [[bodies]] file with a single-body key, and the reverse: each reader names the key it does not know.
  EXPECT_NE(message("[[bodies]]\nmass = 1\ninertia = [1, 1, 1]\n[output]\nt_end = 1\n")
                .find("[top level] unknown key \"output\""),
            std::string::npos);
  EXPECT_NE(
      message("[body]\nprincipal_moments = [1, 2, 3]\n[simulation]\n").find("unknown key \"simulation\""),
      std::string::npos);
  EXPECT_THROW((void)load_any_scenario("/nonexistent/f.toml"), InvalidInput);
  EXPECT_THROW((void)is_multibody_scenario("/nonexistent/f.toml"), InvalidInput);
}

}  // namespace
}  // namespace poinsot::io
