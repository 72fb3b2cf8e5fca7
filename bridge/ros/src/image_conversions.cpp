#include "bridge/ros/image_conversions.hpp"

#include <array>
#include <stdexcept>

namespace bridge::ros1 {

namespace {

/// Where an encoding keeps red, green and blue in its pixel, and how many bytes a pixel has.
struct PixelLayout {
  const char* encoding;
  int bytes;
  std::array<int, 3> rgb;
};

constexpr std::array<PixelLayout, 5> kLayouts{{{"rgb8", 3, {0, 1, 2}},
                                               {"bgr8", 3, {2, 1, 0}},
                                               {"rgba8", 4, {0, 1, 2}},
                                               {"bgra8", 4, {2, 1, 0}},
                                               {"mono8", 1, {0, 0, 0}}}};

const PixelLayout* layoutOf(const std::string& encoding) {
  for (const PixelLayout& layout : kLayouts) {
    if (encoding == layout.encoding) return &layout;
  }
  return nullptr;
}

}  // namespace

sensor_msgs::Image toImage(const CameraFrame& frame, const std::string& frame_id) {
  const auto bytes = static_cast<std::size_t>(frame.width) * frame.height * 3;
  if (frame.width <= 0 || frame.height <= 0 || frame.rgb.size() != bytes) {
    throw std::invalid_argument("a camera frame of " + std::to_string(frame.width) + " x " +
                                std::to_string(frame.height) + " needs " + std::to_string(bytes) +
                                " bytes, not " + std::to_string(frame.rgb.size()));
  }
  sensor_msgs::Image m;
  m.header.stamp.fromSec(frame.time);
  m.header.frame_id = frame_id;
  m.width = static_cast<std::uint32_t>(frame.width);
  m.height = static_cast<std::uint32_t>(frame.height);
  m.encoding = "rgb8";
  m.is_bigendian = 0;
  m.step = m.width * 3;
  m.data = frame.rgb;
  return m;
}

Parsed<CameraFrame> frameFromImage(const sensor_msgs::Image& message) {
  const PixelLayout* layout = layoutOf(message.encoding);
  if (layout == nullptr) {
    return Parsed<CameraFrame>::fail("encoding '" + message.encoding +
                                     "' (rgb8, bgr8, rgba8, bgra8 or mono8)");
  }
  if (message.width == 0 || message.height == 0) {
    return Parsed<CameraFrame>::fail("an image of " + std::to_string(message.width) + " x " +
                                     std::to_string(message.height) + " pixels");
  }
  const std::uint64_t row = std::uint64_t{message.width} * layout->bytes;
  if (message.step < row) {
    return Parsed<CameraFrame>::fail("step " + std::to_string(message.step) +
                                     " is shorter than a " + std::to_string(message.width) +
                                     "-pixel row of " + message.encoding + " (" +
                                     std::to_string(row) + " bytes)");
  }
  const std::uint64_t needed = std::uint64_t{message.step} * message.height;
  if (message.data.size() < needed) {
    return Parsed<CameraFrame>::fail(
        std::to_string(message.data.size()) +
        " bytes of data, not step x height = " + std::to_string(needed));
  }
  CameraFrame frame;
  frame.width = static_cast<int>(message.width);
  frame.height = static_cast<int>(message.height);
  frame.time = message.header.stamp.toSec();
  frame.rgb.resize(static_cast<std::size_t>(frame.width) * frame.height * 3);
  std::uint8_t* out = frame.rgb.data();
  for (std::uint32_t y = 0; y < message.height; ++y) {
    const std::uint8_t* pixel = message.data.data() + std::size_t{y} * message.step;
    for (std::uint32_t x = 0; x < message.width; ++x, pixel += layout->bytes) {
      for (int c = 0; c < 3; ++c) *out++ = pixel[layout->rgb[static_cast<std::size_t>(c)]];
    }
  }
  return Parsed<CameraFrame>::ok(std::move(frame));
}

}  // namespace bridge::ros1
