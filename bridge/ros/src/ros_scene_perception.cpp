#include "bridge/ros/ros_scene_perception.hpp"

#include <ambf_msgs/RigidBodyState.h>
#include <geometry_msgs/PoseStamped.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <cmath>
#include <limits>
#include <map>

#include "bridge/ros/low_latency.hpp"
#include "bridge/ros/ros_conversions.hpp"
#include "bridge/throttled_log.hpp"
#include "missing_publishers.hpp"
#include "raven/control_cycle.hpp"

namespace bridge::ros1 {

class RosScenePerception::Impl {
 public:
  explicit Impl(RosPerceptionOptions options) : options_(std::move(options)) {
    node_.setCallbackQueue(&queue_);
    for (const std::string& object : options_.objects) {
      const std::string topic = topicOf(object);
      if (options_.source == PoseSource::AmbfObjects) {
        subscribers_.push_back(node_.subscribe<ambf_msgs::RigidBodyState>(
            topic, 10,
            [this, object](const ambf_msgs::RigidBodyState::ConstPtr& m) {
              take(object, m->header.stamp, m->pose);
            },
            {}, lowLatency()));
      } else {
        subscribers_.push_back(node_.subscribe<geometry_msgs::PoseStamped>(
            topic, 10,
            [this, object](const geometry_msgs::PoseStamped::ConstPtr& m) {
              take(object, m->header.stamp, m->pose);
            },
            {}, lowLatency()));
      }
    }
    waitFor([this] { return missingPublishers(subscribers_).empty(); },
            [this] { return "no publisher on " + missingPublishers(subscribers_); });
  }

  std::string topicOf(const std::string& object) const {
    return options_.topic_namespace + object +
           (options_.source == PoseSource::AmbfObjects ? "/State" : "/pose");
  }

  void update(double now) {
    now_ = now;
    queue_.callAvailable();
    if (!options_.lock_step) {
      // Wall clock: what has arrived, once every object has been heard from at all.
      const double ever = -std::numeric_limits<double>::infinity();
      waitFor([&] { return behind(ever).empty(); },
              [&] { return "no pose yet of " + behind(ever); });
      return;
    }
    // Every object reported at `now` (stamps are the node's simulated clock, to the nanosecond).
    const double due = now - 0.5 * raven::kControlCycle;
    waitFor([&] { return behind(due).empty(); },
            [&] { return "no pose at t = " + std::to_string(now) + " s of " + behind(due); });
  }

  Sighting sight(const std::string& name) const {
    const auto it = seen_.find(name);
    if (it == seen_.end()) {
      throw PerceptionError("'" + name + "' is not watched, or has not been seen on " +
                            topicOf(name));
    }
    if (!options_.lock_step && now_ - it->second.time > options_.stale_after) {
      throw PerceptionError("'" + name + "' was last seen " +
                            std::to_string(now_ - it->second.time) + " s ago on " + topicOf(name));
    }
    return it->second;
  }

 private:
  void take(const std::string& object, const ::ros::Time& stamp, const geometry_msgs::Pose& pose) {
    const auto parsed = poseFromPose(pose);
    if (!parsed.value) {
      log_.warn(object, topicOf(object) + ": pose ignored: " + parsed.error, stamp.toSec());
      return;
    }
    Sighting& s = seen_[object];
    // A lock-step node stamps with its simulated clock; a tracker with the wall clock, which
    // this platform's clock (wall) runs on too.
    s.time = options_.lock_step ? stamp.toSec() : now_;
    s.pose = options_.world_from_source * *parsed.value;
  }

  std::string behind(double due) const {
    std::string late;
    for (const std::string& object : options_.objects) {
      const auto it = seen_.find(object);
      if (it == seen_.end() || it->second.time < due) late += (late.empty() ? "" : ", ") + object;
    }
    return late;
  }

  template <typename Condition, typename Why>
  void waitFor(Condition condition, Why why) {
    const auto deadline = ::ros::WallTime::now() + ::ros::WallDuration(options_.timeout);
    while (!condition()) {
      if (::ros::WallTime::now() > deadline) throw PerceptionError(why());
      queue_.callAvailable(::ros::WallDuration(0.001));
    }
  }

  RosPerceptionOptions options_;
  ::ros::NodeHandle node_;
  ::ros::CallbackQueue queue_;
  std::vector<::ros::Subscriber> subscribers_;
  std::map<std::string, Sighting> seen_;
  double now_ = 0.0;
  ThrottledLog log_;
};

RosScenePerception::RosScenePerception(RosPerceptionOptions options)
    : impl_(std::make_unique<Impl>(std::move(options))) {}
RosScenePerception::~RosScenePerception() = default;

void RosScenePerception::update(double now) {
  impl_->update(now);
}
Sighting RosScenePerception::sight(const std::string& name) const {
  return impl_->sight(name);
}
std::string RosScenePerception::topicOf(const std::string& object) const {
  return impl_->topicOf(object);
}

}  // namespace bridge::ros1
