// measured_cf from contacts: a body resting on a tilted "jaw" is pushed by it with its weight,
// split into the normal and the friction the incline needs, for rigid and Coulomb soft bodies.

#include "twin/grasp_forces.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "test_files.hpp"

namespace {

constexpr double kGravity = 9.81;
const double kSlope = std::atan(0.3);  // inside the friction cone of mu = 1

/// A static plane "jaw1" tilted by kSlope about y (friction 1) under `resting`; "jaw2" a static
/// box touching nothing.
std::string scene(const std::string& resting) {
  std::ostringstream s;
  s << "bodies: [BODY jaw1, BODY jaw2" << (resting.find("soft") == 0 ? "]\n" : ", BODY thing]\n")
    << (resting.find("soft") == 0 ? "soft bodies: [BODY thing]\n" : "")
    << "BODY jaw2:\n  name: jaw2\n  mass: 0\n  collision shape: BOX\n"
    << "  collision geometry: {x: 0.01, y: 0.01, z: 0.01}\n"
    << "  location: {position: {x: 1, y: 0, z: 1}}\n"
    << "BODY jaw1:\n  name: jaw1\n  mass: 0\n  friction: {static: 1.0}\n"
    << "  collision shape: PLANE\n  collision geometry: {normal: {x: " << std::sin(kSlope)
    << ", y: 0, z: " << std::cos(kSlope) << "}, offset: 0}\n"
    << "BODY thing:\n  name: thing\n";
  if (resting.find("soft") == 0) {
    s << "  mesh: " << test_support::icosphereMesh().string()
      << "\n  mass: 0.05\n  scale: 0.02\n  location: {position: {x: 0, y: 0, z: 0.021}}\n"
      << "  collision margin: 0.0005\n  contact friction: coulomb\n"
      << "  config: {kDF: 1.0, kMT: 0.5, kVC: 10, piterations: 4}\n";
  } else {
    s << "  mass: 0.05\n  friction: {static: 1.0}\n  collision shape: BOX\n"
      << "  collision geometry: {x: 0.02, y: 0.02, z: 0.02}\n"
      << "  location: {position: {x: 0, y: 0, z: 0.0105}, orientation: {r: 0, p: " << kSlope
      << ", y: 0}}\n";
  }
  return s.str();
}

/// The jaw's forces on the resting thing, averaged over 200 steps after 1 s of settling.
bridge::JawForces forcesOnRestingThing(const std::string& kind) {
  test_support::TempDir dir;
  auto sim =
      test_support::simulate({dir.write("s.yaml", scene(kind))}, test_support::noSoftBodySleep);
  auto& world = *sim->world;
  world.step(1000);
  bridge::JawForces mean;
  for (int i = 0; i < 200; ++i) {
    world.step();
    const auto f =
        twin::graspForces(world, {"/ambf/env/jaw1", "/ambf/env/jaw2"}, {}, Eigen::Vector3d::Zero());
    mean.normal += f.jaws[0].normal / 200.0;
    mean.friction += f.jaws[0].friction / 200.0;
    mean.contacts = std::max(mean.contacts, f.jaws[0].contacts);
    EXPECT_EQ(f.jaws[1].contacts, 0);
    EXPECT_TRUE(f.force.isApprox(f.jaws[0].normal + f.jaws[0].friction));
  }
  return mean;
}

void expectInclineForces(const bridge::JawForces& f) {
  const double weight = 0.05 * kGravity;
  const Eigen::Vector3d normal(std::sin(kSlope), 0, std::cos(kSlope));
  const Eigen::Vector3d uphill(-std::cos(kSlope), 0, std::sin(kSlope));
  ASSERT_GT(f.contacts, 0);
  // The jaw carries the weight: normal and friction together point straight up.
  EXPECT_NEAR((f.normal + f.friction).z(), weight, 0.1 * weight);
  EXPECT_NEAR((f.normal + f.friction).head<2>().norm(), 0.0, 0.1 * weight);
  EXPECT_NEAR(f.normal.dot(normal), weight * std::cos(kSlope), 0.1 * weight);
  EXPECT_NEAR(f.friction.dot(uphill), weight * std::sin(kSlope), 0.1 * weight);
  EXPECT_NEAR(f.friction.dot(normal), 0.0, 0.02 * weight);
}

TEST(GraspForces, ARigidBodyOnATiltedJawIsHeldByItsNormalAndFriction) {
  expectInclineForces(forcesOnRestingThing("rigid"));
}

TEST(GraspForces, ACoulombSoftBodyOnATiltedJawIsHeldByItsNormalAndFriction) {
  expectInclineForces(forcesOnRestingThing("soft"));
}

TEST(GraspForces, BodiesOfTheJawsOwnArmAreNotObjects) {
  test_support::TempDir dir;
  auto sim = test_support::simulate({dir.write("s.yaml", scene("rigid"))});
  sim->world->step(500);
  const auto f = twin::graspForces(*sim->world, {"/ambf/env/jaw1", "/ambf/env/jaw2"},
                                   {"/ambf/env/thing"}, Eigen::Vector3d::Zero());
  EXPECT_EQ(f.jaws[0].contacts, 0);
  EXPECT_TRUE(f.force.isZero());
}

}  // namespace
