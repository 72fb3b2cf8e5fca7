// The twin over ROS 1 and the client that drives a Raven-II over its topics, against a real
// rosmaster and the raven_twin_node program: state machine, servo_jr, raven_state, the arm swap,
// identical trajectories in-process and over ROS, bad messages, losing either side.

#include <crtk_msgs/StringStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <gtest/gtest.h>
#include <raven_2/raven_state.h>
#include <raven_twin/GraspForces.h>
#include <sensor_msgs/JointState.h>

#include <cmath>
#include <limits>
#include <optional>

#include "bridge/ros/low_latency.hpp"
#include "bridge/ros/raven_ros_client.hpp"
#include "bridge/ros/ros_conversions.hpp"
#include "ros_peers.hpp"
#include "twin/calibration_profile.hpp"
#include "twin/twin_platform.hpp"
#include "twin_fixtures.hpp"

namespace {

using bridge::Arm;
using bridge::ArmJoints;
using bridge::OperatingState;
using bridge::RavenPlatform;
using bridge::StateCommand;
using bridge::ros1::CommandTopic;
using bridge::ros1::RavenRosClient;

using ros_test::jointCommand;
using ros_test::Rig;
using test_support::advanceUntil;
using test_support::makeReady;

ArmJoints increment(int k) {
  const double s = std::sin(0.01 * k);
  return (ArmJoints() << 1.5e-4 * s, -1e-4 * s, 2e-5 * s, 4e-4 * s, 3e-4 * s, 2e-4 * s, -1e-4 * s)
      .finished();
}

double maxAbs(const ArmJoints& q) {
  return q.cwiseAbs().maxCoeff();
}

/// The node on ideal servos: these tests are about the ROS edge, and measure positions exactly;
/// the motor-level actuation over ROS is TheMotorLevelActuationGivesTheSameTrajectory's.
const std::vector<std::string> kIdealServos{"--actuation", "ideal"};

TEST(TwinOverRos, EnableHomeAndAServoJrStreamIsFollowed) {
  Rig rig(kIdealServos);
  auto& robot = rig.client;
  EXPECT_EQ(robot.operatingStatus().state, OperatingState::Disabled);
  makeReady(robot);
  const ArmJoints start = robot.setpointJs(Arm::Left).position;
  ArmJoints sum = ArmJoints::Zero();
  for (int k = 0; k < 500; ++k) {
    for (Arm arm : raven::kArms) ASSERT_TRUE(robot.send(bridge::ServoJr{arm, increment(k)}));
    sum += increment(k);
    robot.advance(0.002);
    for (Arm arm : raven::kArms) {
      ASSERT_LT(maxAbs(robot.measuredJs(arm).position - robot.setpointJs(arm).position), 3e-4);
    }
  }
  EXPECT_LT(maxAbs(robot.setpointJs(Arm::Left).position - start - sum), 1e-12);
  robot.advance(0.05);
  EXPECT_LT(maxAbs(robot.measuredJs(Arm::Left).position - start - sum), 1e-9);  // at rest
}

TEST(TwinOverRos, EveryTransitionAmongDisabledEnabledAndPausedValidOrNot) {
  Rig rig(kIdealServos);
  ros_test::RawPeer peer(rig.node.ns());
  auto& robot = rig.client;
  using S = OperatingState;
  using C = StateCommand;
  // From each state, every command: over ROS, then compared with the state machine itself.
  for (S from : {S::Disabled, S::Enabled, S::Paused}) {
    for (C command : {C::Enable, C::Disable, C::Pause, C::Resume, C::Home, C::Unhome}) {
      ASSERT_TRUE(robot.send(C::Disable));
      if (from != S::Disabled) {
        ASSERT_TRUE(robot.send(C::Enable));
      }
      if (from == S::Paused) {
        ASSERT_TRUE(robot.send(C::Pause));
      }
      robot.advance(0.001);
      ASSERT_EQ(robot.operatingStatus().state, from);
      bridge::OperatingStateMachine expected;
      expected.apply(C::Enable);
      if (from == S::Disabled) expected.apply(C::Disable);
      if (from == S::Paused) expected.apply(C::Pause);
      const bool valid = expected.apply(command).accepted;

      crtk_msgs::StringStamped message;
      message.string = std::string(bridge::wireName(command));
      peer.send(CommandTopic::StateCommand, message);
      const auto refusals = peer.step(1, valid ? 0 : 1);
      robot.advance(0.001);
      SCOPED_TRACE(std::string(bridge::wireName(from)) + " + " + message.string);
      EXPECT_EQ(robot.operatingStatus().state, expected.status().state);
      EXPECT_EQ(robot.operatingStatus().is_busy, expected.status().is_busy);
      if (!valid) {
        ASSERT_EQ(refusals.size(), 1u);
        EXPECT_NE(refusals[0].find("not valid in state"), std::string::npos) << refusals[0];
      }
    }
  }
  // Homing: busy until the arms arrive, then homed; unhome forgets it; per-arm topics work too.
  ASSERT_TRUE(robot.send(C::Disable));
  ASSERT_TRUE(robot.send(C::Enable));
  robot.advance(0.001);
  crtk_msgs::StringStamped home;
  home.string = "home";
  peer.send(CommandTopic::Arm2StateCommand, home);
  peer.step(1);
  robot.advance(0.001);
  EXPECT_TRUE(robot.operatingStatus().is_busy);
  EXPECT_FALSE(robot.operatingStatus().is_homed);
  for (int i = 0; i < 500 && robot.operatingStatus().is_busy; ++i) robot.advance(0.01);
  EXPECT_TRUE(robot.operatingStatus().ready());
  ASSERT_TRUE(robot.send(C::Unhome));
  robot.advance(0.001);
  EXPECT_FALSE(robot.operatingStatus().is_homed);
}

TEST(TwinOverRos, RavenStateIsPublishedEveryCycleInDegreesAndMicrons) {
  Rig rig(kIdealServos);
  auto& robot = rig.client;
  makeReady(robot);
  robot.advance(0.05);
  const auto state = robot.ravenState();
  ASSERT_TRUE(state);
  EXPECT_EQ(state->runlevel, 3);
  EXPECT_EQ(state->sublevel, 1);
  for (int base : {0, 8}) {
    EXPECT_NEAR(state->jpos[base + 0], 30.0, 0.01);
    EXPECT_NEAR(state->jpos[base + 1], 90.0, 0.01);
    EXPECT_NEAR(state->jpos[base + 2], 22.918, 0.001) << "0.4 m insertion, in 'degrees'";
    EXPECT_EQ(state->jpos[base + 3], 0.0f);
    EXPECT_NEAR(state->jpos[base + 6] + state->jpos[base + 7], 90.0, 0.01);
  }
  for (Arm arm : raven::kArms) {
    const auto a = raven::slot(arm);
    const auto measured = robot.measuredJs(arm).position;
    for (int i = 0; i < raven::kJointCount; ++i) {
      EXPECT_NEAR(state->jpos[static_cast<std::size_t>(bridge::ravenStateIndex(arm, i))],
                  measured(i) * 180.0 / M_PI, 1e-3);
    }
    const auto tool = robot.measuredCp(arm).pose.translation();
    for (std::size_t r = 0; r < 3; ++r) {
      EXPECT_NEAR(state->pos[a * 3 + r], tool(static_cast<int>(r)) * 1e6, 1.0);
    }
  }
  // One raven_state per 1 ms cycle: 200 cycles, 200 messages, stamped 1 ms apart.
  ros::NodeHandle node(rig.node.ns());
  ros::CallbackQueue queue;
  node.setCallbackQueue(&queue);
  std::vector<ros::Time> stamps;
  auto subscriber = node.subscribe<raven_2::raven_state>(
      "ravenstate", 1000,
      [&](const raven_2::raven_state::ConstPtr& m) { stamps.push_back(m->hdr.stamp); }, {},
      bridge::ros1::lowLatency());
  for (int i = 0; i < 1000 && subscriber.getNumPublishers() == 0; ++i) {
    queue.callAvailable(ros::WallDuration(0.01));
  }
  robot.advance(0.001);
  queue.callAvailable(ros::WallDuration(0.1));
  stamps.clear();
  robot.advance(0.2);
  for (int i = 0; i < 500 && stamps.size() < 200; ++i) queue.callAvailable(ros::WallDuration(0.01));
  ASSERT_EQ(stamps.size(), 200u);
  for (std::size_t i = 1; i < stamps.size(); ++i) {
    EXPECT_NEAR((stamps[i] - stamps[i - 1]).toSec(), 0.001, 1e-9);
  }
}

/// The joints on arm1/measured_js after one lock-step step.
sensor_msgs::JointState arm1MeasuredJs(const std::string& ns, RavenRosClient& robot) {
  ros::NodeHandle node(ns);
  ros::CallbackQueue queue;
  node.setCallbackQueue(&queue);
  sensor_msgs::JointState last;
  auto subscriber = node.subscribe<sensor_msgs::JointState>(
      "arm1/measured_js", 10, [&](const sensor_msgs::JointState::ConstPtr& m) { last = *m; }, {},
      bridge::ros1::lowLatency());
  for (int i = 0; i < 1000 && subscriber.getNumPublishers() == 0; ++i) {
    queue.callAvailable(ros::WallDuration(0.01));
  }
  robot.advance(0.001);
  for (int i = 0; i < 500 && last.name.empty(); ++i) queue.callAvailable(ros::WallDuration(0.01));
  return last;
}

TEST(TwinOverRos, ArmsAreSwappedOnMeasuredJsUnlessSwitchedOff) {
  for (bool swap : {true, false}) {
    bridge::ros1::RosClientOptions options;
    options.arm_swap = swap;
    Rig rig(swap ? kIdealServos : std::vector<std::string>{"--actuation", "ideal", "--no-arm-swap"},
            true, options);
    auto& robot = rig.client;
    makeReady(robot);
    // Tell the arms apart: move the left (gold) shoulder only.
    for (int k = 0; k < 10; ++k) {
      ASSERT_TRUE(robot.send(bridge::ServoJr{Arm::Left, ArmJoints::Unit(raven::kShoulder) * 0.01}));
      robot.advance(0.01);
    }
    const auto raw = arm1MeasuredJs(rig.node.ns(), robot);
    ASSERT_EQ(raw.name.size(), 7u);
    const Arm on_arm1 = swap ? Arm::Right : Arm::Left;
    EXPECT_EQ(raw.name[0], swap ? "green_shoulder" : "gold_shoulder");
    EXPECT_NEAR(raw.position[0], robot.measuredJs(on_arm1).position(0), 1e-12);
    // The client undoes the swap: its left arm is the one that moved.
    EXPECT_GT(robot.measuredJs(Arm::Left).position(0) - robot.measuredJs(Arm::Right).position(0),
              0.09);
  }
}

/// The same commands, on any platform; returns both arms' measured joints after every step.
std::vector<std::array<ArmJoints, 2>> runScript(RavenPlatform& robot) {
  std::vector<std::array<ArmJoints, 2>> trace;
  auto record = [&] {
    trace.push_back({robot.measuredJs(Arm::Left).position, robot.measuredJs(Arm::Right).position});
  };
  robot.send(StateCommand::Enable);
  robot.send(StateCommand::Home);
  for (int i = 0; i < 1000 && (i == 0 || robot.operatingStatus().is_busy); ++i) {
    robot.advance(0.01);
    record();
  }
  for (int k = 0; k < 300; ++k) {
    robot.send(bridge::ServoJr{Arm::Left, increment(k)});
    robot.send(bridge::ServoJr{Arm::Right, -increment(k)});
    if (k % 10 == 0) robot.send(bridge::ServoJawJr{Arm::Left, 0.002});
    robot.advance(0.002);
    record();
  }
  ArmJoints goal = robot.setpointJs(Arm::Right).position;
  goal(raven::kElbow) += 0.05;
  goal(raven::kWrist) -= 0.2;
  robot.send(bridge::MoveJp{Arm::Right, goal});
  for (int i = 0; i < 100; ++i) {
    robot.advance(0.005);
    record();
  }
  Eigen::Isometry3d nudge = Eigen::Isometry3d::Identity();
  nudge.translation() = Eigen::Vector3d(0.002, -0.001, 0.001);
  robot.send(bridge::ServoCr{Arm::Left, nudge});
  for (int i = 0; i < 50; ++i) {
    robot.advance(0.002);
    record();
  }
  return trace;
}

void expectSameTrajectory(const std::vector<std::string>& node_args,
                          const twin::TwinOptions& in_process_options) {
  twin::TwinPlatform in_process(in_process_options);
  const auto expected = runScript(in_process);
  Rig rig(node_args);
  const auto over_ros = runScript(rig.client);
  ASSERT_EQ(over_ros.size(), expected.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    for (std::size_t a = 0; a < 2; ++a) {
      worst = std::max(worst, maxAbs(over_ros[i][a] - expected[i][a]));
    }
  }
  EXPECT_LT(worst, 1e-6);
  testing::Test::RecordProperty("worst_joint_difference", std::to_string(worst));
  // The script did move the arms.
  EXPECT_GT(maxAbs(expected.back()[0] - expected.front()[0]), 0.01);
}

TEST(TwinOverRos, SameCommandsGiveTheSameTrajectoryInProcessAndOverRos) {
  expectSameTrajectory(kIdealServos, twin::TwinOptions{});
}

TEST(TwinOverRos, TheMotorLevelActuationGivesTheSameTrajectoryInProcessAndOverRos) {
  twin::TwinOptions options;  // the node's default: the shipped calibration's motors
  twin::CalibrationProfile::shipped().applyTo(options);
  expectSameTrajectory({}, options);
}

/// A malformed or unsafe message a raw peer sends, and the words its refusal must hold.
struct BadMessage {
  const char* what;
  std::function<void()> send;
  const char* reason;
};

/// One of each kind of bad message to arm 1, the arm standing at `start`.
std::vector<BadMessage> badMessages(ros_test::RawPeer& peer,
                                    const bridge::ros1::RavenRosClient& robot,
                                    const ArmJoints& start) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> home(start.data(), start.data() + 7);
  auto with = [home](int i, double value) {
    auto q = home;
    q[static_cast<std::size_t>(i)] = value;
    return q;
  };
  return {
      {"5 values",
       [=, &peer] {
         peer.send(CommandTopic::Arm1ServoJr, jointCommand({0, 0, 0, 0, 0}));
       },
       "position has 5 values"},
      {"NaN",
       [=, &peer] {
         peer.send(CommandTopic::Arm1ServoJr, jointCommand({0, nan, 0, 0, 0, 0, 0}));
       },
       "position[1]"},
      {"inf", [=, &peer] { peer.send(CommandTopic::Arm1ServoJp, jointCommand(with(4, inf))); },
       "position[4]"},
      {"15 values, extras not 0",
       [=, &peer] {
         std::vector<double> q(15, 0.0);
         q[9] = 1.0;
         peer.send(CommandTopic::Arm1ServoJr, jointCommand(q));
       },
       "must be 0"},
      {"a jump beyond the clamps",
       [=, &peer] { peer.send(CommandTopic::Arm1ServoJp, jointCommand(with(0, home[0] + 0.2))); },
       "would jump"},
      {"servo_jr piling up beyond the clamps",
       [=, &peer] {
         peer.send(CommandTopic::Arm1ServoJr, jointCommand({0, 0, 0.002, 0, 0, 0, 0}));
       },
       "'insertion' would jump"},
      {"empty grasp", [=, &peer] { peer.send(CommandTopic::Grasp1ServoJp, jointCommand({})); },
       "position is empty"},
      {"NaN grasp", [=, &peer] { peer.send(CommandTopic::Grasp1ServoJr, jointCommand({nan})); },
       "position[0]"},
      {"non-unit quaternion",
       [=, &peer] {
         geometry_msgs::TransformStamped m;
         m.transform.rotation.w = 2.0;
         peer.send(CommandTopic::Arm1ServoCp, m);
       },
       "quaternion has length"},
      {"a tool jump",
       [=, &peer, &robot] {
         auto pose = robot.measuredCp(Arm::Left).pose;
         pose.translation().z() += 0.05;
         peer.send(CommandTopic::Arm1ServoCp,
                   bridge::ros1::toTransformStamped(pose, ros::Time::now(), "", ""));
       },
       "tool would jump"},
      {"unknown state command",
       [=, &peer] {
         crtk_msgs::StringStamped m;
         m.string = "fly";
         peer.send(CommandTopic::StateCommand, m);
       },
       "unknown state command 'fly'"},
  };
}

TEST(TwinOverRos, BadMessagesAreRefusedWithAReasonAndMoveNothing) {
  Rig rig(kIdealServos);
  ros_test::RawPeer peer(rig.node.ns());
  auto& robot = rig.client;
  makeReady(robot);
  robot.advance(0.2);  // "ready" is within a tolerance of home: let the arm come to rest
  const ArmJoints start = robot.measuredJs(Arm::Left).position;
  for (const auto& c : badMessages(peer, robot, start)) {
    SCOPED_TRACE(c.what);
    c.send();
    const auto refusals = peer.step(20, 1);
    ASSERT_EQ(refusals.size(), 1u);
    EXPECT_NE(refusals[0].find(c.reason), std::string::npos) << refusals[0];
    robot.advance(0.02);
    EXPECT_LT(maxAbs(robot.measuredJs(Arm::Left).position - start), 1e-6);
    EXPECT_EQ(robot.operatingStatus().state, OperatingState::Enabled);
  }
  // Good commands while PAUSED or DISABLED are refused too.
  for (auto state : {StateCommand::Pause, StateCommand::Disable}) {
    ASSERT_TRUE(robot.send(state));
    robot.advance(0.001);
    peer.send(CommandTopic::Arm1ServoJr, jointCommand({0.001, 0, 0, 0, 0, 0, 0}));
    const auto refusals = peer.step(20, 1);
    ASSERT_EQ(refusals.size(), 1u);
    EXPECT_NE(refusals[0].find(state == StateCommand::Pause ? "PAUSED" : "DISABLED"),
              std::string::npos)
        << refusals[0];
    robot.advance(0.02);
    EXPECT_LT(maxAbs(robot.measuredJs(Arm::Left).position - start), 1e-6);
  }
  // Each refusal is in the node's log too.
  const std::string log = rig.node.stopAndReadLog();
  for (const char* reason : {"position has 5 values", "would jump", "unknown state command 'fly'",
                             "the robot is PAUSED"}) {
    EXPECT_NE(log.find(reason), std::string::npos) << reason << " not logged:\n" << log;
  }
}

TEST(TwinOverRos, ASilentControllerLeavesTheArmsHolding) {
  Rig rig(kIdealServos);
  auto& robot = rig.client;
  makeReady(robot);
  for (int k = 0; k < 250; ++k) {
    robot.send(bridge::ServoJr{Arm::Left, increment(k)});
    robot.advance(0.002);
  }
  robot.advance(0.5);
  const ArmJoints held = robot.measuredJs(Arm::Left).position;
  double drift = 0.0;
  for (int i = 0; i < 100; ++i) {  // one second without a command
    robot.advance(0.01);
    drift = std::max(drift, maxAbs(robot.measuredJs(Arm::Left).position - held));
  }
  EXPECT_LT(drift, 3e-4) << "more than two encoder counts of the roll";
  EXPECT_EQ(robot.operatingStatus().state, OperatingState::Enabled);
}

TEST(TwinOverRos, AClientThatLosesTheRobotReportsFaultInsteadOfHanging) {
  for (bool lock_step : {true, false}) {
    SCOPED_TRACE(lock_step ? "lock-step" : "wall clock");
    Rig rig(kIdealServos, lock_step);
    auto& robot = rig.client;
    ASSERT_TRUE(robot.send(StateCommand::Enable));
    advanceUntil(robot, [&] { return robot.operatingStatus().state == OperatingState::Enabled; });
    ASSERT_EQ(robot.operatingStatus().state, OperatingState::Enabled);
    rig.node.kill();
    const auto started = std::chrono::steady_clock::now();
    for (int i = 0; i < 300 && robot.operatingStatus().state != OperatingState::Fault; ++i) {
      robot.advance(0.01);
    }
    const double took =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    EXPECT_EQ(robot.operatingStatus().state, OperatingState::Fault);
    EXPECT_LT(took, 3.0) << "the client must give up after its robot timeout (0.5 s)";
    EXPECT_FALSE(robot.lostReason().empty());
    const auto refused = robot.send(bridge::ServoJr{Arm::Left, ArmJoints::Zero()});
    EXPECT_FALSE(refused);
    EXPECT_NE(refused.note.find("robot lost"), std::string::npos) << refused.note;
  }
}

TEST(TwinOverRos, TheWallClockTwinFollowsAServoStreamInRealTime) {
  Rig rig(kIdealServos, /*lock_step=*/false);
  auto& robot = rig.client;
  EXPECT_EQ(robot.clockKind(), bridge::ClockKind::Wall);
  makeReady(robot);
  const ArmJoints start = robot.setpointJs(Arm::Left).position;
  for (int k = 0; k < 100; ++k) {
    robot.send(bridge::ServoJr{Arm::Left, ArmJoints::Unit(raven::kRoll) * 0.001});
    robot.advance(0.002);
  }
  robot.advance(0.1);
  EXPECT_NEAR(robot.measuredJs(Arm::Left).position(raven::kRoll) - start(raven::kRoll), 0.1, 1e-4);
}

}  // namespace

namespace {

TEST(TwinOverRos, TheTwinPublishesEachGraspersContactForces) {
  Rig rig(kIdealServos);
  auto& robot = rig.client;
  makeReady(robot);
  ros::NodeHandle node(rig.node.ns());
  ros::CallbackQueue queue;
  node.setCallbackQueue(&queue);
  std::optional<geometry_msgs::WrenchStamped> wrench;
  std::optional<raven_twin::GraspForces> jaws;
  auto on_wrench = node.subscribe<geometry_msgs::WrenchStamped>(
      "grasp2/measured_cf", 10,
      [&](const geometry_msgs::WrenchStamped::ConstPtr& m) { wrench = *m; }, {},
      bridge::ros1::lowLatency());
  auto on_jaws = node.subscribe<raven_twin::GraspForces>(
      "grasp2/jaw_forces", 10, [&](const raven_twin::GraspForces::ConstPtr& m) { jaws = *m; }, {},
      bridge::ros1::lowLatency());
  for (int i = 0;
       i < 1000 && (on_wrench.getNumPublishers() == 0 || on_jaws.getNumPublishers() == 0); ++i) {
    queue.callAvailable(ros::WallDuration(0.01));
  }
  robot.advance(0.001);
  for (int i = 0; i < 500 && !(wrench && jaws); ++i) queue.callAvailable(ros::WallDuration(0.01));
  ASSERT_TRUE(wrench && jaws) << "grasp2/measured_cf and grasp2/jaw_forces are published";
  EXPECT_EQ(wrench->header.frame_id, "world");
  EXPECT_EQ(wrench->header.stamp, jaws->header.stamp);
  // At home the jaws touch nothing but each other, which is no object.
  EXPECT_EQ(jaws->contacts[0] + jaws->contacts[1], 0u);
  EXPECT_EQ(wrench->wrench.force.x, 0.0);
  EXPECT_EQ(wrench->wrench.force.z, 0.0);

  // The client reads both halves of the same cycle as the grasper's measured_cf.
  for (int i = 0; i < 50 && !(robot.measuredCf(Arm::Left) && robot.measuredCf(Arm::Right)); ++i) {
    robot.advance(0.001);
  }
  const auto left = robot.measuredCf(Arm::Left);
  ASSERT_TRUE(left.has_value()) << "the twin's grasp forces reach its client";
  ASSERT_TRUE(robot.measuredCf(Arm::Right).has_value());
  EXPECT_EQ(left->jaws[0].contacts + left->jaws[1].contacts, 0);
  EXPECT_TRUE(left->force.isZero());
  EXPECT_GT(left->time, 0.0);
}

TEST(RosConversions, GraspForcesAreReadJawByJawAndNonFiniteOnesRefused) {
  raven_twin::GraspForces jaws;
  jaws.normal[1].y = -0.15;
  jaws.friction[1].z = 0.01;
  jaws.contacts = {0, 3};
  geometry_msgs::Wrench wrench;
  wrench.force.z = 0.0196;
  const auto read = bridge::ros1::grasperForcesFrom(jaws, wrench);
  ASSERT_TRUE(read.value) << read.error;
  EXPECT_EQ(read.value->jaws[1].normal, Eigen::Vector3d(0, -0.15, 0));
  EXPECT_EQ(read.value->jaws[1].friction, Eigen::Vector3d(0, 0, 0.01));
  EXPECT_EQ(read.value->jaws[1].contacts, 3);
  EXPECT_EQ(read.value->force.z(), 0.0196);
  jaws.friction[0].x = std::nan("");
  EXPECT_NE(bridge::ros1::grasperForcesFrom(jaws, wrench).error.find("jaw 1"), std::string::npos);
  jaws.friction[0].x = 0.0;
  wrench.torque.y = std::numeric_limits<double>::infinity();
  EXPECT_NE(bridge::ros1::grasperForcesFrom(jaws, wrench).error.find("measured_cf"),
            std::string::npos);
}

}  // namespace
