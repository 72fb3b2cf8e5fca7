#pragma once
// Test helpers for pictures the viewer writes: a PNG read back, and pixel tests on the viewer's
// known colours.

#include <Eigen/Core>
#include <filesystem>
#include <vector>

namespace test_support {

/// An RGB image read back from a PNG.
struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  const unsigned char* at(int x, int y) const {
    return &rgb[(static_cast<std::size_t>(y) * width + x) * 3];
  }
  /// Throws std::runtime_error naming the file if it cannot be read.
  static Image read(const std::filesystem::path& file);
};

/// The viewer's clear colour (0.91, 0.93, 0.95).
bool isBackground(const unsigned char* p);
/// A soft body (the rings), lit or in shade.
bool isRingRed(const unsigned char* p);
/// The collision view's orange.
bool isCollisionOrange(const unsigned char* p);

/// Share of the pixels in the square of half-width `half` around `centre` for which `test` holds.
template <typename Test>
double shareNear(const Image& image, const Eigen::Vector2d& centre, int half, Test test) {
  int hits = 0, all = 0;
  for (int y = static_cast<int>(centre.y()) - half; y <= static_cast<int>(centre.y()) + half; ++y) {
    for (int x = static_cast<int>(centre.x()) - half; x <= static_cast<int>(centre.x()) + half;
         ++x) {
      if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
      ++all;
      hits += test(image.at(x, y));
    }
  }
  return all ? static_cast<double>(hits) / all : 0.0;
}

}  // namespace test_support
