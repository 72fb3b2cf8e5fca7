// Coulomb contacts of soft bodies (`contact friction: coulomb`): the friction cone on an
// incline, the contact forces against the weight, a pinch that holds only when squeezed, and a
// body resting on a link that never sleeps while the link may move.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <sstream>

#include "test_files.hpp"

namespace {

constexpr double kGravity = 9.81;
constexpr double kCubeMass = 0.02;  // kg
constexpr double kCubeSide = 0.02;  // m

/// A closed cube surface of side 1 centred on the origin, `n` x `n` squares per face.
std::string subdividedCubeObj(int n) {
  std::ostringstream obj;
  int base = 1;
  // Each face: an origin corner and two edge directions, outward by the right-hand rule.
  const int faces[6][3][3] = {
      {{-1, -1, -1}, {0, 1, 0}, {1, 0, 0}}, {{-1, -1, 1}, {1, 0, 0}, {0, 1, 0}},
      {{-1, -1, -1}, {1, 0, 0}, {0, 0, 1}}, {{-1, 1, -1}, {0, 0, 1}, {1, 0, 0}},
      {{-1, -1, -1}, {0, 0, 1}, {0, 1, 0}}, {{1, -1, -1}, {0, 1, 0}, {0, 0, 1}}};
  for (const auto& f : faces) {
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; j <= n; ++j) {
        const double u = 2.0 * i / n, v = 2.0 * j / n;
        obj << "v";
        for (int k = 0; k < 3; ++k) obj << ' ' << 0.5 * (f[0][k] + u * f[1][k] + v * f[2][k]);
        obj << '\n';
      }
    }
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const int a = base + i * (n + 1) + j, b = a + (n + 1), c = b + 1, d = a + 1;
        obj << "f " << a << ' ' << b << ' ' << c << "\nf " << a << ' ' << c << ' ' << d << '\n';
      }
    }
    base += (n + 1) * (n + 1);
  }
  return obj.str();
}

/// ADF of a soft cube "cube" (2 cm, 20 g) at `z` with Coulomb contacts and friction factor kDF.
std::string softCube(double x, double z, double kdf) {
  std::ostringstream s;
  s << "BODY cube:\n  name: cube\n  mesh: cube.obj\n  mass: " << kCubeMass
    << "\n  scale: " << kCubeSide << "\n  location: {position: {x: " << x << ", y: 0, z: " << z
    << "}}\n  collision margin: 0.0005\n  contact friction: coulomb\n"
    << "  config: {kDF: " << kdf << ", kMT: 0.2, kVC: 10, piterations: 4, kDP: 0.001}\n";
  return s.str();
}

/// Static ground plane tilted by `angle` about y (uphill towards -x), friction 1.
std::string tiltedGround(double angle) {
  std::ostringstream s;
  s << "BODY ground:\n  name: ground\n  mass: 0\n  friction: {static: 1.0}\n"
    << "  collision shape: PLANE\n  collision geometry: {normal: {x: " << std::sin(angle)
    << ", y: 0, z: " << std::cos(angle) << "}, offset: 0}\n";
  return s.str();
}

struct Scene {
  test_support::TempDir dir;
  std::unique_ptr<test_support::Simulation> sim;
  explicit Scene(const std::string& adf) {
    dir.write("cube.obj", subdividedCubeObj(4));
    // Awake throughout: a sleeping body has no contacts to read.
    sim = test_support::simulate({dir.write("scene.yaml", adf)}, test_support::noSoftBodySleep);
  }
  ambf_like::World& world() { return *sim->world; }
};

/// How far the cube's centre moves along the incline in `seconds` once it has settled.
double slideOnIncline(double angle, double kdf, double seconds) {
  Scene scene("bodies: [BODY ground]\nsoft bodies: [BODY cube]\n" + tiltedGround(angle) +
              softCube(0.0, 0.5 * kCubeSide / std::cos(angle) + 0.001, kdf));
  auto& world = scene.world();
  auto& cube = world.softBody("cube");
  world.step(300);
  const Eigen::Vector3d start = cube.centerOfMass();
  world.step(static_cast<std::uint64_t>(seconds / world.stepSize()));
  EXPECT_TRUE(cube.isFinite());
  const Eigen::Vector3d downhill(std::cos(angle), 0.0, -std::sin(angle));
  return (cube.centerOfMass() - start).dot(downhill);
}

TEST(CoulombContact, ACubeStaysOnAnInclineInsideTheFrictionCone) {
  // tan(16.7 deg) = 0.3 < mu = kDF x 1 = 0.6: static friction holds it.
  const double slide = slideOnIncline(std::atan(0.3), 0.6, 1.0);
  EXPECT_LT(std::abs(slide), 0.001) << "moved " << slide << " m along the incline";
}

TEST(CoulombContact, ACubeSlidesOnAnInclineOutsideTheFrictionCone) {
  // tan = 0.3 > mu = 0.15: it slides with a = g (sin - mu cos) = 1.41 m/s^2, 0.70 m in 1 s.
  const double angle = std::atan(0.3);
  const double expected = 0.5 * kGravity * (std::sin(angle) - 0.15 * std::cos(angle));
  const double slide = slideOnIncline(angle, 0.15, 1.0);
  EXPECT_GT(slide, 0.5 * expected);
  EXPECT_LT(slide, 1.2 * expected);
}

TEST(CoulombContact, ContactForcesOnACubeAtRestCarryItsWeight) {
  Scene scene("bodies: [BODY ground]\nsoft bodies: [BODY cube]\n" + tiltedGround(0.0) +
              softCube(0.0, 0.5 * kCubeSide + 0.001, 0.6));
  auto& world = scene.world();
  world.step(500);
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  const int steps = 200;
  for (int i = 0; i < steps; ++i) {
    world.step();
    for (const auto& f : world.softContactForces()) {
      EXPECT_EQ(f.rigid_body, "/ambf/env/ground");
      EXPECT_GE(f.normal_force.dot(f.normal), 0.0) << "contacts push, never pull";
      EXPECT_NEAR(f.friction_force.dot(f.normal), 0.0, 1e-12);
      total += f.normal_force + f.friction_force;
    }
  }
  total /= steps;
  EXPECT_NEAR(total.z(), kCubeMass * kGravity, 0.1 * kCubeMass * kGravity);
  EXPECT_LT(total.head<2>().norm(), 0.05 * kCubeMass * kGravity);
}

/// The cube hung between two vertical walls `gap` apart (no floor): how far it falls in
/// `seconds` after its first 0.3 s (the grip settling).
double fallBetweenWalls(double gap, double seconds) {
  std::ostringstream walls;
  for (int side : {-1, 1}) {
    walls << "BODY wall" << (side < 0 ? "L" : "R") << ":\n  name: wall" << (side < 0 ? "L" : "R")
          << "\n  mass: 0\n  friction: {static: 1.0}\n  collision shape: BOX\n"
          << "  collision geometry: {x: 0.01, y: 0.04, z: 0.04}\n"
          << "  location: {position: {x: " << side * (0.5 * gap + 0.005) << ", y: 0, z: 0}}\n";
  }
  Scene scene("bodies: [BODY wallL, BODY wallR]\nsoft bodies: [BODY cube]\n" + walls.str() +
              softCube(0.0, 0.0, 1.0));
  auto& world = scene.world();
  auto& cube = world.softBody("cube");
  world.step(300);
  const double start = cube.centerOfMass().z();
  world.step(static_cast<std::uint64_t>(seconds / world.stepSize()));
  EXPECT_TRUE(cube.isFinite());
  return start - cube.centerOfMass().z();
}

TEST(CoulombContact, APinchHoldsWhenSqueezedAndLetsGoWhenNot) {
  const double squeezed = fallBetweenWalls(0.7 * kCubeSide, 1.0);
  const double squeezed_less = fallBetweenWalls(0.9 * kCubeSide, 1.0);
  // The walls' surfaces at the cube's faces' collision margin (0.5 mm).
  const double touching = fallBetweenWalls(kCubeSide + 2 * 0.0005, 1.0);
  EXPECT_LT(squeezed, 0.0005) << "a cube squeezed by 30 % slid " << squeezed << " m in 1 s";
  EXPECT_LT(squeezed_less, 0.0005) << "a cube squeezed by 10 % slid " << squeezed_less << " m";
  EXPECT_GT(touching, 0.1) << "a cube merely touching both walls fell only " << touching << " m";
}

/// A 100 g paddle 20 cm long, hinged about y at x = 0 to a static anchor and held level by its
/// joint's position controller (or by nothing of its own), with the cube resting on it `x` from
/// the hinge.
std::string cubeOnAPaddle(double x, bool position_controlled = true) {
  std::ostringstream s;
  s << "bodies: [BODY anchor, BODY paddle]\njoints: [JOINT hinge]\nsoft bodies: [BODY cube]\n"
    << "ignore inter-collision: true\n"
    << "BODY anchor: {name: anchor, mass: 0, collision shape: BOX, collision geometry: {x: 0.01, "
       "y: 0.01, z: 0.01}}\n"
    << "BODY paddle:\n  name: paddle\n  mass: 0.1\n  friction: {static: 1.0}\n"
    << "  damping: {linear: 0, angular: 0}\n  collision shape: BOX\n"
    << "  collision geometry: {x: 0.2, y: 0.06, z: 0.01}\n"
    << "  location: {position: {x: 0.1, y: 0, z: 0}}\n"
    << "JOINT hinge:\n  parent: BODY anchor\n  child: BODY paddle\n"
    << "  parent pivot: {x: 0, y: 0, z: 0}\n  child pivot: {x: -0.1, y: 0, z: 0}\n"
    << "  parent axis: {x: 0, y: 1, z: 0}\n  child axis: {x: 0, y: 1, z: 0}\n  type: revolute\n"
    << (position_controlled ? "  controller output type: POSITION\n  max motor impulse: 0.05\n"
                            : "")
    << softCube(x, 0.005 + 0.5 * kCubeSide + 0.001, 0.6);
  return s.str();
}

/// The paddle's hinge effort and the cube's centre x, each averaged over `steps` more steps.
struct PaddleLoad {
  double effort = 0.0;  ///< N m
  double cube_x = 0.0;  ///< m
};
PaddleLoad meanLoad(ambf_like::World& world, int steps) {
  PaddleLoad mean;
  for (int i = 0; i < steps; ++i) {
    world.step();
    mean.effort += world.joint("hinge").effort() / steps;
    mean.cube_x += world.softBody("cube").centerOfMass().x() / steps;
  }
  return mean;
}

/// What holds the level paddle and the cube (its centre `cube_x` from the hinge) at rest about
/// the hinge: the paddle's weight at L/2 and the cube's at its centre (N m, about y).
double holdingMoment(double cube_x) {
  return -(0.1 * kGravity * 0.1 + kCubeMass * kGravity * cube_x);
}

TEST(CoulombContact, ACubeOnAnArticulatedPaddleLoadsItsJointWithItsWeightsMoment) {
  // The paddle is a link of an articulation (reduced coordinates) or a rigid body (maximal):
  // either way the cube's contacts push it, and at rest its joint holds the paddle's weight
  // (m g L/2) and the cube's (m g x, x its centre's distance from the hinge).
  for (const auto articulation :
       {ambf_like::Articulation::Reduced, ambf_like::Articulation::Maximal}) {
    const bool reduced = articulation == ambf_like::Articulation::Reduced;
    test_support::TempDir dir;
    dir.write("cube.obj", subdividedCubeObj(4));
    auto sim = test_support::simulate({dir.write("scene.yaml", cubeOnAPaddle(0.15))},
                                      [articulation](ambf_like::WorldSpec& world) {
                                        world.articulation = articulation;
                                        world.soft_body_sleep.enabled = false;
                                      });
    auto& world = *sim->world;
    ASSERT_EQ(world.articulationCount(), reduced ? 1u : 0u);
    auto& hinge = world.joint("hinge");
    hinge.commandPosition(0.0);
    world.step(500);
    const PaddleLoad load = meanLoad(world, 200);
    const double cube_moment = kCubeMass * kGravity * load.cube_x;
    const double expected = holdingMoment(load.cube_x);
    std::cout << (reduced ? "reduced" : "maximal") << ": joint " << load.effort << " N m, expected "
              << expected << " (the cube's share " << cube_moment << ")\n";
    EXPECT_NEAR(load.cube_x, 0.15, 0.005) << "the cube slid off its place";
    EXPECT_NEAR(load.effort, expected, 0.05 * cube_moment) << (reduced ? "reduced" : "maximal");
    EXPECT_TRUE(world.softBody("cube").isFinite());
  }
}

TEST(CoulombContact, AGearedPaddleUnderACubeIsHeldByItsMotorsFrictionWithoutCreeping) {
  // The paddle's hinge is turned by a geared motor (ratio 10) that applies no torque, and whose
  // Coulomb friction (0.03 N m, 0.3 N m at the joint) is more than the weights' moment (about
  // 0.13 N m): static friction holds it where it is, with just that moment. The cube's contacts
  // act after the step's positions are integrated, so the link starts each step with a kick they
  // gave it; friction resists how the motor turns, not that kick (it would push the paddle up).
  test_support::TempDir dir;
  dir.write("cube.obj", subdividedCubeObj(4));
  auto sim = test_support::simulate({dir.write("scene.yaml", cubeOnAPaddle(0.15, false))},
                                    test_support::noSoftBodySleep);
  auto& world = *sim->world;
  ASSERT_EQ(world.articulationCount(), 1u);
  ambf_like::TransmissionSpec gear;
  gear.joints = {"hinge"};
  gear.coupling = Eigen::MatrixXd::Constant(1, 1, 10.0);
  gear.rotor_inertia = Eigen::VectorXd::Constant(1, 2e-4);
  gear.viscous = Eigen::VectorXd::Zero(1);
  auto& motor = world.addTransmission(gear);
  motor.drive(Eigen::VectorXd::Zero(1), Eigen::VectorXd::Constant(1, 0.03));
  auto& hinge = world.joint("hinge");
  world.step(500);
  const double settled = hinge.position();
  const PaddleLoad load = meanLoad(world, 1000);
  const double expected = holdingMoment(load.cube_x);
  std::cout << "held by friction: joint " << load.effort << " N m, expected " << expected
            << "; moved " << hinge.position() - settled << " rad in 1 s\n";
  EXPECT_NEAR(hinge.position(), settled, 1e-6) << "the paddle crept";
  EXPECT_NEAR(load.effort, expected, 0.05 * kCubeMass * kGravity * load.cube_x);
  EXPECT_TRUE(world.softBody("cube").isFinite());
}

TEST(CoulombContact, ACubeOnAJointedPaddleStaysAwakeAndFollowsItDownHoweverSlowly) {
  // Soft-body sleep on (the default). The paddle tilts down at 5 mrad/s: under the cube its
  // surface sinks 0.75 mm/s and its fastest point moves slower than the 2 mm/s that wakes a
  // sleeper. A cube asleep on it would hang in the air, as a ring asleep in jaws that open slowly
  // would; a body touching a link (which a command can move at any step) must stay awake.
  for (const auto articulation :
       {ambf_like::Articulation::Reduced, ambf_like::Articulation::Maximal}) {
    test_support::TempDir dir;
    dir.write("cube.obj", subdividedCubeObj(4));
    auto sim = test_support::simulate(
        {dir.write("scene.yaml", cubeOnAPaddle(0.15))},
        [articulation](ambf_like::WorldSpec& world) { world.articulation = articulation; });
    auto& world = *sim->world;
    const auto& cube = world.softBody("cube");
    const auto& paddle = world.body("paddle");
    auto& hinge = world.joint("hinge");
    hinge.commandPosition(0.0);
    while (world.time() < 3.0) {  // long past the 0.5 s of rest a sleeper needs
      world.step();
      ASSERT_FALSE(cube.isAsleep()) << "asleep at " << world.time() << " s on a jointed paddle";
    }
    // Its contacts keep carrying its weight (what a grasp's force sensor reads).
    Eigen::Vector3d carried = Eigen::Vector3d::Zero();
    for (const auto& f : world.softContactForces()) carried += f.normal_force + f.friction_force;
    EXPECT_NEAR(carried.z(), kCubeMass * kGravity, 0.2 * kCubeMass * kGravity);
    // The cube's centre above the paddle's top face, in the paddle's frame.
    const auto height = [&] { return (paddle.pose().inverse() * cube.centerOfMass()).z() - 0.005; };
    const double resting = height();
    const double tilt = 0.02;  // rad: 3 mm lower under the cube, over 4 s
    const double start = world.time();
    while (world.time() < start + tilt / 0.005) {
      hinge.commandPosition(0.005 * (world.time() - start));  // positive: the free end down
      world.step();
    }
    world.step(500);
    ASSERT_NEAR(hinge.position(), tilt, 0.002);
    EXPECT_NEAR(height(), resting, 0.0005) << "the cube stayed behind as the paddle went down";
    EXPECT_TRUE(cube.isFinite());
  }
}

}  // namespace
