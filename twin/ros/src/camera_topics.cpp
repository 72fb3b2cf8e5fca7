#include "twin/ros/camera_topics.hpp"

#include <algorithm>
#include <stdexcept>

#include "scenario/peg_cameras.hpp"

namespace twin::ros1 {

namespace {

std::vector<std::string> topicsOf(const std::vector<std::string>& views) {
  std::vector<std::string> topics;
  for (const std::string& view : views) topics.push_back(CameraTopics::topicOf(view));
  return topics;
}

}  // namespace

std::string CameraTopics::topicOf(const std::string& view) {
  std::string name = view;
  std::replace(name.begin(), name.end(), '-', '_');  // ROS names take no '-'
  return "cameras/" + name + "/image_raw";
}

CameraTopics::CameraTopics(const ambf_like::World& world, CameraTopicOptions options)
    : options_(std::move(options)),
      cameras_(std::make_unique<scenario::PegCameras>(world, options_.views, options_.width,
                                                      options_.height)),
      publisher_(topicsOf(options_.views), options_.views) {
  if (!(options_.rate > 0.0)) {
    throw std::invalid_argument("a camera's frame rate must be positive, not " +
                                std::to_string(options_.rate));
  }
}

CameraTopics::~CameraTopics() = default;

void CameraTopics::update(const ambf_like::World& world, double now, double stamp) {
  if (now < next_frame_) return;
  next_frame_ = std::max(next_frame_ + 1.0 / options_.rate, now);
  const std::vector<viewer::CameraImages> images = cameras_->render(world, true, false, false);
  for (std::size_t i = 0; i < images.size(); ++i) {
    publisher_.publish(i, {images[i].width, images[i].height, images[i].rgb, stamp});
  }
}

}  // namespace twin::ros1
