// World::saveState and World::restoreState: after a restore the world steps exactly as it did
// after the save (stacked boxes in contact, a soft ball and a material cube with Coulomb contacts
// on the ground, a joint under control), whatever it did in between; saving keeps the contacts'
// warm start; a state belongs to its world; an articulated arm (reduced coordinates) against
// its limits and the ground repeats too.

#include <BulletSoftBody/btSoftBody.h>
#include <btBulletDynamicsCommon.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

#include "test_files.hpp"

namespace {

using test_support::TempDir;

std::string box(const std::string& name, double z) {
  std::ostringstream s;
  s << "BODY " << name << ":\n  name: " << name
    << "\n  mass: 0.2\n  collision shape: BOX\n  collision geometry: {x: 0.04, y: 0.04, z: 0.04}"
       "\n  location: {position: {x: 0.3, y: 0, z: "
    << z << "}}\n";
  return s.str();
}

/// Three boxes stacked on the ground, a soft ball dropped beside them, a 10 mm material cube
/// with Coulomb contacts, and a link on a revolute joint with a PID.
std::filesystem::path writeScene(const TempDir& dir) {
  dir.write("cube.vtk", test_support::boxVtk(3, 3, 3, 0.01 / 3));
  return dir.write(
      "scene.yaml",
      "bodies: [BODY ground, BODY box1, BODY box2, BODY box3, BODY base, BODY link]\n"
      "soft bodies: [BODY blob, BODY cube]\njoints: [JOINT base-link]\n" +
          test_support::groundPlaneBody() + box("box1", 0.0205) + box("box2", 0.061) +
          box("box3", 0.1015) +
          "BODY base: {name: base, mass: 0, collision shape: BOX, collision geometry: {x: 0.05, "
          "y: 0.05, z: 0.05}, location: {position: {x: -0.3, y: 0, z: 0.5}}}\n"
          "BODY link:\n  name: link\n  mass: 1.0\n  collision shape: BOX\n"
          "  collision geometry: {x: 0.2, y: 0.04, z: 0.04}\n"
          "  collision offset: {position: {x: 0.1, y: 0, z: 0}}\n"
          "  inertial offset: {position: {x: 0.1, y: 0, z: 0}}\n"
          "  location: {position: {x: -0.3, y: 0, z: 0.6}}\n" +
          test_support::softBallBody(0.002) +
          "  location: {position: {x: 0, y: 0.3, z: 0.08}}\n"
          "  config: {kDF: 0.8, kVC: 20, piterations: 4, bending constraint: 2}\n"
          "BODY cube:\n  name: cube\n  mesh: cube.vtk\n"
          "  material: {young's modulus: 1.0e6, poisson's ratio: 0.45, density: 1100}\n"
          "  location: {position: {x: 0, y: -0.3, z: 0.002}}\n  collision margin: 0.0005\n"
          "  contact friction: coulomb\n"
          "JOINT base-link:\n  name: base-link\n  parent: BODY base\n  child: BODY link\n"
          "  parent pivot: {x: 0, y: 0, z: 0.1}\n  parent axis: {x: 0, y: 1, z: 0}\n"
          "  child axis: {x: 0, y: 1, z: 0}\n  type: revolute\n"
          "  joint limits: {low: -1.5, high: 1.5}\n  controller: {P: 200, I: 40, D: 10}\n");
}

/// Contacts that see millimetres.
void options(ambf_like::WorldSpec& world) {
  world.sdf_voxel_size = 0.001;
}

/// Every coordinate of the world's motion as raw doubles: the bodies' poses and velocities, the
/// soft bodies' nodes and their velocities, the joint, the contact impulses.
std::vector<double> motionOf(const ambf_like::World& world) {
  std::vector<double> out;
  auto push = [&](const btVector3& v) { out.insert(out.end(), {v.x(), v.y(), v.z()}); };
  for (std::size_t i = 0; i < world.bodyCount(); ++i) {
    const btRigidBody& b = world.body(i).bullet();
    push(b.getWorldTransform().getOrigin());
    const btQuaternion q = b.getWorldTransform().getRotation();
    out.insert(out.end(), {q.x(), q.y(), q.z(), q.w()});
    push(b.getLinearVelocity());
    push(b.getAngularVelocity());
  }
  for (std::size_t i = 0; i < world.softBodyCount(); ++i) {
    const btSoftBody& s = world.softBody(i).bullet();
    for (int n = 0; n < s.m_nodes.size(); ++n) {
      push(s.m_nodes[n].m_x);
      push(s.m_nodes[n].m_v);
    }
  }
  out.push_back(world.joint(0).position());
  for (const auto& c : world.contacts()) out.push_back(c.normal_impulse);
  for (const auto& f : world.softContactForces()) out.push_back(f.normal_force.z());
  return out;
}

/// Steps `steps` times, moving the joint's target midway; the motion after each step.
std::vector<std::vector<double>> run(ambf_like::World& world, int steps) {
  std::vector<std::vector<double>> out;
  for (int i = 0; i < steps; ++i) {
    if (i == steps / 2) world.joint("base-link").commandPosition(-0.6);
    world.step();
    out.push_back(motionOf(world));
  }
  return out;
}

TEST(WorldState, StepsAfterARestoreRepeatTheStepsAfterTheSaveBitForBit) {
  TempDir dir;
  auto sim = test_support::simulate({writeScene(dir)}, options);
  ambf_like::World& world = *sim->world;
  world.joint("base-link").commandPosition(0.7);
  world.step(400);  // the boxes settle on each other, the ball and the cube land
  ASSERT_GE(world.contacts("box2").size(), 4u) << "the stack is in contact";
  ASSERT_FALSE(world.softContactForces().empty()) << "the cube rests on its Coulomb contacts";

  const auto state = world.saveState();
  const double saved_time = world.time();
  const auto at_save = motionOf(world);
  const auto after_save = run(world, 300);
  world.step(500);  // and on, far from the saved state
  ASSERT_NE(motionOf(world), at_save);

  world.restoreState(*state);
  EXPECT_EQ(world.time(), saved_time);
  EXPECT_EQ(world.stepCount(), 400u);
  EXPECT_EQ(motionOf(world), at_save);
  EXPECT_EQ(run(world, 300), after_save);

  world.restoreState(*state);  // a state restores as often as asked
  EXPECT_EQ(run(world, 300), after_save);
}

TEST(WorldState, SavingKeepsTheContactsAndTheirWarmStart) {
  // Saving reorders the collision caches, so the steps after it are not those of a world that
  // did not save, bit for bit; but they keep every contact point and its impulse. Without them
  // the stack loses half its points for a step and its top box drops 8 um.
  TempDir dir;
  auto saving = test_support::simulate({writeScene(dir)}, options);
  auto plain = test_support::simulate({writeScene(dir)}, options);
  for (auto* world : {saving->world.get(), plain->world.get()}) {
    world->joint("base-link").commandPosition(0.7);
    world->step(400);
  }
  saving->world->saveState();
  saving->world->step();
  plain->world->step();
  EXPECT_EQ(saving->world->contacts("box2").size(), plain->world->contacts("box2").size());
  const auto z = [](const test_support::Simulation& sim) {
    return sim.world->body("box3").bullet().getWorldTransform().getOrigin().z();
  };
  EXPECT_NEAR(z(*saving), z(*plain), 1e-6);
}

TEST(WorldState, AStateBelongsToItsWorld) {
  TempDir dir;
  auto one = test_support::simulate({writeScene(dir)}, options);
  auto other = test_support::simulate({writeScene(dir)}, options);
  const auto state = one->world->saveState();
  EXPECT_THROW(other->world->restoreState(*state), std::invalid_argument);
}

/// An arm in reduced coordinates: a shoulder under a PID from a static base, an elbow with
/// limits it falls against, the forearm sweeping a box on the ground, a soft ball dropped on the
/// upper arm.
std::filesystem::path writeArm(const TempDir& dir) {
  auto link = [](const std::string& name, double x) {
    return "BODY " + name + ":\n  name: " + name +
           "\n  mass: 0.5\n  collision shape: BOX\n"
           "  collision geometry: {x: 0.2, y: 0.03, z: 0.03}\n"
           "  location: {position: {x: " +
           std::to_string(x) + ", y: 0, z: 0.15}}\n";
  };
  auto revolute = [](const std::string& name, const std::string& parent, const std::string& child,
                     double pivot_x, const std::string& extra) {
    return "JOINT " + name + ":\n  name: " + name + "\n  parent: BODY " + parent +
           "\n  child: BODY " + child + "\n  parent pivot: {x: " + std::to_string(pivot_x) +
           ", y: 0, z: 0}\n  child pivot: {x: -0.1, y: 0, z: 0}\n"
           "  parent axis: {x: 0, y: 1, z: 0}\n  child axis: {x: 0, y: 1, z: 0}\n"
           "  type: revolute\n" +
           extra;
  };
  return dir.write(
      "arm.yaml",
      "bodies: [BODY ground, BODY base, BODY upper, BODY fore, BODY box1]\n"
      "soft bodies: [BODY blob]\njoints: [JOINT shoulder, JOINT elbow]\n" +
          test_support::groundPlaneBody() +
          "BODY base: {name: base, mass: 0, collision shape: BOX, collision geometry: {x: 0.05, "
          "y: 0.05, z: 0.05}, location: {position: {x: 0, y: 0, z: 0.15}}}\n" +
          link("upper", 0.125) + link("fore", 0.325) + box("box1", 0.0205) +
          test_support::softBallBody(0.002) +
          "  location: {position: {x: 0.15, y: 0, z: 0.3}}\n"
          "  config: {kDF: 0.8, kVC: 20, piterations: 4, bending constraint: 2}\n" +
          revolute("shoulder", "base", "upper", 0.025,
                   "  joint limits: {low: -1.5, high: 1.5}\n  controller: {P: 30, I: 5, D: 2}\n") +
          revolute("elbow", "upper", "fore", 0.1, "  joint limits: {low: -0.4, high: 0.4}\n"));
}

/// The arm's motion: its joints, its links' poses and velocities, the ball's nodes, the
/// contacts.
std::vector<double> armMotionOf(const ambf_like::World& world) {
  auto out = motionOf(world);
  for (std::size_t i = 0; i < world.jointCount(); ++i) {
    out.insert(out.end(),
               {world.joint(i).position(), world.joint(i).velocity(), world.joint(i).effort()});
  }
  return out;
}

TEST(WorldState, AnArticulatedArmRepeatsItsStepsAfterARestoreBitForBit) {
  TempDir dir;
  auto reduced = [](ambf_like::WorldSpec& world) {
    options(world);
    world.articulation = ambf_like::Articulation::Reduced;
  };
  auto sim = test_support::simulate({writeArm(dir)}, reduced);
  ambf_like::World& world = *sim->world;
  ASSERT_EQ(world.articulationCount(), 1u);
  world.joint("shoulder").commandPosition(0.5);  // the forearm down onto the box
  world.step(400);
  ASSERT_FALSE(world.contacts("fore").empty()) << "the forearm touches the box";
  for (const auto& c : world.contacts("base")) {  // jointed to it, overlapping it: no contact
    EXPECT_FALSE(c.body_a == "/ambf/env/upper" || c.body_b == "/ambf/env/upper");
  }
  ASSERT_GT(std::abs(world.joint("elbow").effort()), 0.0) << "the elbow rests on its limit";

  const auto state = world.saveState();
  auto run_arm = [&](int steps) {
    std::vector<std::vector<double>> out;
    for (int i = 0; i < steps; ++i) {
      if (i == steps / 2) world.joint("shoulder").commandPosition(-0.3);  // and up again
      world.step();
      out.push_back(armMotionOf(world));
    }
    return out;
  };
  const auto at_save = armMotionOf(world);
  const auto after_save = run_arm(300);
  world.step(500);
  ASSERT_NE(armMotionOf(world), at_save);

  world.restoreState(*state);
  EXPECT_EQ(armMotionOf(world), at_save);
  EXPECT_EQ(run_arm(300), after_save);
}

}  // namespace
