#include "bridge/ros/image_conversions.hpp"

#include <array>
#include <cstring>
#include <limits>
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

/// A depth encoding (REP 118): bytes a pixel, and metres per unit of its value.
struct DepthLayout {
  const char* encoding;
  int bytes;
  double metres;
};

constexpr std::array<DepthLayout, 2> kDepthLayouts{{{"32FC1", 4, 1.0}, {"16UC1", 2, 0.001}}};

const PixelLayout* layoutOf(const std::string& encoding) {
  for (const PixelLayout& layout : kLayouts) {
    if (encoding == layout.encoding) return &layout;
  }
  return nullptr;
}

const DepthLayout* depthLayoutOf(const std::string& encoding) {
  for (const DepthLayout& layout : kDepthLayouts) {
    if (encoding == layout.encoding) return &layout;
  }
  return nullptr;
}

/// Whether the message's sizes hold a whole image of `bytes` a pixel; else why not.
std::string wholeImage(const sensor_msgs::Image& message, int bytes) {
  if (message.width == 0 || message.height == 0) {
    return "an image of " + std::to_string(message.width) + " x " + std::to_string(message.height) +
           " pixels";
  }
  const std::uint64_t row = std::uint64_t{message.width} * static_cast<std::uint64_t>(bytes);
  if (message.step < row) {
    return "step " + std::to_string(message.step) + " is shorter than a " +
           std::to_string(message.width) + "-pixel row of " + message.encoding + " (" +
           std::to_string(row) + " bytes)";
  }
  const std::uint64_t needed = std::uint64_t{message.step} * message.height;
  if (message.data.size() < needed) {
    return std::to_string(message.data.size()) +
           " bytes of data, not step x height = " + std::to_string(needed);
  }
  return {};
}

/// One depth value of `bytes` bytes at `at`, in the message's byte order, in metres (a 16-bit
/// 0 is no reading: +infinity, as the twin's own depth images have it).
float depthAt(const std::uint8_t* at, const DepthLayout& layout, bool big_endian) {
  std::array<std::uint8_t, 4> b{};
  for (int i = 0; i < layout.bytes; ++i) {
    b[static_cast<std::size_t>(i)] = at[big_endian ? layout.bytes - 1 - i : i];
  }
  if (layout.bytes == 2) {
    const auto mm = static_cast<std::uint16_t>(b[0] | (b[1] << 8));
    return mm == 0 ? std::numeric_limits<float>::infinity()
                   : static_cast<float>(mm * layout.metres);
  }
  float value = 0.0f;
  std::memcpy(&value, b.data(), sizeof(value));  // little-endian hosts (x86, ARM)
  return static_cast<float>(value * layout.metres);
}

Parsed<CameraFrame> depthFromImage(const sensor_msgs::Image& message, const DepthLayout& layout) {
  if (std::string why = wholeImage(message, layout.bytes); !why.empty()) {
    return Parsed<CameraFrame>::fail(why);
  }
  CameraFrame frame;
  frame.width = static_cast<int>(message.width);
  frame.height = static_cast<int>(message.height);
  frame.time = message.header.stamp.toSec();
  frame.depth.reserve(static_cast<std::size_t>(frame.width) * frame.height);
  for (std::uint32_t y = 0; y < message.height; ++y) {
    const std::uint8_t* pixel = message.data.data() + std::size_t{y} * message.step;
    for (std::uint32_t x = 0; x < message.width; ++x, pixel += layout.bytes) {
      frame.depth.push_back(depthAt(pixel, layout, message.is_bigendian != 0));
    }
  }
  return Parsed<CameraFrame>::ok(std::move(frame));
}

}  // namespace

sensor_msgs::Image toImage(const CameraFrame& frame, const std::string& frame_id) {
  const auto pixels = static_cast<std::size_t>(frame.width) * frame.height;
  const bool depth = frame.isDepth();
  const std::size_t have = depth ? frame.depth.size() : frame.rgb.size();
  const std::size_t need = depth ? pixels : pixels * 3;
  if (frame.width <= 0 || frame.height <= 0 || have != need) {
    throw std::invalid_argument("a camera frame of " + std::to_string(frame.width) + " x " +
                                std::to_string(frame.height) + " needs " + std::to_string(need) +
                                (depth ? " depths" : " bytes") + ", not " + std::to_string(have));
  }
  sensor_msgs::Image m;
  m.header.stamp.fromSec(frame.time);
  m.header.frame_id = frame_id;
  m.width = static_cast<std::uint32_t>(frame.width);
  m.height = static_cast<std::uint32_t>(frame.height);
  m.is_bigendian = 0;
  if (depth) {
    m.encoding = "32FC1";
    m.step = m.width * 4;
    m.data.resize(frame.depth.size() * sizeof(float));
    std::memcpy(m.data.data(), frame.depth.data(), m.data.size());
  } else {
    m.encoding = "rgb8";
    m.step = m.width * 3;
    m.data = frame.rgb;
  }
  return m;
}

Parsed<CameraFrame> frameFromImage(const sensor_msgs::Image& message) {
  if (const DepthLayout* depth = depthLayoutOf(message.encoding)) {
    return depthFromImage(message, *depth);
  }
  const PixelLayout* layout = layoutOf(message.encoding);
  if (layout == nullptr) {
    return Parsed<CameraFrame>::fail("encoding '" + message.encoding +
                                     "' (rgb8, bgr8, rgba8, bgra8, mono8, 32FC1 or 16UC1)");
  }
  if (std::string why = wholeImage(message, layout->bytes); !why.empty()) {
    return Parsed<CameraFrame>::fail(why);
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
