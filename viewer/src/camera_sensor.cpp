#include "viewer/camera_sensor.hpp"

#include <stdexcept>
#include <string>

#include "headless_context.hpp"
#include "renderer.hpp"
#include "viewer/scene_geometry.hpp"

namespace viewer {

CameraSensor::CameraSensor(const ambf_like::World& world, int width, int height,
                           const std::function<SceneLabels(const SceneGeometry&)>& label,
                           const std::filesystem::path& skin)
    : width_(width), height_(height) {
  if (width < 8 || height < 8 || width > 4096 || height > 4096) {
    throw std::invalid_argument("a camera image is 8..4096 pixels a side, not " +
                                std::to_string(width) + "x" + std::to_string(height));
  }
  geometry_ = std::make_unique<const SceneGeometry>(SceneGeometry::of(world, skin));
  labels_ = label(*geometry_);
  if (labels_.bodies.size() != geometry_->bodies.size() ||
      labels_.soft_bodies.size() != geometry_->soft_bodies.size()) {
    throw std::invalid_argument(
        "segmentation labels for another scene: " + std::to_string(labels_.bodies.size()) +
        " bodies and " + std::to_string(labels_.soft_bodies.size()) +
        " soft bodies labelled, the world has " + std::to_string(geometry_->bodies.size()) +
        " and " + std::to_string(geometry_->soft_bodies.size()));
  }
  for (std::size_t i = 0; i < labels_.bodies.size(); ++i) {
    const std::size_t n = labels_.bodies[i].size();
    if (n != 1 && n != geometry_->bodies[i].visual.triangles()) {
      throw std::invalid_argument("body " + geometry_->bodies[i].name + ": " + std::to_string(n) +
                                  " labels for " +
                                  std::to_string(geometry_->bodies[i].visual.triangles()) +
                                  " triangles (give one, or one per triangle)");
    }
  }
  context_ = std::make_unique<detail::HeadlessContext>(width, height);
}

CameraSensor::~CameraSensor() = default;

CameraImages CameraSensor::render(const ambf_like::World& world, const View& view, bool rgb,
                                  bool depth, bool segmentation, const Look& look) {
  context_->bind();
  const FrameState frame = FrameState::of(world, false);
  const Camera camera = view.at(frame.body_poses);
  CameraImages out;
  out.width = width_;
  out.height = height_;
  if (rgb || depth) {
    detail::draw(*geometry_, frame, camera, width_, height_, ViewOptions{}, look);
    if (rgb) out.rgb = detail::readPixels(width_, height_);
    if (depth) out.depth = detail::readDepth(camera, width_, height_);
  }
  if (segmentation) {
    detail::drawLabels(*geometry_, frame, camera, width_, height_, labels_);
    const std::vector<std::uint8_t> colours = detail::readPixels(width_, height_);
    out.segmentation.resize(colours.size() / 3);
    for (std::size_t p = 0; p < out.segmentation.size(); ++p) {
      out.segmentation[p] = colours[3 * p] | (colours[3 * p + 1] << 8) |
                            (static_cast<std::uint32_t>(colours[3 * p + 2]) << 16);
    }
  }
  return out;
}

}  // namespace viewer
