#include "twin/ros/camera_topics.hpp"

#include <algorithm>
#include <stdexcept>

#include "scenario/peg_cameras.hpp"

namespace twin::ros1 {

namespace {

/// The colour topics, then (with depth) the depth topics.
std::vector<std::string> topicsOf(const CameraTopicOptions& options) {
  std::vector<std::string> topics;
  for (const std::string& view : options.views) topics.push_back(CameraTopics::topicOf(view));
  if (!options.depth) return topics;
  for (const std::string& view : options.views) topics.push_back(CameraTopics::depthTopicOf(view));
  return topics;
}

/// Each topic's frame id: its camera's name.
std::vector<std::string> frameIdsOf(const CameraTopicOptions& options) {
  std::vector<std::string> ids = options.views;
  if (options.depth) ids.insert(ids.end(), options.views.begin(), options.views.end());
  return ids;
}

/// The nominal scene's look, its depth read as `options` say.
scenario::SceneVariation lookOf(const CameraTopicOptions& options) {
  scenario::SceneVariation look;
  look.depth_noise = options.depth_noise;
  look.depth_scale = options.depth_scale;
  look.depth_baseline = options.depth_baseline;
  return look;
}

std::string rosName(const std::string& view) {
  std::string name = view;
  std::replace(name.begin(), name.end(), '-', '_');  // ROS names take no '-'
  return name;
}

}  // namespace

std::string CameraTopics::topicOf(const std::string& view) {
  return "cameras/" + rosName(view) + "/image_raw";
}

std::string CameraTopics::depthTopicOf(const std::string& view) {
  return "cameras/" + rosName(view) + "/depth/image_raw";
}

CameraTopics::CameraTopics(const ambf_like::World& world, CameraTopicOptions options)
    : options_(std::move(options)),
      cameras_(std::make_unique<scenario::PegCameras>(world, options_.views, options_.width,
                                                      options_.height, lookOf(options_))),
      publisher_(topicsOf(options_), frameIdsOf(options_)) {
  if (!(options_.rate > 0.0)) {
    throw std::invalid_argument("a camera's frame rate must be positive, not " +
                                std::to_string(options_.rate));
  }
}

CameraTopics::~CameraTopics() = default;

void CameraTopics::update(const ambf_like::World& world, double now, double stamp) {
  if (now < next_frame_) return;
  next_frame_ = std::max(next_frame_ + 1.0 / options_.rate, now);
  const std::vector<viewer::CameraImages> images =
      cameras_->render(world, true, options_.depth, false);
  for (std::size_t i = 0; i < images.size(); ++i) {
    const viewer::CameraImages& image = images[i];
    publisher_.publish(i, {image.width, image.height, image.rgb, {}, stamp});
    if (options_.depth) {
      publisher_.publish(images.size() + i, {image.width, image.height, {}, image.depth, stamp});
    }
  }
}

}  // namespace twin::ros1
