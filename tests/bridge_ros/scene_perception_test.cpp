// What a task sees of the scene over ROS 1, against a real rosmaster: the twin node's AMBF
// object topics give exactly the poses the in-process world does (soft rings as their
// shape-matched frame, stamped with the simulated clock in lock-step); a tracker's PoseStamped
// stream of recorded ring poses comes out registered into the robot's frame, a bad pose is
// ignored, a lost object goes stale, and an object nobody publishes is named.

#include <geometry_msgs/PoseStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <cmath>
#include <limits>
#include <vector>

#include "bridge/ros/ros_conversions.hpp"
#include "bridge/ros/ros_scene_perception.hpp"
#include "raven/platform_profile.hpp"
#include "twin/ros/ambf_object_topics.hpp"
#include "twin/twin_platform.hpp"
#include "twin/world_perception.hpp"

namespace {

using bridge::ros1::PoseSource;
using bridge::ros1::RosPerceptionOptions;
using bridge::ros1::RosScenePerception;

const std::vector<std::string> kObjects{"peg_board", "ring1", "ring2", "ring3",
                                        "ring4",     "ring5", "ring6"};

twin::TwinOptions pegScene() {
  twin::TwinOptions options;
  options.launch_file = raven::modelDirectory() / "peg_transfer" / "launch.yaml";
  options.clock = bridge::ClockKind::Simulated;
  return options;
}

double poseGap(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.matrix() - b.matrix()).cwiseAbs().maxCoeff();
}

TEST(ScenePerceptionOverRos, TheObjectTopicsGiveTheWorldsPosesAtTheSimulatedTime) {
  twin::TwinPlatform twin(pegScene());
  twin::ros1::AmbfObjectTopics topics(twin.world(), true);
  EXPECT_GE(topics.bodyTopics(), kObjects.size());
  RosPerceptionOptions options;
  options.topic_namespace = "/peg_transfer/";
  options.objects = kObjects;
  options.lock_step = true;
  RosScenePerception seen(options);
  EXPECT_EQ(seen.topicOf("ring1"), "/peg_transfer/ring1/State");
  const twin::WorldPerception truth(twin.world());
  for (int cycle = 0; cycle < 300; ++cycle) {
    twin.advance(0.001);  // the rings settle on their posts
    topics.update(twin.now());
    seen.update(twin.now());  // waits for every object's state of this cycle
    if (cycle % 50 != 0) continue;
    for (const std::string& object : kObjects) {
      const bridge::Sighting over_ros = seen.sight(object);
      EXPECT_NEAR(over_ros.time, twin.now(), 1e-9) << object;
      EXPECT_LT(poseGap(over_ros.pose, truth.sight(object).pose), 1e-12) << object;
      EXPECT_FALSE(over_ros.volume_ratio) << object << ": AMBF's topics carry no volume";
    }
  }
  EXPECT_TRUE(truth.sight("ring1").volume_ratio);  // the in-process world does
}

/// Publishes geometry_msgs/PoseStamped as a tracker (vrpn_client_ros) does.
class RecordedTracker {
 public:
  explicit RecordedTracker(const std::string& topic)
      : publisher_(node_.advertise<geometry_msgs::PoseStamped>(topic, 10)) {}
  void publish(const Eigen::Isometry3d& pose) {
    publisher_.publish(bridge::ros1::toPoseStamped(pose, ::ros::Time::now(), "tracker"));
  }
  void publishRaw(const geometry_msgs::PoseStamped& m) { publisher_.publish(m); }

 private:
  ::ros::NodeHandle node_;
  ::ros::Publisher publisher_;
};

TEST(ScenePerceptionOverRos, ATrackersRecordedPosesComeOutInTheRobotsFrame) {
  // Poses of a ring recorded in the twin: at rest, then tipped and carried off its post.
  twin::TwinPlatform twin(pegScene());
  const twin::WorldPerception truth(twin.world());
  std::vector<Eigen::Isometry3d> recorded;
  for (int k = 0; k < 5; ++k) {
    Eigen::Isometry3d pose = truth.sight("ring1").pose;
    pose.translation() += Eigen::Vector3d(0.002 * k, -0.001 * k, 0.004 * k);
    pose.linear() = Eigen::AngleAxisd(0.1 * k, Eigen::Vector3d::UnitX()) * pose.linear();
    recorded.push_back(pose);
  }
  // The tracker's frame: 1.2 m in front of the robot, turned half a turn about z.
  Eigen::Isometry3d world_from_tracker = Eigen::Isometry3d::Identity();
  world_from_tracker.translation() << 0.1, 1.2, 0.3;
  world_from_tracker.linear() = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()).matrix();

  RecordedTracker tracker("/vrpn_client_node/ring1/pose");
  RosPerceptionOptions options;
  options.source = PoseSource::Tracker;
  options.topic_namespace = "/vrpn_client_node/";
  options.objects = {"ring1"};
  options.world_from_source = world_from_tracker;
  options.stale_after = 0.5;
  RosScenePerception seen(options);
  EXPECT_EQ(seen.topicOf("ring1"), "/vrpn_client_node/ring1/pose");
  EXPECT_THROW(seen.sight("ring1"), bridge::PerceptionError);  // nothing has arrived yet

  // Delivered, the sighting is the recorded pose in the robot's frame (platform time 1.0 s).
  auto receive = [&](const Eigen::Isometry3d& expected) {
    const auto deadline = ::ros::WallTime::now() + ::ros::WallDuration(5.0);
    while (::ros::WallTime::now() < deadline) {
      seen.update(1.0);
      try {
        if (poseGap(seen.sight("ring1").pose, expected) < 1e-12) return true;
      } catch (const bridge::PerceptionError&) {
      }
    }
    return false;
  };
  for (const Eigen::Isometry3d& pose : recorded) {
    tracker.publish(world_from_tracker.inverse() * pose);
    ASSERT_TRUE(receive(pose)) << "the recorded pose did not come out in the robot's frame";
  }
  // A pose with a NaN quaternion is ignored: the last good one stands.
  geometry_msgs::PoseStamped bad = bridge::ros1::toPoseStamped(
      world_from_tracker.inverse() * recorded[0], ::ros::Time::now(), "tracker");
  bad.pose.orientation.w = std::numeric_limits<double>::quiet_NaN();
  tracker.publishRaw(bad);
  tracker.publish(world_from_tracker.inverse() * recorded[2]);  // ordered after the bad one
  ASSERT_TRUE(receive(recorded[2]));
  // Not seen for longer than stale_after: no sighting.
  seen.update(1.0 + 0.6);
  EXPECT_THROW(seen.sight("ring1"), bridge::PerceptionError);
}

TEST(ScenePerceptionOverRos, AnObjectNobodyPublishesIsNamed) {
  RosPerceptionOptions options;
  options.source = PoseSource::Tracker;
  options.topic_namespace = "/nobody/";
  options.objects = {"ring7"};
  options.timeout = 0.3;
  try {
    RosScenePerception seen(options);
    FAIL() << "no error";
  } catch (const bridge::PerceptionError& e) {
    EXPECT_NE(std::string(e.what()).find("/nobody/ring7/pose"), std::string::npos) << e.what();
  }
}

}  // namespace
