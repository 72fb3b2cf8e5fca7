#include "bridge/ros/ros_image_publisher.hpp"

#include <ros/ros.h>

#include <stdexcept>

#include "bridge/ros/image_conversions.hpp"

namespace bridge::ros1 {

class RosImagePublisher::Impl {
 public:
  Impl(const std::vector<std::string>& topics, std::vector<std::string> frame_ids)
      : frame_ids_(std::move(frame_ids)) {
    if (frame_ids_.size() != topics.size()) {
      throw std::invalid_argument("one frame id per camera topic");
    }
    for (const std::string& topic : topics) {
      publishers_.push_back(node_.advertise<sensor_msgs::Image>(topic, 2));
    }
  }

  void publish(std::size_t camera, const CameraFrame& frame) {
    publishers_.at(camera).publish(toImage(frame, frame_ids_.at(camera)));
  }

 private:
  ::ros::NodeHandle node_;
  std::vector<std::string> frame_ids_;
  std::vector<::ros::Publisher> publishers_;
};

RosImagePublisher::RosImagePublisher(const std::vector<std::string>& topics,
                                     const std::vector<std::string>& frame_ids)
    : impl_(std::make_unique<Impl>(topics, frame_ids)) {}
RosImagePublisher::~RosImagePublisher() = default;

void RosImagePublisher::publish(std::size_t camera, const CameraFrame& frame) {
  impl_->publish(camera, frame);
}

}  // namespace bridge::ros1
