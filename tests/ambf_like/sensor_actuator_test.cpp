// Proximity sensors and constraint actuators as AMBF has them: the example's sensor sees a
// falling block at the right distance from the moment it enters its range, the actuator holds
// it in the air and lets it go; the loader reads both layouts and names bad input.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ambf_like/scene_loader.hpp"
#include "ambf_like/world.hpp"
#include "test_files.hpp"

namespace {

using testing::HasSubstr;

/// The block's lowest face above the sensor's rays' origins (z = 0.011), from its pose.
double gapBelowBlock(const ambf_like::World& world) {
  return world.body("block").pose().translation().z() - 0.01 - 0.011;
}

TEST(ProximitySensor, SeesABodyEnteringItsRangeAtTheRightDistance) {
  auto sim = test_support::simulate({test_support::exampleFile("sensors_actuators.yaml")});
  auto& world = *sim->world;
  ASSERT_EQ(world.sensorCount(), 1u);
  auto& sensor = world.sensor("pad_sensor");
  ASSERT_EQ(sensor.readings().size(), 2u);
  int triggered_steps = 0;
  double previous_gap = gapBelowBlock(world);
  for (int i = 0; i < 400 && gapBelowBlock(world) > 0.02; ++i) {
    world.step();
    const double gap = gapBelowBlock(world);
    if (!sensor.triggered()) {
      ASSERT_GT(gap, 0.1 - 1e-3) << "the block is within range but not seen, step " << i;
      previous_gap = gap;
      continue;
    }
    if (triggered_steps++ == 0) {
      EXPECT_GT(previous_gap, 0.1) << "seen only once it entered the 0.1 m range";
      EXPECT_LE(gap, 0.1);
    }
    for (const auto& ray : sensor.readings()) {
      ASSERT_TRUE(ray.triggered);
      EXPECT_NEAR(ray.distance, gap, 1e-3) << "step " << i;
      EXPECT_EQ(ray.body, "/ambf/env/block");
    }
  }
  EXPECT_GT(triggered_steps, 5);
}

TEST(ConstraintActuator, HoldsTheSensedBodyInTheAirAndReleasesIt) {
  auto sim = test_support::simulate({test_support::exampleFile("sensors_actuators.yaml")});
  auto& world = *sim->world;
  auto& sensor = world.sensor("pad_sensor");
  auto& gripper = world.actuator("pad_gripper");
  while (!(sensor.triggered() && sensor.nearest()->distance < 0.05)) world.step();
  gripper.actuate(world.body(sensor.nearest()->body));
  EXPECT_TRUE(gripper.actuated());
  EXPECT_EQ(gripper.heldBody(), "/ambf/env/block");
  world.step(20);  // the block's fall is stopped within a few steps
  const double held = world.body("block").pose().translation().z();
  world.step(1000);  // one second under gravity
  EXPECT_NEAR(world.body("block").pose().translation().z(), held, 1e-3);
  EXPECT_GT(held, 0.03) << "held in the air, above the pad";
  gripper.release();
  EXPECT_FALSE(gripper.actuated());
  world.step(1000);
  EXPECT_NEAR(world.body("block").pose().translation().z(), 0.02, 1e-3) << "fell onto the pad";
  EXPECT_THROW(gripper.actuate(world.body("pad")), std::invalid_argument);
  // A non-finite or far offset (a bad ActuatorCmd) attaches nothing.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(gripper.actuate(world.body("block"), ambf_like::Vec3(nan, 0, 0)),
               std::invalid_argument);
  EXPECT_THROW(gripper.actuate(world.body("block"), ambf_like::Vec3(0, 0, 1e6)),
               std::invalid_argument);
  EXPECT_FALSE(gripper.actuated());
  world.step(10);
  EXPECT_TRUE(world.body("block").pose().matrix().allFinite());
}

TEST(SensorLoading, ParametricFansAndBadSensorsAreReadAsAmbfReadsThem) {
  test_support::TempDir dir;
  auto file = [&](const std::string& sensor) {
    return dir.write("m.yaml",
                     "bodies: [BODY base]\nsensors: [SENSOR s]\n"
                     "BODY base: {mass: 0, collision shape: BOX, collision geometry: {x: 1, y: 1, "
                     "z: 1}}\n"
                     "SENSOR s:\n  parent: BODY base\n  range: 0.5\n" +
                         sensor);
  };
  const auto fan = ambf_like::loadModelFiles({file(
      "  type: RAYTRACER\n  parametric: {resolution: 3, horizontal angle: 1.0, vertical angle: "
      "0.5, start offset: 0.1}\n")});
  const auto& rays = fan.spec.models[0].sensors.at(0).rays;
  ASSERT_EQ(rays.size(), 9u);
  EXPECT_NEAR(rays[4].direction.x(), 1.0, 1e-12) << "the middle ray looks along +x";
  EXPECT_NEAR(rays[4].origin.x(), 0.1, 1e-12);
  EXPECT_NEAR(std::atan2(rays[0].direction.y(), rays[0].direction.x()), -0.5, 1e-12);
  const auto resistance =
      ambf_like::loadModelFiles({file("  type: RESISTANCE\n  friction: {static: 0.5}\n  array: "
                                      "[{direction: {x: 0, y: 0, z: 1}}]\n")});
  EXPECT_EQ(resistance.spec.models[0].sensors.at(0).type, ambf_like::SensorType::Resistance);
  EXPECT_THAT(resistance.warnings.at(0).message, HasSubstr("'friction' accepted, not simulated"));
  EXPECT_THAT(test_support::loadErrorOf(
                  [&] { ambf_like::loadModelFiles({file("  type: SONAR\n  array: []\n")}); }),
              HasSubstr("unknown sensor type 'SONAR'"));
  EXPECT_THAT(test_support::loadErrorOf([&] {
                ambf_like::loadModelFiles(
                    {file("  type: PROXIMITY\n  array: [{direction: {x: 0, y: 0, z: 0}}]\n")});
              }),
              HasSubstr("SENSOR s/array[0]/direction"));
}

}  // namespace
