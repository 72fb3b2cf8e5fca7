#include "bridge/ros/ros_camera_images.hpp"

#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stdexcept>

#include "bridge/ros/image_conversions.hpp"
#include "bridge/throttled_log.hpp"
#include "missing_publishers.hpp"

namespace bridge::ros1 {

class RosCameraImages::Impl {
 public:
  explicit Impl(RosCameraOptions options)
      : options_(std::move(options)), cameras_(options_.topics.size()) {
    node_.setCallbackQueue(&queue_);
    for (std::size_t i = 0; i < options_.topics.size(); ++i) {
      subscribers_.push_back(node_.subscribe<sensor_msgs::Image>(
          options_.topics[i], 1,
          [this, i](const sensor_msgs::Image::ConstPtr& m) { take(i, *m); }));
    }
    spinner_.start();
    const auto deadline = ::ros::WallTime::now() + ::ros::WallDuration(options_.timeout);
    while (!missingPublishers(subscribers_).empty()) {
      if (::ros::WallTime::now() > deadline) {
        throw std::runtime_error("no publisher on the camera topic(s) " +
                                 missingPublishers(subscribers_));
      }
      ::ros::WallDuration(0.01).sleep();  // the master's answer comes on ROS's own threads
    }
  }

  ~Impl() { spinner_.stop(); }

  std::uint64_t received(std::size_t camera) const {
    std::lock_guard lock(mutex_);
    return cameras_.at(camera).received;
  }

  CameraFrame latest(std::size_t camera, std::uint64_t after) const {
    std::unique_lock lock(mutex_);
    const Camera& c = cameras_.at(camera);
    const bool arrived = changed_.wait_for(lock, std::chrono::duration<double>(options_.timeout),
                                           [&] { return c.received > after; });
    if (!arrived) {
      throw std::runtime_error("no new image on " + options_.topics[camera] + " for " +
                               std::to_string(options_.timeout) + " s" +
                               (c.refused.empty()
                                    ? std::string()
                                    : " (the last message was refused: " + c.refused + ")"));
    }
    return c.frame;
  }

  const std::vector<std::string>& topics() const { return options_.topics; }

 private:
  /// One topic's latest image.
  struct Camera {
    CameraFrame frame;
    std::uint64_t received = 0;
    std::string refused;  ///< why the last refused message was
  };

  void take(std::size_t camera, const sensor_msgs::Image& message) {
    Parsed<CameraFrame> parsed = frameFromImage(message);
    {
      std::lock_guard lock(mutex_);
      Camera& c = cameras_[camera];
      if (!parsed.value) {
        c.refused = parsed.error;
      } else {
        c.frame = std::move(*parsed.value);
        ++c.received;
      }
    }
    if (parsed.value) {
      changed_.notify_all();
    } else {
      log_.warn(options_.topics[camera],
                options_.topics[camera] + ": image refused: " + parsed.error,
                ::ros::WallTime::now().toSec());
    }
  }

  RosCameraOptions options_;
  ::ros::NodeHandle node_;
  ::ros::CallbackQueue queue_;
  ::ros::AsyncSpinner spinner_{1, &queue_};
  std::vector<::ros::Subscriber> subscribers_;
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::vector<Camera> cameras_;
  ThrottledLog log_;
};

RosCameraImages::RosCameraImages(RosCameraOptions options)
    : impl_(std::make_unique<Impl>(std::move(options))) {}
RosCameraImages::~RosCameraImages() = default;

std::uint64_t RosCameraImages::received(std::size_t camera) const {
  return impl_->received(camera);
}
CameraFrame RosCameraImages::latest(std::size_t camera, std::uint64_t after) const {
  return impl_->latest(camera, after);
}
const std::vector<std::string>& RosCameraImages::topics() const {
  return impl_->topics();
}

}  // namespace bridge::ros1
