// A world's sensors and actuators on AMBF's own topics, against a real rosmaster: the example's
// proximity sensor publishes what it sees as AMBF does, and its constraint actuator takes the
// sensed block on an ambf_msgs/ActuatorCmd, holds it and lets it go.

#include <ambf_msgs/ActuatorCmd.h>
#include <ambf_msgs/ActuatorState.h>
#include <ambf_msgs/SensorState.h>
#include <gtest/gtest.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <optional>

#include "test_files.hpp"
#include "twin/ros/ambf_object_topics.hpp"

namespace {

constexpr double kRange = 0.1;  // the example sensor's range (m)

/// The example world with its topics, and an AMBF client of them.
class AmbfTopics : public ::testing::Test {
 protected:
  AmbfTopics()
      : sim_(test_support::simulate({test_support::exampleFile("sensors_actuators.yaml")})),
        topics_(*sim_->world, false) {
    client_.setCallbackQueue(&queue_);
    sensor_sub_ = client_.subscribe<ambf_msgs::SensorState>(
        "/ambf/env/pad_sensor/State", 1000,
        [this](const ambf_msgs::SensorState::ConstPtr& m) { sensor_ = *m; });
    actuator_sub_ = client_.subscribe<ambf_msgs::ActuatorState>(
        "/ambf/env/pad_gripper/State", 1000,
        [this](const ambf_msgs::ActuatorState::ConstPtr& m) { actuator_ = *m; });
    command_ = client_.advertise<ambf_msgs::ActuatorCmd>("/ambf/env/pad_gripper/Command", 10);
    waitFor([&] {
      return sensor_sub_.getNumPublishers() > 0 && actuator_sub_.getNumPublishers() > 0 &&
             command_.getNumSubscribers() > 0;
    });
  }

  ambf_like::World& world() { return *sim_->world; }
  double blockGap() {  // from the sensor's rays to the block's underside
    return world().body("block").pose().translation().z() - 0.01 - 0.011;
  }
  /// One step, the topics updated, and every message that arrives within a moment delivered.
  void step() {
    world().step();
    topics_.update(world().time());
    queue_.callAvailable(::ros::WallDuration(0.002));
  }
  /// Steps, then waits for the state of this very step. (Not "a newer sim_step": sim_step counts
  /// publications, and waitFor republishes, so a message of the step before could still be on
  /// its way with a newer sim_step.)
  void stepAndReceive() {
    step();
    const auto now = static_cast<float>(world().time());  // the message's own type
    waitFor([&] { return sensor_ && sensor_->sim_time == now; });
  }
  template <typename Condition>
  void waitFor(Condition condition) {
    for (int i = 0; i < 2000 && !condition(); ++i) {
      topics_.update(world().time());
      queue_.callAvailable(::ros::WallDuration(0.005));
    }
    ASSERT_TRUE(condition()) << "nothing arrived in 10 s";
  }
  void send(bool actuate, const std::string& body = "", const std::string& sensor = "") {
    ambf_msgs::ActuatorCmd m;
    m.actuate = actuate;
    m.body_name.data = body;
    m.use_sensor_data = !sensor.empty();
    m.sensor_identifier.data = sensor;
    command_.publish(m);
  }

  std::unique_ptr<test_support::Simulation> sim_;
  twin::ros1::AmbfObjectTopics topics_;
  ::ros::NodeHandle client_;
  ::ros::CallbackQueue queue_;
  ::ros::Subscriber sensor_sub_, actuator_sub_;
  ::ros::Publisher command_;
  std::optional<ambf_msgs::SensorState> sensor_;
  std::optional<ambf_msgs::ActuatorState> actuator_;
};

TEST_F(AmbfTopics, TheSensorStatePublishesWhatItSeesAsAmbfDoes) {
  EXPECT_EQ(topics_.sensorTopics(), 1u);
  EXPECT_EQ(topics_.actuatorTopics(), 1u);
  int seen = 0;
  for (int i = 0; i < 400 && blockGap() > 0.02; ++i) {
    stepAndReceive();
    const auto& m = *sensor_;
    ASSERT_EQ(m.count, 2u);
    ASSERT_EQ(m.triggered.size(), 2u);
    ASSERT_EQ(m.range.size(), 1u);
    EXPECT_FLOAT_EQ(m.range[0], kRange);
    EXPECT_EQ(m.type.data, "PROXIMITY");
    EXPECT_EQ(m.parent_name.data, "pad");
    if (!m.triggered[0]) {
      EXPECT_GT(blockGap(), kRange - 1e-3);
      EXPECT_EQ(m.measurement[0], 0.0F);
      continue;
    }
    ++seen;
    EXPECT_EQ(m.sensed_objects[0].data, "/ambf/env/block");
    // AMBF's depth fraction: 1 - distance / range.
    EXPECT_NEAR((1.0 - m.measurement[0]) * kRange, blockGap(), 1e-3) << "step " << i;
  }
  EXPECT_GT(seen, 5);
}

TEST_F(AmbfTopics, TheActuatorTakesTheSensedBodyOnCommandHoldsItAndLetsGo) {
  while (!(world().sensor("pad_sensor").triggered() && blockGap() < 0.05)) step();
  // A body that does not exist: logged, nothing held.
  send(true, "no_such_body");
  waitFor([&] { return actuator_.has_value(); });
  for (int i = 0; i < 5; ++i) step();
  EXPECT_FALSE(world().actuator("pad_gripper").actuated());

  send(true, "", "pad_sensor");  // AMBF's use_sensor_data: whatever the sensor sees
  waitFor([&] { return actuator_ && actuator_->actuated; });
  EXPECT_EQ(world().actuator("pad_gripper").heldBody(), "/ambf/env/block");
  const double held = blockGap();
  for (int i = 0; i < 1000; ++i) step();
  EXPECT_NEAR(blockGap(), held, 0.002) << "held 1 s in the air";

  send(false);
  waitFor([&] { return actuator_ && !actuator_->actuated; });
  for (int i = 0; i < 1000; ++i) step();
  EXPECT_LT(blockGap(), 0.001) << "released, it fell onto the pad";
}

}  // namespace
