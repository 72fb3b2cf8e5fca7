// Reduced coordinates: a joint tree on a static body becomes one Featherstone articulation that
// starts where its bodies were loaded, moves as the constraint formulation does, holds loaded
// joints exactly, keeps its limits, and reads the same through Joint and RigidBody.

#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "test_files.hpp"

namespace {

using ambf_like::Articulation;
using ambf_like::Vec3;

/// A horizontal double pendulum on a static anchor, hinged about y (so gravity swings it),
/// with a small tip fixed to its lower link and `extra` spliced into the lower link's joint.
std::filesystem::path doublePendulum(const test_support::TempDir& dir,
                                     const std::string& extra = "",
                                     const std::string& damping = "{linear: 0, angular: 0}") {
  auto box = [&](const std::string& name, double mass, double x, double length) {
    return "BODY " + name + ":\n  mass: " + std::to_string(mass) +
           "\n  collision shape: BOX\n  collision geometry: {x: " + std::to_string(length) +
           ", y: 0.02, z: 0.02}\n  damping: " + damping +
           "\n  location: {position: {x: " + std::to_string(x) + ", y: 0, z: 0}}\n";
  };
  auto hinge = [](const std::string& name, const std::string& parent, const std::string& child,
                  double parent_x, double child_x, const std::string& type) {
    return "JOINT " + name + ":\n  parent: BODY " + parent + "\n  child: BODY " + child +
           "\n  parent pivot: {x: " + std::to_string(parent_x) +
           ", y: 0, z: 0}\n  child pivot: {x: " + std::to_string(child_x) +
           ", y: 0, z: 0}\n  parent axis: {x: 0, y: 1, z: 0}\n  child axis: {x: 0, y: 1, z: 0}\n"
           "  type: " +
           type + "\n  controller output type: POSITION\n  max motor impulse: 0.05\n";
  };
  return dir.write(
      "pendulum.yaml",
      "bodies: [BODY anchor, BODY upper, BODY lower, BODY tip]\n"
      "joints: [JOINT shoulder, JOINT elbow, JOINT tip_mount]\n"
      "ignore inter-collision: true\n"
      "BODY anchor: {mass: 0, collision shape: BOX, collision geometry: {x: 0.02, y: 0.02, z: "
      "0.02}}\n" +
          box("upper", 1.0, 0.1, 0.2) + box("lower", 0.5, 0.3, 0.2) + box("tip", 0.1, 0.4, 0.02) +
          hinge("shoulder", "anchor", "upper", 0.0, -0.1, "revolute") +
          hinge("elbow", "upper", "lower", 0.1, -0.1, "revolute") + extra +
          hinge("tip_mount", "lower", "tip", 0.1, 0.0, "fixed"));
}

std::unique_ptr<test_support::Simulation> load(const std::filesystem::path& model,
                                               Articulation articulation) {
  return test_support::simulate({model}, [articulation](ambf_like::WorldSpec& world) {
    world.articulation = articulation;
    world.solver_iterations = 50;  // the constraint formulation as tight as it gets
  });
}

/// The double pendulum with elbow limits [-0.5, 0.4] rad, its shoulder held at 0 and its elbow
/// pushed up (towards 0.4) with 1 N m from rest.
std::unique_ptr<test_support::Simulation> elbowPushedTowardsItsUpperLimit(
    const test_support::TempDir& dir) {
  auto sim =
      load(doublePendulum(dir, "  joint limits: {low: -0.5, high: 0.4}\n"), Articulation::Reduced);
  sim->world->joint("shoulder").commandPosition(0.0);
  sim->world->joint("elbow").commandEffort(1.0);
  return sim;
}

/// Steps all three `steps` times; the largest distance between the tip of `reduced` and that of
/// `maximal` on the way (`alongside` is a third world stepped with them).
double worstTipGap(test_support::Simulation& reduced, test_support::Simulation& maximal,
                   test_support::Simulation& alongside, int steps) {
  double worst = 0.0;
  for (int i = 0; i < steps; ++i) {
    reduced.world->step();
    maximal.world->step();
    alongside.world->step();
    const Vec3 gap = reduced.world->body("tip").pose().translation() -
                     maximal.world->body("tip").pose().translation();
    worst = std::max(worst, gap.norm());
  }
  return worst;
}

TEST(Articulation, AJointTreeOnAStaticBodyStartsWhereItsBodiesWereLoaded) {
  test_support::TempDir dir;
  // The elbow's zero is turned by 0.3 rad: the loaded pose reads -0.3 either way.
  const auto model = doublePendulum(dir, "  offset: 0.3\n");
  auto reduced = load(model, Articulation::Reduced);
  auto maximal = load(model, Articulation::Maximal);
  EXPECT_EQ(reduced->world->articulationCount(), 1u);
  EXPECT_EQ(maximal->world->articulationCount(), 0u);
  for (std::size_t j = 0; j < 3; ++j) {
    EXPECT_NEAR(reduced->world->joint(j).position(), maximal->world->joint(j).position(), 1e-12)
        << reduced->world->joint(j).name();
  }
  EXPECT_NEAR(reduced->world->joint("elbow").position(), -0.3, 1e-12);
  for (std::size_t b = 0; b < 4; ++b) {
    const auto a = reduced->world->body(b).pose();
    const auto m = maximal->world->body(b).pose();
    EXPECT_LT((a.translation() - m.translation()).norm(), 1e-12) << reduced->world->body(b).name();
    EXPECT_LT((a.linear() - m.linear()).norm(), 1e-12) << reduced->world->body(b).name();
  }
}

TEST(Articulation, AFreeDoublePendulumSwingsAsWithConstraintsAndHoldsItsEnergy) {
  test_support::TempDir dir;
  const auto model = doublePendulum(dir);
  auto reduced = load(model, Articulation::Reduced);
  auto maximal = load(model, Articulation::Maximal);
  auto energy = [](ambf_like::World& world) {
    double total = 0.0;
    for (std::size_t b = 0; b < world.bodyCount(); ++b) {
      const auto& body = world.body(b);
      if (body.isStatic()) continue;
      const Vec3 w = body.angularVelocity();
      const auto inertia = body.bullet().getLocalInertia();
      const Vec3 w_local = body.centerOfMassPose().linear().transpose() * w;
      total +=
          0.5 * body.mass() * body.linearVelocity().squaredNorm() +
          0.5 * (w_local.array().square() * Eigen::Array3d(inertia.x(), inertia.y(), inertia.z()))
                    .sum() +
          body.mass() * 9.81 * body.centerOfMassPose().translation().z();
    }
    return total;
  };
  const double reduced_start = energy(*reduced->world);
  const double maximal_start = energy(*maximal->world);
  double worst_gap = 0.0, reduced_drift = 0.0, maximal_drift = 0.0, lowest = 0.0;
  for (int i = 0; i < 500; ++i) {  // half a second: the tip falls through the bottom of its arc
    reduced->world->step();
    maximal->world->step();
    const Vec3 tip = reduced->world->body("tip").pose().translation();
    worst_gap =
        std::max(worst_gap, (tip - maximal->world->body("tip").pose().translation()).norm());
    reduced_drift = std::max(reduced_drift, std::abs(energy(*reduced->world) - reduced_start));
    maximal_drift = std::max(maximal_drift, std::abs(energy(*maximal->world) - maximal_start));
    lowest = std::min(lowest, tip.z());
  }
  RecordProperty("tip_gap_m", std::to_string(worst_gap));
  RecordProperty("reduced_energy_drift_j", std::to_string(reduced_drift));
  RecordProperty("maximal_energy_drift_j", std::to_string(maximal_drift));
  EXPECT_LT(lowest, -0.2) << "it should swing down";
  EXPECT_LT(worst_gap, 5e-3);
  // Both integrators are semi-implicit Euler: energy wanders within O(dt) of its start, not
  // away from it. 1 % of what the fall through 0.4 m releases (0.5 % measured, 0.1 % with
  // constraints).
  EXPECT_LT(reduced_drift, 0.01 * 1.6 * 9.81 * 0.4);
}

TEST(Articulation, BodiesMirrorTheirLinksVelocities) {
  test_support::TempDir dir;
  auto sim = load(doublePendulum(dir), Articulation::Reduced);
  auto& world = *sim->world;
  world.step(200);
  // Both hinges turn about y: the lower link spins at the sum of their rates, and its centre
  // moves with each rate about its own pivot.
  const double shoulder = world.joint("shoulder").velocity();
  const double elbow = world.joint("elbow").velocity();
  const Vec3 axis = Vec3::UnitY();
  const Vec3 centre = world.body("lower").centerOfMassPose().translation();
  const Vec3 elbow_pivot = world.body("upper").pose() * Vec3(0.1, 0, 0);
  const Vec3 expected = shoulder * axis.cross(centre) + elbow * axis.cross(centre - elbow_pivot);
  ASSERT_GT(expected.norm(), 0.5) << "the arm should be swinging";
  EXPECT_LT((world.body("lower").linearVelocity() - expected).norm(), 1e-9);
  EXPECT_LT((world.body("lower").angularVelocity() - (shoulder + elbow) * axis).norm(), 1e-9);
}

TEST(Articulation, PositionServoHoldsALoadedJointExactlyAndReportsTheTorque) {
  test_support::TempDir dir;
  auto sim = load(doublePendulum(dir), Articulation::Reduced);
  auto& world = *sim->world;
  world.joint("shoulder").commandPosition(-0.2);  // about y: the arm tips upwards
  world.joint("elbow").commandPosition(0.0);
  world.step(1000);
  EXPECT_NEAR(world.joint("shoulder").position(), -0.2, 1e-9);
  EXPECT_NEAR(world.joint("elbow").position(), 0.0, 1e-9);
  // The shoulder carries the whole arm's weight: the moment of every moving body about it.
  double moment = 0.0;
  for (const char* name : {"upper", "lower", "tip"}) {
    const auto& body = world.body(name);
    moment += body.mass() * 9.81 * body.centerOfMassPose().translation().x();
  }
  // Gravity turns the arm down (+y about the shoulder); the servo's torque balances it.
  EXPECT_NEAR(world.joint("shoulder").effort(), -moment, 1e-6 * moment);
}

TEST(Articulation, LimitsHoldAgainstAnEffortAndReportTheirTorque) {
  test_support::TempDir dir;
  auto sim = elbowPushedTowardsItsUpperLimit(dir);
  auto& world = *sim->world;
  world.step(1000);
  EXPECT_NEAR(world.joint("elbow").position(), 0.4, 1e-3);
  EXPECT_NEAR(world.joint("elbow").velocity(), 0.0, 1e-6);
  // At rest the limit holds both the 1 N m and gravity's torque; the joint's effort (the 1 N m
  // plus the limit's) is then minus gravity's torque about the elbow.
  const Vec3 pivot = world.body("upper").pose() * Vec3(0.1, 0, 0);
  double gravity_torque = 0.0;
  for (const char* name : {"lower", "tip"}) {
    const auto& body = world.body(name);
    gravity_torque += body.mass() * 9.81 * (body.centerOfMassPose().translation() - pivot).x();
  }
  EXPECT_NEAR(world.joint("elbow").effort(), -gravity_torque, 1e-3);
}

TEST(Articulation, AJointArrivingAtItsLimitStopsOnItWithoutPassingIt) {
  test_support::TempDir dir;
  auto sim = elbowPushedTowardsItsUpperLimit(dir);
  auto& world = *sim->world;
  // Driven from rest, the elbow arrives at several rad/s: a step's travel is millimetres of a
  // radian, which a row made only once the bound is passed would let it overshoot by.
  double highest = -1.0, arrival_speed = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const double speed = world.joint("elbow").velocity();
    world.step();
    const double q = world.joint("elbow").position();
    if (q > 0.4 - 1e-9 && arrival_speed == 0.0) arrival_speed = speed;
    highest = std::max(highest, q);
  }
  EXPECT_GT(arrival_speed * world.stepSize(), 2e-3) << "the test needs a fast arrival";
  EXPECT_LE(highest, 0.4 + 1e-6);
  EXPECT_NEAR(world.joint("elbow").position(), 0.4, 1e-6);
  EXPECT_NEAR(world.joint("elbow").velocity(), 0.0, 1e-6);  // stopped, not bounced
}

TEST(Articulation, DampedBodiesSlowDownAsBulletsDampedRigidBodiesDo) {
  test_support::TempDir dir;
  // AMBF's Raven damps every body with 0.99 (blender-raven2.yaml): a velocity kept at
  // (1 - 0.99)^t, down to 1 % in a second. Damping that strong dominates the swing.
  const auto model = doublePendulum(dir, "", "{linear: 0.99, angular: 0.99}");
  auto reduced = load(model, Articulation::Reduced);
  auto maximal = load(model, Articulation::Maximal);
  ASSERT_EQ(reduced->world->articulationCount(), 1u);
  EXPECT_TRUE(reduced->world->warnings().empty());
  auto undamped = load(doublePendulum(dir), Articulation::Reduced);
  const double worst_gap = worstTipGap(*reduced, *maximal, *undamped, 1000);
  RecordProperty("tip_gap_m", std::to_string(worst_gap));
  const double shoulder = reduced->world->joint("shoulder").position();
  const double free_shoulder = undamped->world->joint("shoulder").position();
  // A second in, the damped arm has sunk a good deal less far than the free one swung...
  EXPECT_GT(std::abs(free_shoulder - shoulder), 0.1) << shoulder << " vs " << free_shoulder;
  // ... and the two formulations agree on where it is: within 1 % of its 0.4 m reach.
  EXPECT_LT(worst_gap, 4e-3);
  EXPECT_NEAR(shoulder, maximal->world->joint("shoulder").position(), 0.01);
}

TEST(Articulation, AModelWithAGravityOfItsOwnSwingsByIt) {
  test_support::TempDir dir;
  // The pendulum on Mars: its model's gravity, not the world's.
  const auto earth = doublePendulum(dir);
  std::ifstream in(earth);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto mars = dir.write("mars.yaml", "gravity: {x: 0, y: 0, z: -3.71}\n" + text);
  auto reduced = load(mars, Articulation::Reduced);
  auto maximal = load(mars, Articulation::Maximal);
  auto on_earth = load(earth, Articulation::Reduced);
  ASSERT_EQ(reduced->world->articulationCount(), 1u);
  const double worst_gap = worstTipGap(*reduced, *maximal, *on_earth, 300);
  // In 0.3 s the tip falls about g t^2 / 2 at first: 17 cm on Mars, 44 cm on Earth (less, as
  // it swings); the two formulations agree on Mars's.
  const double fallen = -reduced->world->body("tip").pose().translation().z();
  const double fallen_on_earth = -on_earth->world->body("tip").pose().translation().z();
  EXPECT_GT(fallen, 0.05);
  EXPECT_GT(fallen_on_earth, 1.5 * fallen);
  EXPECT_LT(worst_gap, 2e-3);
}

TEST(Articulation, EachBranchFromAStaticBodyIsAnArticulationAndTheRestStaysMaximal) {
  test_support::TempDir dir;
  // AMBF's Raven in small: a moving body welded between two static bases, an arm on each.
  const std::string box = "collision shape: BOX, collision geometry: {x: 0.02, y: 0.02, z: 0.02}";
  auto body = [&](const std::string& name, double mass, double y) {
    return "BODY " + name + ": {mass: " + std::to_string(mass) + ", " + box +
           ", damping: {linear: 0.99, angular: 0.99}, location: {position: {x: 0, y: " +
           std::to_string(y) + ", z: 0}}}\n";
  };
  auto joint = [](const std::string& parent, const std::string& child, const std::string& type) {
    return "JOINT " + parent + "-" + child + ": {parent: BODY " + parent + ", child: BODY " +
           child +
           ", parent axis: {x: 0, y: 0, z: 1}, child axis: {x: 0, y: 0, z: 1}, type: " + type +
           ", controller: {P: 10, I: 0, D: 0.01}}\n";
  };
  const auto model = dir.write(
      "bases.yaml",
      "bodies: [BODY weld, BODY base_L, BODY arm_L, BODY base_R, BODY arm_R]\n"
      "joints: [JOINT weld-base_L, JOINT base_L-arm_L, JOINT weld-base_R, JOINT base_R-arm_R]\n"
      "ignore inter-collision: true\n" +
          body("weld", 0.1, 0) + body("base_L", 0, 0.1) + body("arm_L", 0.5, 0.1) +
          body("base_R", 0, -0.1) + body("arm_R", 0.5, -0.1) + joint("weld", "base_L", "fixed") +
          joint("base_L", "arm_L", "revolute") + joint("weld", "base_R", "fixed") +
          joint("base_R", "arm_R", "revolute"));
  auto sim = load(model, Articulation::Reduced);
  auto& world = *sim->world;
  EXPECT_EQ(world.articulationCount(), 2u);
  ASSERT_EQ(world.warnings().size(), 1u);
  EXPECT_THAT(world.warnings()[0], testing::HasSubstr("'weld' is no joint's child"));
  // Joints keep the model's order, whichever formulation each has.
  ASSERT_EQ(world.jointCount(), 4u);
  EXPECT_EQ(world.joint(1).name(), "base_L-arm_L");
  EXPECT_EQ(world.joint(2).name(), "weld-base_R");
  // The right arm turns as it does with constraints; the left one, not commanded, stays. (With
  // AMBF's default controller, D = 1 on a velocity output, the velocity command flips sign
  // every step: the exact motor of reduced coordinates follows it, Bullet's iterative one
  // smooths it, and the two drift apart by some 0.05 rad a second.)
  auto maximal = load(model, Articulation::Maximal);
  for (auto* w : {&world, maximal->world.get()}) {
    w->joint("base_R-arm_R").commandPosition(0.3);
    w->step(1000);
  }
  const double turned = world.joint("base_R-arm_R").position();
  EXPECT_GT(turned, 0.1);
  EXPECT_NEAR(turned, maximal->world->joint("base_R-arm_R").position(), 1e-3);
  EXPECT_NEAR(world.joint("base_L-arm_L").position(), 0.0, 1e-9);
}

TEST(Articulation, JointsThatAreNoTreeOnAStaticBodyStayInMaximalCoordinatesSayingWhy) {
  test_support::TempDir dir;
  // A spring is not a degree of freedom Bullet's articulations have.
  const auto spring = dir.write(
      "spring.yaml",
      "bodies: [BODY a, BODY b]\njoints: [JOINT s]\n"
      "BODY a: {mass: 0}\n"
      "BODY b: {mass: 1, inertia: {ix: 1, iy: 1, iz: 1}, damping: {linear: 0, angular: 0}}\n"
      "JOINT s: {parent: BODY a, child: BODY b, type: linear spring, stiffness: 10}\n");
  auto sim = load(spring, Articulation::Reduced);
  EXPECT_EQ(sim->world->articulationCount(), 0u);
  ASSERT_EQ(sim->world->warnings().size(), 1u);
  EXPECT_THAT(sim->world->warnings()[0],
              testing::AllOf(testing::HasSubstr("spring.yaml"),
                             testing::HasSubstr("left in maximal coordinates"),
                             testing::HasSubstr("joint 's'")));
  sim->world->step(10);
  EXPECT_TRUE(sim->world->isFinite());
  // Asked for nothing, a world says nothing.
  EXPECT_TRUE(load(spring, Articulation::Maximal)->world->warnings().empty());
}

/// A URDF chain of `links` revolute joints hanging from a static base.
std::string urdfChain(int links) {
  std::string urdf = "<?xml version=\"1.0\"?>\n<robot name=\"chain\">\n<link name=\"base\"/>\n";
  for (int i = 0; i < links; ++i) {
    const std::string name = "l" + std::to_string(i);
    urdf += "<link name=\"" + name +
            "\"><inertial><mass value=\"0.01\"/><inertia ixx=\"1e-5\" iyy=\"1e-5\" "
            "izz=\"1e-5\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>\n"
            "<joint name=\"j" +
            std::to_string(i) + "\" type=\"revolute\"><parent link=\"" +
            (i == 0 ? std::string("base") : "l" + std::to_string(i - 1)) + "\"/><child link=\"" +
            name +
            "\"/><origin xyz=\"0 0 0.01\"/><axis xyz=\"1 0 0\"/><limit lower=\"-1\" "
            "upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>\n";
  }
  return urdf + "</robot>\n";
}

TEST(Articulation, ALongChainStaysInMaximalCoordinatesWhereItsJointSpaceSolveWouldNotFit) {
  // One articulation's servo keeps its dense joint-space inverse inertia: a 20,000-joint chain
  // held 15.9 GB and never stepped. Up to 64 moving joints a chain is one articulation; beyond,
  // it is constraints (linear in the joints), and asked for reduced the world says why.
  test_support::TempDir dir;
  const auto fits = dir.write("fits.urdf", urdfChain(64));
  const auto long_chain = dir.write("long.urdf", urdfChain(65));
  EXPECT_EQ(test_support::simulate({fits})->world->articulationCount(), 1u);
  EXPECT_EQ(test_support::simulate({long_chain})->world->articulationCount(), 0u);
  auto asked = load(long_chain, Articulation::Reduced);
  EXPECT_EQ(asked->world->articulationCount(), 0u);
  ASSERT_EQ(asked->world->warnings().size(), 1u);
  EXPECT_THAT(
      asked->world->warnings()[0],
      testing::AllOf(testing::HasSubstr("long.urdf"), testing::HasSubstr("65 moving joints"),
                     testing::HasSubstr("left in maximal coordinates")));
  asked->world->step(10);
  EXPECT_TRUE(asked->world->isFinite());
}

TEST(Articulation, TheDefaultIsReducedWhereverReducedCarriesTheScene) {
  test_support::TempDir dir;
  const auto pendulum = doublePendulum(dir);
  auto by_default = [](const std::vector<std::filesystem::path>& models) {
    return test_support::simulate(models);  // Articulation::Automatic
  };
  auto alone = by_default({pendulum});
  EXPECT_EQ(alone->world->articulationCount(), 1u);
  EXPECT_TRUE(alone->world->warnings().empty()) << "maximal where needed says nothing";
  // A soft body with Coulomb contacts pushes on links as on rigid bodies: the pendulum stays one
  // articulation.
  dir.write("cube.vtk", test_support::boxVtk(2, 2, 2, 0.01));
  const auto coulomb =
      dir.write("cube.yaml",
                "namespace: /cube/\nsoft bodies: [BODY cube]\n"
                "BODY cube: {name: cube, mass: 0.05, mesh: cube.vtk, contact friction: coulomb, "
                "location: {position: {x: 0, y: 0.5, z: 0}}}\n");
  EXPECT_EQ(by_default({pendulum, coulomb})->world->articulationCount(), 1u);
  // An actuator hanging from the lower link attaches bodies by constraints between rigid bodies:
  // that branch stays maximal, and the actuator takes a free box.
  const auto hand = dir.write(
      "hand.yaml",
      "namespace: /hand/\nbodies: [BODY box]\nactuators: [ACTUATOR hand]\n"
      "BODY box: {name: box, mass: 0.1, collision shape: BOX, collision geometry: {x: 0.02, y: "
      "0.02, z: 0.02}, location: {position: {x: 0.3, y: 0, z: -0.05}}}\n"
      "ACTUATOR hand: {name: hand, type: CONSTRAINT, parent: BODY /ambf/env/lower}\n");
  auto held = by_default({pendulum, hand});
  EXPECT_EQ(held->world->articulationCount(), 0u);
  EXPECT_NO_THROW(held->world->actuator("hand").actuate(held->world->body("box")));
}

TEST(Articulation, AnActuatorRefusesToAttachALinkNamingWhy) {
  test_support::TempDir dir;
  const auto pendulum = doublePendulum(dir);
  const auto hand = dir.write("hand.yaml",
                              "namespace: /hand/\nactuators: [ACTUATOR hand]\n"
                              "ACTUATOR hand: {name: hand, type: CONSTRAINT, parent: BODY "
                              "/ambf/env/anchor}\n");
  auto sim = test_support::simulate({pendulum, hand}, [](ambf_like::WorldSpec& world) {
    world.articulation = Articulation::Reduced;
  });
  ASSERT_EQ(sim->world->articulationCount(), 1u);
  try {
    sim->world->actuator("hand").actuate(sim->world->body("lower"));
    FAIL() << "attached a link";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), testing::HasSubstr("link of an articulation"));
  }
}

TEST(Articulation, ARunawayJointIsNotClampedBelowWhatRigidBodiesReach) {
  test_support::TempDir dir;
  // Bullet clamps a multibody's joint speeds at 100 rad/s; a rigid body turns up to a quarter
  // turn a step (1571 rad/s at 1 ms), and so does a link here.
  auto sim = load(doublePendulum(dir), Articulation::Reduced);
  sim->world->joint("shoulder").commandEffort(50.0);
  sim->world->step(150);  // the tip, 0.4 m out, stays below the StepGuard's 100 m/s
  EXPECT_GT(std::abs(sim->world->joint("shoulder").velocity()),
            120.0);  // Bullet would stop it at 100
}

}  // namespace
