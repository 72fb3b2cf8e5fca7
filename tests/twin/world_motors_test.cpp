// The motors drive the simulated links through the cables and carry what the links carry: the
// weight the calibration fitted, and what the tool presses on, checked against the statics.

#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ambf_like/bullet_conversions.hpp"
#include "arm_contacts.hpp"
#include "bridge/raven_state.hpp"
#include "twin/calibration_profile.hpp"
#include "twin/gravity_compensation.hpp"
#include "twin/motor_controller.hpp"
#include "twin_fixtures.hpp"

namespace {

using raven::Arm;
using raven::ArmJoints;
using test_support::ArmChain;
using test_support::chainOf;
using test_support::contactLoads;
using test_support::frictionlessMotors;
using test_support::touching;
using test_support::withObstacle;

/// The torque the amplifiers apply (at the gearbox outputs): the logged DAC counts back in N m
/// (Tau itself may pass the DAC's clip).
ArmJoints appliedTorque(const twin::TwinPlatform& twin, Arm arm) {
  const auto state = twin.ravenState();
  const auto dac = twin::DacConversion::raven2(arm);
  ArmJoints applied;
  for (int i = 0; i < raven::kJointCount; ++i) {
    applied(i) = state->dac_val[static_cast<std::size_t>(bridge::ravenStateIndex(arm, i))] /
                 dac.counts_per_torque(i);
  }
  return applied;
}

ArmJoints loggedTau(const twin::TwinPlatform& twin, Arm arm) {
  const auto state = twin.ravenState();
  ArmJoints tau;
  for (int i = 0; i < raven::kJointCount; ++i) {
    tau(i) = state->tau[static_cast<std::size_t>(bridge::ravenStateIndex(arm, i))];
  }
  return tau;
}

/// The load the calibration says `arm`'s motors carry at `joints` (at the gearbox outputs): the
/// firmware's gravity estimate times one plus the fitted gravity error, and the fitted offset.
ArmJoints fittedLoad(const twin::TwinOptions& options, Arm arm, const ArmJoints& joints) {
  const auto& m = (*options.motors)[raven::slot(arm)];
  return (ArmJoints::Ones() + m.gravity_error)
             .cwiseProduct(twin::gravityCompensation(arm, joints, twin::DriveTrain::raven2())) +
         m.offset;
}

TEST(WorldMotors, HeldStillTheMotorsCarryTheFittedWeightAndOffset) {
  // Acceptance 1(c): frictionless, at rest, Tau is the load the calibration fitted (the
  // firmware's weight estimate, the fitted gravity error and offset), whatever the links of the
  // model weigh.
  twin::TwinOptions options = frictionlessMotors();
  auto shipped = twin::CalibrationProfile::shipped().mechanics;
  // The shipped profile fits no offsets: these are of the size and signs a fit with them finds.
  const ArmJoints offset =
      (ArmJoints() << -0.04, 0.02, -0.03, 0.005, -0.005, 0.004, -0.004).finished();
  for (std::size_t a = 0; a < 2; ++a) {
    (*options.motors)[a].gravity_error = shipped[a].gravity_error;
    (*options.motors)[a].offset = offset;
  }
  auto motors = test_support::readyTwin(options);
  motors->advance(3.0);  // the integrators take up what the compensation misses
  // Held, a motor hunts by an encoder count about its setpoint (kp x 1.6 mrad is about 0.015
  // N m on a shoulder): its torque balances the load on average, over a second.
  std::array<ArmJoints, 2> mean_tau{ArmJoints::Zero(), ArmJoints::Zero()};
  constexpr int kCycles = 1000;
  for (int k = 0; k < kCycles; ++k) {
    motors->advance(0.001);
    for (Arm arm : raven::kArms) {
      mean_tau[raven::slot(arm)] += loggedTau(*motors, arm) / kCycles;
    }
  }
  for (Arm arm : raven::kArms) {
    const ArmJoints expected = fittedLoad(options, arm, motors->measuredJs(arm).position);
    const ArmJoints tau = mean_tau[raven::slot(arm)];
    const double scale = expected.cwiseAbs().maxCoeff();
    for (int i = 0; i < raven::kJointCount; ++i) {
      EXPECT_NEAR(tau(i), expected(i), 0.05 * std::abs(expected(i)) + 1e-3 * scale)
          << raven::armName(arm) << " " << raven::kJointNames[static_cast<std::size_t>(i)];
    }
  }
}

/// `arm`'s mean Tau over a second (the motors hunt by an encoder count about their setpoints).
ArmJoints meanTauOverASecond(twin::TwinPlatform& twin, Arm arm) {
  ArmJoints mean = ArmJoints::Zero();
  constexpr int kCycles = 1000;
  for (int k = 0; k < kCycles; ++k) {
    twin.advance(0.001);
    mean += loggedTau(twin, arm) / kCycles;
  }
  return mean;
}

TEST(WorldMotors, AnElbowHeldAfterAMoveCarriesItsCablesFrictionThatWay) {
  // Frictionless motors but the left elbow's cable (0.05 N m beyond it, taken up over 3 motor
  // rad): moved up by 0.04 rad (4.9 motor rad, the cable stretched all the way) and held, the
  // link stands and the stretched cable pulls the motor back by its friction, so Tau is the
  // fitted load plus 0.05; moved down past twice the travel, the load minus 0.05. (What the
  // motor swings back as it settles, some 0.05 motor rad, unstretches the cable by its share
  // of the travel: under 2 %.)
  twin::TwinOptions options = frictionlessMotors();
  (*options.motors)[0].cable_friction(raven::kElbow) = 0.05;
  (*options.motors)[0].cable_travel(raven::kElbow) = 3.0;
  auto twin = test_support::readyTwin(options);
  const Arm arm = Arm::Left;
  for (const double step : {1e-4, -1e-4}) {
    ArmJoints move = ArmJoints::Zero();
    move(raven::kElbow) = step;
    for (int k = 0; k < (step > 0 ? 400 : 800); ++k) {
      twin->send(bridge::ServoJr{arm, move});
      twin->advance(0.001);
    }
    twin->advance(3.0);  // the integrators take up the load
    const ArmJoints tau = meanTauOverASecond(*twin, arm);
    const double expected =
        fittedLoad(options, arm, twin->measuredJs(arm).position)(raven::kElbow) +
        std::copysign(0.05, step);
    EXPECT_NEAR(tau(raven::kElbow), expected, 0.05 * 0.05) << (step > 0 ? "up" : "down");
  }
}

/// `arm` at rest against an obstacle, averaged over `cycles` 1 ms cycles: the joint loads its
/// motors apply through the cables, the fitted weight they carry, and J^T F of its contacts.
struct JointBalance {
  ArmJoints by_motors = ArmJoints::Zero();
  ArmJoints weight = ArmJoints::Zero();
  ArmJoints by_contact = ArmJoints::Zero();
  double drift = 0.0;      ///< the farthest any joint went over the cycles (rad or m)
  double arm_speed = 0.0;  ///< the fastest shoulder, elbow or insertion speed met
};

JointBalance balanceAtRest(twin::TwinPlatform& twin, const twin::TwinOptions& options, Arm arm,
                           int cycles) {
  const auto drive = twin::DriveTrain::raven2();
  const auto c = drive.coupling(arm);
  const ArmChain chain = chainOf(twin, arm);
  JointBalance balance;
  std::vector<double> start;
  for (const auto* joint : chain.joints) start.push_back(joint->position());
  for (int k = 0; k < cycles; ++k) {
    twin.advance(0.001);
    for (int j = 0; j <= raven::kInsertion; ++j) {
      balance.arm_speed = std::max(balance.arm_speed,
                                   std::abs(chain.joints[static_cast<std::size_t>(j)]->velocity()));
    }
    balance.by_motors +=
        c.transpose() * appliedTorque(twin, arm).cwiseQuotient(drive.gearbox) / cycles;
    balance.by_contact += contactLoads(twin, arm) / cycles;
  }
  for (std::size_t j = 0; j < start.size(); ++j) {
    balance.drift = std::max(balance.drift, std::abs(chain.joints[j]->position() - start[j]));
  }
  balance.weight =
      c.transpose() *
      fittedLoad(options, arm, twin.measuredJs(arm).position).cwiseQuotient(drive.gearbox);
  return balance;
}

/// At rest, each joint's motor load carries the fitted weight and pushes against the contacts:
/// within 5 % of what it should be, or 0.1 mN m (revolute) and 1 mN (the insertion).
void expectMotorsHoldTheContacts(const JointBalance& b) {
  const ArmJoints expected = b.weight - b.by_contact;
  for (int j = 0; j < raven::kJointCount; ++j) {
    const double floor = j == raven::kInsertion ? 1e-3 : 1e-4;
    EXPECT_NEAR(b.by_motors(j), expected(j), 0.05 * std::abs(expected(j)) + floor)
        << raven::kJointNames[static_cast<std::size_t>(j)] << ": contact " << b.by_contact(j)
        << ", weight " << b.weight(j);
  }
}

TEST(WorldMotors, AToolPressedOnASlabLoadsTheArmMotorsWithJTransposeF) {
  // Acceptance 1(b): the arm at rest with the tool pressed on a rigid slab; the motors' joint
  // loads less the weight they carry equal J^T F of the contact forces.
  const twin::TwinOptions motors_only = frictionlessMotors();
  const auto probe = test_support::readyTwin(motors_only);
  ambf_like::World& free_world = probe->world();
  // A 3 x 3 x 1 cm slab 3 cm ahead of the jaws at home, across the insertion's axis: on the
  // side away from the shaft, where withdrawing the insertion takes them in this model's frames.
  const auto& insertion = *chainOf(*probe, Arm::Left).joints[raven::kInsertion];
  const Eigen::Vector3d axis =
      free_world.body("/raven2/left/" + insertion.spec().parent).pose().linear() *
      insertion.spec().parent_axis.normalized();
  ambf_like::PrimitiveShape slab;
  slab.box_size = Eigen::Vector3d(0.03, 0.03, 0.01);
  ambf_like::Transform pose = ambf_like::Transform::Identity();
  pose.translation() = free_world.body("/raven2/left/jaw1_link").pose().translation() - 0.03 * axis;
  pose.linear() =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis).toRotationMatrix();
  const twin::TwinOptions options = withObstacle(motors_only, slab, pose, 0.5);
  auto pressed = test_support::readyTwin(options);
  ArmJoints in = ArmJoints::Zero();
  in(raven::kInsertion) = -2e-5;  // 2 cm/s toward the slab
  for (int k = 0; k < 8000 && !touching(*pressed, Arm::Left, raven::kInsertion); ++k) {
    pressed->send(bridge::ServoJr{Arm::Left, in});
    pressed->advance(0.001);
  }
  ASSERT_TRUE(touching(*pressed, Arm::Left, raven::kInsertion)) << "never reached the slab";
  for (int k = 0; k < 150; ++k) {  // 3 mm into it
    pressed->send(bridge::ServoJr{Arm::Left, in});
    pressed->advance(0.001);
  }
  pressed->advance(3.0);  // the arm stops at once; the tool's joints settle on their integrators
  // Pressed, the arm stands still while its motors hunt by an encoder count: motors and
  // contacts balance on average, over 0.3 s.
  const JointBalance balance = balanceAtRest(*pressed, options, Arm::Left, 300);
  EXPECT_LT(balance.drift, 5e-4);
  EXPECT_LT(balance.arm_speed, 1e-3) << "the arm itself stands still; its tool motors hunt";
  EXPECT_GT(balance.by_contact(raven::kInsertion), 10.0) << "pressed with less than 10 N";
  expectMotorsHoldTheContacts(balance);
}

TEST(WorldMotors, JawsClosedOnARigidBallSqueezeItWithTheJawMotorsTorque) {
  // Acceptance 1(a): the jaws commanded closed on a rigid ball held in the world. The jaw
  // motors' integrators wind up against it; at rest their torque, through the cables and the
  // jaws' lever arms, is the squeeze.
  const twin::TwinOptions motors_only = frictionlessMotors();
  ambf_like::PrimitiveShape ball;
  ball.type = ambf_like::PrimitiveType::Sphere;
  ball.radius = 0.007 * std::sin(0.25);  // met about 0.5 rad open, 7 mm from the jaws' pivot
  ambf_like::Transform away = ambf_like::Transform::Identity();
  away.translation() = Eigen::Vector3d(0, 0, -1);  // out of the jaws' way while they home
  const twin::TwinOptions options = withObstacle(motors_only, ball, away, 0.0);
  auto squeezing = test_support::readyTwin(options);
  ambf_like::World& world = squeezing->world();
  // Homed, the ball goes onto the jaws' bisector (each jaw reaches 11 mm along its x, its
  // gripping face across its y): moved as a test moves a fixture, between steps.
  const auto jaw1 = world.body("/raven2/left/jaw1_link").pose();
  const auto jaw2 = world.body("/raven2/left/jaw2_link").pose();
  ambf_like::Transform between = ambf_like::Transform::Identity();
  between.translation() =
      jaw1.translation() + 0.007 * (jaw1.linear().col(0) + jaw2.linear().col(0)).normalized();
  world.body("/test/obstacle").bullet().setWorldTransform(ambf_like::toBt(between));
  ArmJoints close = ArmJoints::Zero();
  close(raven::kJaw1) = close(raven::kJaw2) = -1e-3;  // 1 rad/s each
  const auto bothPress = [&] {
    return touching(*squeezing, Arm::Left, raven::kJaw1) &&
           touching(*squeezing, Arm::Left, raven::kJaw2);
  };
  for (int k = 0; k < 2000 && !bothPress(); ++k) {
    squeezing->send(bridge::ServoJr{Arm::Left, close});
    squeezing->advance(0.001);
  }
  ASSERT_TRUE(bothPress()) << "the jaws never closed on the ball";
  for (int k = 0; k < 100; ++k) {  // commanded 0.1 rad further closed
    squeezing->send(bridge::ServoJr{Arm::Left, close});
    squeezing->advance(0.001);
  }
  squeezing->advance(5.0);  // the rotors take up the squeeze step by step
  // Squeezed at the jaws' DAC clip (about 50 N a jaw), the ball wedges the jaws apart and
  // pushes the tool back; the arm's integrators wind up against it, so the arm creeps (about
  // 4 mrad/s, quasi-static) and, as on the robot, trips the overdrive e-stop some seconds later.
  const JointBalance balance = balanceAtRest(*squeezing, options, Arm::Left, 300);
  EXPECT_LT(balance.drift, 2e-3);
  EXPECT_GT(balance.by_contact(raven::kJaw1), 0.1) << "squeezed with less than 0.1 N m";
  EXPECT_GT(balance.by_contact(raven::kJaw2), 0.1) << "squeezed with less than 0.1 N m";
  expectMotorsHoldTheContacts(balance);
}

/// One arm's jaw motors (jaw1, jaw2) as the control software logs them: Tau (N m at the gearbox
/// outputs) and the motor error mpos_d - mpos (rad).
struct JawMotors {
  Eigen::Vector2d tau, error;
};

JawMotors jawMotors(const twin::TwinPlatform& twin, Arm arm) {
  const auto state = twin.ravenState();
  JawMotors jaws;
  for (int j = 0; j < 2; ++j) {
    const auto at = static_cast<std::size_t>(bridge::ravenStateIndex(arm, raven::kJaw1 + j));
    jaws.tau(j) = state->tau[at];
    jaws.error(j) = (state->mpos_d[at] - state->mpos[at]) * M_PI / 180.0;
  }
  return jaws;
}

/// A ready twin whose left jaws a pad has closed at 1 rad/s each (servo_jr at 1 kHz) until each
/// setpoint is 0.1 rad past the faces' meeting, a grasp closed hard on nothing, then 0.5 s on.
std::unique_ptr<twin::TwinPlatform> jawsClosedHardOnNothing(const twin::TwinOptions& options) {
  auto twin = test_support::readyTwin(options);
  ArmJoints close = ArmJoints::Zero();
  close(raven::kJaw1) = close(raven::kJaw2) = -1e-3;
  while (twin->setpointJs(Arm::Left).position(raven::kJaw1) > -0.1) {
    twin->send(bridge::ServoJr{Arm::Left, close});
    twin->advance(0.001);
  }
  twin->advance(0.5);
  return twin;
}

TEST(WorldMotors, JawsWithFittedFacesStopWhereTheseMeet) {
  // The calibration's faces (0.010 + 0.005 rad) move the World's stop on the pair by their sum,
  // as they move the motors-alone model's: jaws closed hard on nothing rest there.
  twin::TwinOptions options = frictionlessMotors();
  (*options.motors)[0].face(raven::kJaw1) = 0.010;
  (*options.motors)[0].face(raven::kJaw2) = 0.005;
  auto twin = jawsClosedHardOnNothing(options);
  const Arm arm = Arm::Left;
  const ArmJoints q = twin->measuredJs(arm).position;
  EXPECT_NEAR(q(raven::kJaw1) + q(raven::kJaw2), 0.015,
              4.0 * test_support::countInJoint(twin::DriveTrain::raven2(), raven::kJaw1));
  ASSERT_NE(twin->arms().jawStop(arm), nullptr);
  EXPECT_NEAR(twin->arms().jawStop(arm)->gap(), 0.0, 1e-3) << "resting on the stop";
}

TEST(WorldMotors, JawsOnFacesThatGiveArePressedPastThemByTheLoadTimesTheCompliance) {
  // The calibration's face compliances (0.1 rad per N m each, the pair 0.2) make the World's
  // stop a spring: jaws closed hard on nothing go past where the faces meet by 0.2 rad per N m
  // each joint is pressed with, and that is what the motors push through the cables.
  twin::TwinOptions options = frictionlessMotors();
  (*options.motors)[0].face_compliance(raven::kJaw1) = 0.1;
  (*options.motors)[0].face_compliance(raven::kJaw2) = 0.1;
  auto twin = jawsClosedHardOnNothing(options);
  const Arm arm = Arm::Left;
  const ambf_like::CoupledStop* stop = twin->arms().jawStop(arm);
  ASSERT_NE(stop, nullptr);
  const auto drive = twin::DriveTrain::raven2();
  const ArmJoints by_motors =
      drive.coupling(arm).transpose() * appliedTorque(*twin, arm).cwiseQuotient(drive.gearbox);
  const ArmJoints q = twin->measuredJs(arm).position;
  std::printf("faces that give: past by %.4f rad, stop %.4f N m, motors %.4f/%.4f N m\n",
              -(q(raven::kJaw1) + q(raven::kJaw2)), stop->force(), -by_motors(raven::kJaw1),
              -by_motors(raven::kJaw2));
  EXPECT_GT(stop->force(), 0.05) << "pressed hard (N m)";
  EXPECT_NEAR(stop->gap(), -0.2 * stop->force(), 0.02 * 0.2 * stop->force());
  EXPECT_NEAR(-(q(raven::kJaw1) + q(raven::kJaw2)), 0.2 * stop->force(),
              0.05 * 0.2 * stop->force() + 4.0 * test_support::countInJoint(drive, raven::kJaw1));
  for (int motor : {raven::kJaw1, raven::kJaw2}) {
    EXPECT_NEAR(-by_motors(motor), stop->force(), 0.05 * stop->force()) << "motor " << motor;
  }
}

TEST(WorldMotors, JawsClosedOnEachOtherStopThereAndWindTheirIntegratorsUp) {
  // Acceptance 1(d): both jaws commanded 0.1 rad past the faces' meeting (opening -0.2, a grasp
  // closed hard on nothing, as the robot's recordings hold it for seconds). The faces stop the
  // jaws at opening 0; the motors' error stays, and their integrators wind up by KI times it
  // every second (raven2-actuation.md §3: no clamp), the stop bearing what the motors push.
  const twin::TwinOptions options = frictionlessMotors();
  auto twin = jawsClosedHardOnNothing(options);
  const Arm arm = Arm::Left;
  const ambf_like::CoupledStop* stop = twin->arms().jawStop(arm);
  ASSERT_NE(stop, nullptr);
  const twin::MotorGains gains = twin::MotorGains::raven2(arm);
  const auto drive = twin::DriveTrain::raven2();
  const JawMotors before = jawMotors(*twin, arm);
  Eigen::Vector2d error_integral = Eigen::Vector2d::Zero();
  double widest_overlap = 0.0, stop_force = 0.0;
  ArmJoints by_motors = ArmJoints::Zero();
  constexpr int kCycles = 500;
  for (int k = 0; k < kCycles; ++k) {
    twin->advance(0.001);
    error_integral += jawMotors(*twin, arm).error * 0.001;
    const ArmJoints q = twin->measuredJs(arm).position;
    widest_overlap = std::max(widest_overlap, -(q(raven::kJaw1) + q(raven::kJaw2)));
    stop_force += stop->force() / kCycles;
    by_motors += drive.coupling(arm).transpose() *
                 appliedTorque(*twin, arm).cwiseQuotient(drive.gearbox) / kCycles;
  }
  const JawMotors after = jawMotors(*twin, arm);
  std::printf(
      "jaws on each other: overlap <= %.2g rad, stop %.4f N m, motors %.4f/%.4f N m, "
      "Tau %+.4f/%+.4f -> %+.4f/%+.4f N m in 0.5 s\n",
      widest_overlap, stop_force, -by_motors(raven::kJaw1), -by_motors(raven::kJaw2), before.tau(0),
      before.tau(1), after.tau(0), after.tau(1));
  EXPECT_LT(widest_overlap, 2e-3) << "the jaws passed through each other (rad)";
  for (int j = 0; j < 2; ++j) {
    const int motor = raven::kJaw1 + j;
    // The control law, cycle by cycle: KP on the error, KI on its integral (no D: KD is 0).
    const double law =
        gains.kp(motor) * (after.error(j) - before.error(j)) + gains.ki(motor) * error_integral(j);
    EXPECT_NEAR(after.tau(j) - before.tau(j), law, 0.05 * std::abs(law)) << "jaw " << j + 1;
    // Held at the stop, each motor stays about 0.1 rad of jaw (0.9 motor rad) from its setpoint:
    // its integrator winds up by 0.02 N m or more in the half second.
    EXPECT_GT(std::abs(gains.ki(motor) * error_integral(j)), 0.02) << "jaw " << j + 1;
    // The faces bear what the motors push, through the cables (frictionless motors).
    EXPECT_NEAR(-by_motors(motor), stop_force, 0.05 * stop_force) << "jaw " << j + 1;
  }
}

}  // namespace
