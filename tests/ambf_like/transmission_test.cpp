// Motors behind joints (World::addTransmission): a rotor's inertia and friction reflected
// through the gear ratio, checked against the textbook answers for one geared link.

#include <gtest/gtest.h>

#include <cmath>

#include "test_files.hpp"

namespace {

constexpr double kMass = 0.5, kLength = 0.2, kWidth = 0.02;
constexpr double kRatio = 10.0;  // motor rad per joint rad
constexpr double kRotor = 2e-4;  // kg m^2 on the motor
constexpr double kStep = 0.001;

/// A box link along x hinged at one end about the vertical z (gravity does not turn it), or
/// about y (gravity does), in reduced coordinates, or maximal ones.
std::unique_ptr<test_support::Simulation> gearedLink(const test_support::TempDir& dir,
                                                     ambf_like::Articulation articulation,
                                                     const std::string& axis = "{x: 0, y: 0, z: 1}",
                                                     const std::string& kind = "type: continuous") {
  const auto model = dir.write(
      "link.yaml",
      "bodies: [BODY anchor, BODY link]\njoints: [JOINT hinge]\nignore inter-collision: true\n"
      "BODY anchor: {mass: 0, collision shape: BOX, collision geometry: {x: 0.02, y: 0.02, z: "
      "0.02}}\n"
      "BODY link:\n  mass: " +
          std::to_string(kMass) +
          "\n  collision shape: BOX\n  collision geometry: {x: " + std::to_string(kLength) +
          ", y: " + std::to_string(kWidth) + ", z: " + std::to_string(kWidth) +
          "}\n  damping: {linear: 0, angular: 0}\n"
          "  location: {position: {x: 0.1, y: 0, z: 0}}\n"
          "JOINT hinge:\n  parent: BODY anchor\n  child: BODY link\n  parent pivot: {x: 0, y: 0, "
          "z: 0}\n  child pivot: {x: -0.1, y: 0, z: 0}\n  parent axis: " +
          axis + "\n  child axis: " + axis + "\n  " + kind + "\n");
  return test_support::simulate(
      {model}, [articulation](ambf_like::WorldSpec& world) { world.articulation = articulation; });
}

/// The link's moment of inertia about its hinge: a box's about its centre, moved by m (L/2)^2.
double linkInertiaAboutHinge() {
  return kMass * (kLength * kLength + kWidth * kWidth) / 12.0 +
         kMass * (kLength / 2.0) * (kLength / 2.0);
}

ambf_like::TransmissionSpec gear(double viscous = 0.0) {
  ambf_like::TransmissionSpec spec;
  spec.joints = {"hinge"};
  spec.coupling = Eigen::MatrixXd::Constant(1, 1, kRatio);
  spec.rotor_inertia = Eigen::VectorXd::Constant(1, kRotor);
  spec.viscous = Eigen::VectorXd::Constant(1, viscous);
  return spec;
}

Eigen::VectorXd one(double value) {
  return Eigen::VectorXd::Constant(1, value);
}

TEST(Transmission, TheLinkFeelsItsInertiaOverTheRatioSquaredAtTheMotor) {
  test_support::TempDir dir;
  auto sim = gearedLink(dir, ambf_like::Articulation::Reduced);
  auto& transmission = sim->world->addTransmission(gear());
  const double expected = linkInertiaAboutHinge() / (kRatio * kRatio);
  EXPECT_NEAR(transmission.linkInertia()(0, 0), expected, 1e-9 * expected);
}

TEST(Transmission, TheLinksWeighOnTheirJointsAsTheirCentresOfMassSay) {
  // Horizontal along x, hinged about y: holding it takes -m g L/2 about y (gravity along -z).
  test_support::TempDir dir;
  auto sim = gearedLink(dir, ambf_like::Articulation::Reduced, "{x: 0, y: 1, z: 0}");
  auto& transmission = sim->world->addTransmission(gear());
  EXPECT_NEAR(transmission.linkWeight()(0), -kMass * 9.81 * kLength / 2.0, 1e-9);
}

TEST(Transmission, AMotorTorqueAcceleratesLinkAndRotorTogether) {
  // Joint: (I + r^2 J) qdd = r tau, so after t from rest qd = r tau t / (I + r^2 J).
  test_support::TempDir dir;
  auto sim = gearedLink(dir, ambf_like::Articulation::Reduced);
  auto& transmission = sim->world->addTransmission(gear());
  const double torque = 0.01;
  transmission.drive(one(torque), one(0.0));
  sim->world->step(200);
  const double reflected = linkInertiaAboutHinge() + kRatio * kRatio * kRotor;
  const double expected = kRatio * torque * 0.2 / reflected;
  auto& hinge = sim->world->joint("hinge");
  EXPECT_NEAR(hinge.velocity(), expected, 1e-3 * expected);
  // The joint reads the torque the motor puts through the gear (r tau), not what its rotor took.
  EXPECT_NEAR(hinge.effort(), kRatio * torque, 1e-9);
  // Without the rotor (a bare joint torque) the link alone would turn 4x as fast.
  EXPECT_LT(hinge.velocity(), kRatio * torque * 0.2 / linkInertiaAboutHinge() / 3.0);
}

TEST(Transmission, CoulombFrictionHoldsBelowItsTorqueAndTakesItsShareAbove) {
  test_support::TempDir dir;
  auto sim = gearedLink(dir, ambf_like::Articulation::Reduced);
  auto& transmission = sim->world->addTransmission(gear());
  auto& hinge = sim->world->joint("hinge");
  const double friction = 0.02;
  transmission.drive(one(0.9 * friction), one(friction));
  sim->world->step(200);
  EXPECT_NEAR(hinge.velocity(), 0.0, 1e-12);
  EXPECT_NEAR(hinge.position(), 0.0, 1e-12);
  transmission.drive(one(2.0 * friction), one(friction));
  sim->world->step(200);
  const double reflected = linkInertiaAboutHinge() + kRatio * kRatio * kRotor;
  const double expected = kRatio * friction * 0.2 / reflected;
  EXPECT_NEAR(hinge.velocity(), expected, 1e-3 * expected);
}

TEST(Transmission, ViscousFrictionLetsTheMotorReachTorqueOverDamping) {
  // Steady state: tau = b w_motor, so the joint turns at tau / (b r).
  test_support::TempDir dir;
  auto sim = gearedLink(dir, ambf_like::Articulation::Reduced);
  const double viscous = 2e-3;
  auto& transmission = sim->world->addTransmission(gear(viscous));
  const double torque = 0.01;
  transmission.drive(one(torque), one(0.0));
  sim->world->step(3000);  // 3 s: the time constant (I + r^2 J) / (r^2 b) is 0.12 s
  EXPECT_NEAR(sim->world->joint("hinge").velocity(), torque / (viscous * kRatio), 1e-6);
}

TEST(Transmission, AHardStopStopsLinkAndRotorTogether) {
  // A stop takes the momentum of all that turns: (I + r^2 J) w in the step it is met, and,
  // pushed on, the motor's whole r tau from then on. Bullet's own rows would stop the link's I
  // alone and leave the rotor's r^2 J w (3x the link's here) to run on into it.
  test_support::TempDir dir;
  const double stop = 0.5;
  auto sim =
      gearedLink(dir, ambf_like::Articulation::Reduced, "{x: 0, y: 0, z: 1}",
                 "type: revolute\n  joint limits: {low: -0.5, high: " + std::to_string(stop) + "}");
  auto& transmission = sim->world->addTransmission(gear());
  auto& hinge = sim->world->joint("hinge");
  const double speed = 2.0;
  hinge.place(stop, speed);  // at the stop, turning into it
  sim->world->step();
  const double reflected = linkInertiaAboutHinge() + kRatio * kRatio * kRotor;
  EXPECT_NEAR(hinge.velocity(), 0.0, 1e-6);
  // The stop's impulse is what effort() reads against the motor's (none yet), times the step.
  EXPECT_NEAR(-hinge.effort() * kStep, reflected * speed, 0.01 * reflected * speed);
  const double torque = 0.01;
  transmission.drive(one(torque), one(0.0));
  for (int k = 0; k < 3; ++k) {
    sim->world->step();
    EXPECT_NEAR(hinge.effort(), 0.0, 1e-3 * kRatio * torque) << "step " << k;
    EXPECT_LE(hinge.position(), stop + 1e-4);
  }
}

TEST(Transmission, APlacedJointStartsThereAtItsSpeed) {
  test_support::TempDir dir;
  auto sim = gearedLink(dir, ambf_like::Articulation::Reduced);
  auto& hinge = sim->world->joint("hinge");
  hinge.place(0.7, 1.5);
  EXPECT_DOUBLE_EQ(hinge.position(), 0.7);
  EXPECT_DOUBLE_EQ(hinge.velocity(), 1.5);
  sim->world->step();
  EXPECT_NEAR(hinge.position(), 0.7 + 1.5 * kStep, 1e-9);
  EXPECT_NEAR(sim->world->body("link").pose().translation().y(), 0.1 * std::sin(0.7015), 1e-6);
}

TEST(Transmission, IsRefusedWithTheReasonWhereItCannotBeSolved) {
  test_support::TempDir dir;
  auto maximal = gearedLink(dir, ambf_like::Articulation::Maximal);
  EXPECT_THROW(
      {
        try {
          maximal->world->addTransmission(gear());
        } catch (const std::invalid_argument& e) {
          EXPECT_NE(std::string(e.what()).find("'hinge'"), std::string::npos) << e.what();
          throw;
        }
      },
      std::invalid_argument);
  EXPECT_THROW(maximal->world->joint("hinge").place(0.1, 0.0), std::invalid_argument);
  auto reduced = gearedLink(dir, ambf_like::Articulation::Reduced);
  auto bad = gear();
  bad.rotor_inertia(0) = 0.0;
  EXPECT_THROW(reduced->world->addTransmission(bad), std::invalid_argument);
  bad = gear();
  bad.coupling = Eigen::MatrixXd::Constant(2, 1, kRatio);
  EXPECT_THROW(reduced->world->addTransmission(bad), std::invalid_argument);
  auto& transmission = reduced->world->addTransmission(gear());
  EXPECT_THROW(reduced->world->addTransmission(gear()), std::invalid_argument);
  EXPECT_THROW(transmission.drive(one(NAN), one(0.0)), std::invalid_argument);
  EXPECT_THROW(transmission.drive(one(0.0), one(-1.0)), std::invalid_argument);
}

}  // namespace
