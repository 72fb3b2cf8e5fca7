// AMBF's acceptance by default, and --strict: each kind of file AMBF loads with a warning loads
// here with one naming file, line and key, and is the error it was under LoadOptions::strict.
// Malformed YAML, wrong types and NaNs stay errors in both modes.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "ambf_like/scene_loader.hpp"
#include "ambf_like/world.hpp"
#include "test_files.hpp"

namespace {

using test_support::loadErrorOf;
using test_support::TempDir;
using testing::AllOf;
using testing::HasSubstr;

/// A static base and a dynamic box on a revolute joint; `box` and `joint` are spliced in.
std::string hingedBoxModel(const std::string& box = "  mass: 1.0\n",
                           const std::string& joint = "") {
  return "bodies: [BODY base, BODY box]\n"
         "joints: [JOINT hinge]\n"
         "BODY base:\n"
         "  mass: 0.0\n"
         "  collision shape: BOX\n"
         "  collision geometry: {x: 1, y: 1, z: 0.1}\n"
         "BODY box:\n"
         "  collision shape: BOX\n"
         "  collision geometry: {x: 0.1, y: 0.1, z: 0.1}\n" +
         box +
         "JOINT hinge:\n"
         "  parent: BODY base\n"
         "  child: BODY box\n"
         "  type: revolute\n" +
         joint;
}

/// The default load's warnings, joined.
std::string warningsOf(const ambf_like::LoadedScene& scene) {
  std::string all;
  for (const auto& w : scene.warnings) all += w.message + "\n";
  return all;
}

std::string strictError(const std::filesystem::path& file) {
  return loadErrorOf([&] { ambf_like::loadModelFiles({file}, std::nullopt, {.strict = true}); });
}

TEST(AmbfAcceptance, KeysAmbfCarriesAreAcceptedAndNotedOnceAsNotSimulated) {
  TempDir dir;
  const auto file = dir.write(
      "m.yaml",
      "detached: false\n" +
          hingedBoxModel("  mass: 1.0\n  use material: true\n  redundant: 1\n", "  detached: 0\n"));
  const auto scene = ambf_like::loadModelFiles({file});
  const std::string w = warningsOf(scene);
  EXPECT_THAT(w, AllOf(HasSubstr("'use material' accepted, not simulated"),
                       HasSubstr("'redundant' accepted, not simulated"),
                       HasSubstr("'detached' accepted, not simulated")));
  EXPECT_EQ(scene.warnings.size(), 3u) << "each key once, however often it appears:\n" << w;
  EXPECT_EQ(strictError(file), "") << "known keys are not errors under --strict either";
}

TEST(AmbfAcceptance, AnUnknownKeyIsAWarningWithItsSuggestionAndAStrictError) {
  TempDir dir;
  const auto file = dir.write("m.yaml", hingedBoxModel("  mass: 1.0\n  restitutoin: 0.2\n"));
  const auto scene = ambf_like::loadModelFiles({file});
  EXPECT_THAT(warningsOf(scene), AllOf(HasSubstr("unknown key 'restitutoin'"),
                                       HasSubstr("did you mean 'restitution'")));
  EXPECT_THAT(strictError(file),
              AllOf(HasSubstr(file.string() + ":11"), HasSubstr("BODY box/restitutoin"),
                    HasSubstr("did you mean 'restitution'")));
}

TEST(AmbfAcceptance, ASensorOnAnotherModelsBodyIsFoundByItsQualifiedNameAndSkippedIfMissing) {
  TempDir dir;
  const auto robot = dir.write("robot.yaml", "namespace: /robot/\n" + hingedBoxModel());
  auto extras = [&](const std::string& parent) {
    return dir.write("extras_" + std::to_string(parent.size()) + ".yaml",
                     "namespace: /extras/\nsensors: [SENSOR eye]\nactuators: [ACTUATOR hand]\n"
                     "SENSOR eye:\n  name: eye\n  type: PROXIMITY\n  parent: BODY " +
                         parent +
                         "\n  range: 0.1\n  array: [{offset: {x: 0, y: 0, z: 0}, direction: "
                         "{x: 0, y: 0, z: 1}}]\n"
                         "ACTUATOR hand:\n  name: hand\n  type: CONSTRAINT\n  parent: BODY " +
                         parent + "\n");
  };
  // Loaded after the robot, in one load or appended to its scene: the parent is the robot's box.
  const auto good = extras("/robot/box");
  auto scene = ambf_like::loadModelFiles({robot, good});
  EXPECT_EQ(scene.spec.models[1].sensors.size(), 1u);
  auto appended = ambf_like::loadModelFiles({robot}).spec;
  EXPECT_TRUE(ambf_like::appendModelFiles(appended, {good}).empty());
  ambf_like::MeshLibrary meshes;
  ambf_like::World world(appended, meshes);
  EXPECT_EQ(world.sensor("eye").parent().qualifiedName(), "/robot/box");
  EXPECT_EQ(world.actuator("hand").spec().parent, "/robot/box");
  // A parent no model before it has: skipped with a warning, as AMBF skips it; strict: an error.
  const auto missing = extras("/robot/no_such_body");
  scene = ambf_like::loadModelFiles({robot, missing});
  EXPECT_TRUE(scene.spec.models[1].sensors.empty());
  EXPECT_TRUE(scene.spec.models[1].actuators.empty());
  EXPECT_THAT(warningsOf(scene), AllOf(HasSubstr("sensor 'eye': parent body '/robot/no_such_body'"),
                                       HasSubstr("skipped")));
  EXPECT_THAT(loadErrorOf([&] {
                ambf_like::loadModelFiles({robot, missing}, std::nullopt, {.strict = true});
              }),
              AllOf(HasSubstr(missing.string()), HasSubstr("SENSOR eye/parent")));
}

TEST(AmbfAcceptance, Yaml11BooleansAsAmbfWritesThem) {
  TempDir dir;
  for (const auto& [text, value] : std::vector<std::pair<std::string, bool>>{{"1", true},
                                                                             {"0", false},
                                                                             {"yes", true},
                                                                             {"no", false},
                                                                             {"on", true},
                                                                             {"off", false},
                                                                             {"True", true},
                                                                             {"FALSE", false},
                                                                             {"y", true}}) {
    const auto file = dir.write(
        "m.yaml", hingedBoxModel("  mass: 1.0\n  passive: " + text + "\n  visible: " + text + "\n",
                                 "  enable motor: " + text + "\n"));
    const auto scene = ambf_like::loadModelFiles({file}, std::nullopt, {.strict = true});
    EXPECT_EQ(scene.spec.models[0].bodies[1].passive, value) << text;
    EXPECT_EQ(scene.spec.models[0].bodies[1].visible, value) << text;
    EXPECT_TRUE(scene.spec.models[0].bodies[0].visible) << "a body without the key is drawn";
    EXPECT_EQ(scene.spec.models[0].joints[0].enable_motor, value) << text;
  }
  const auto bad = dir.write("m.yaml", hingedBoxModel("  mass: 1.0\n", "  enable motor: maybe\n"));
  for (bool strict : {false, true}) {
    EXPECT_THAT(loadErrorOf([&] { ambf_like::loadModelFiles({bad}, std::nullopt, {strict}); }),
                AllOf(HasSubstr("JOINT hinge/enable motor"), HasSubstr("got 'maybe'")))
        << "strict " << strict;
  }
}

TEST(AmbfAcceptance, ABodyWithoutMassIsStaticWithAWarningAndAStrictError) {
  TempDir dir;
  const auto file = dir.write("m.yaml", hingedBoxModel(""));
  const auto scene = ambf_like::loadModelFiles({file});
  EXPECT_THAT(warningsOf(scene), HasSubstr("body 'box': missing required key 'mass' (AMBF warns "
                                           "and loads such a body static, mass 0)"));
  EXPECT_EQ(scene.spec.models[0].bodies[1].mass, 0.0);
  EXPECT_THAT(strictError(file),
              AllOf(HasSubstr(file.string() + ":8"), HasSubstr("missing required key 'mass'")));
}

TEST(AmbfAcceptance, AMissingMeshIsAWarningNamingBodyFileAndPathsAndTheBodyKeepsItsMass) {
  TempDir dir;
  const auto file = dir.write("m.yaml",
                              "bodies: [BODY part]\n"
                              "high resolution path: ./high/\n"
                              "low resolution path: ./low/\n"
                              "BODY part: {name: part, mass: 2.0, mesh: part.STL,\n"
                              "            inertia: {ix: 0.1, iy: 0.2, iz: 0.3}}\n");
  const auto scene = ambf_like::loadModelFiles({file});
  EXPECT_THAT(warningsOf(scene), AllOf(HasSubstr("body 'part'"), HasSubstr("part.STL"),
                                       HasSubstr("low/part.STL"), HasSubstr("high/part.STL")));
  EXPECT_EQ(scene.spec.models[0].bodies[0].mass, 2.0);
  EXPECT_THAT(strictError(file), AllOf(HasSubstr(file.string() + ":4"), HasSubstr("part.STL")));
  // And it steps: a body without its geometry falls freely.
  auto sim = test_support::simulate({file});
  for (int i = 0; i < 100; ++i) sim->world->step();
  EXPECT_TRUE(sim->world->isFinite());
}

TEST(AmbfAcceptance, InertiaThatWasToComeFromAMissingMeshFallsBackToAStatedSphere) {
  TempDir dir;
  const auto file = dir.write(
      "m.yaml", "bodies: [BODY part]\nBODY part: {name: part, mass: 2.0, mesh: gone.STL}\n");
  const auto scene = ambf_like::loadModelFiles({file});
  EXPECT_THAT(warningsOf(scene), AllOf(HasSubstr("body 'part'"),
                                       HasSubstr("its inertia was to come from the missing mesh"),
                                       HasSubstr("solid sphere")));
  const auto& body = scene.spec.models[0].bodies[0];
  EXPECT_EQ(body.mass, 2.0);
  ASSERT_TRUE(body.inertia.has_value());
  const double r = ambf_like::kFallbackInertiaRadius;
  EXPECT_DOUBLE_EQ(body.inertia->x(), 0.4 * 2.0 * r * r);
  EXPECT_THAT(strictError(file), HasSubstr("gone.STL"));
}

TEST(AmbfAcceptance, MalformedYamlWrongTypesAndNaNStayErrorsByDefault) {
  TempDir dir;
  for (const auto& [text, expected] : std::vector<std::pair<std::string, std::string>>{
           {"bodies: [BODY a\n", "malformed YAML"},
           {hingedBoxModel("  mass: heavy\n"), "expected a number, got 'heavy'"},
           {hingedBoxModel("  mass: .nan\n"), "BODY box/mass"}}) {
    const auto file = dir.write("m.yaml", text);
    EXPECT_THAT(loadErrorOf([&] { ambf_like::loadModelFiles({file}); }), HasSubstr(expected));
  }
}

}  // namespace
