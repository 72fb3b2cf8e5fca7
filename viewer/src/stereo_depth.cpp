#include "viewer/stereo_depth.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

namespace viewer {

namespace {

/// SplitMix64's finaliser: a well-mixed 64-bit value of any 64-bit input.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// A standard normal value, a function of (key, index) alone (Box-Muller on two hashed
/// uniforms in (0, 1]).
double normal(std::uint64_t key, std::uint64_t index) {
  const std::uint64_t a = mix(key ^ mix(2 * index)), b = mix(key ^ mix(2 * index + 1));
  const double u1 = (static_cast<double>(a >> 11) + 1.0) * 0x1.0p-53;
  const double u2 = static_cast<double>(b >> 11) * 0x1.0p-53;
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

/// Leaves no reading on each row's pixels the second imager (to the right) cannot see: pixel x
/// is hidden where some x' > x has a disparity larger by more than x' - x.
void dropOccluded(std::vector<float>& depth, int width, int height, double focal_baseline) {
  const float none = std::numeric_limits<float>::infinity();
  std::vector<double> disparity(static_cast<std::size_t>(width));
  for (int row = 0; row < height; ++row) {
    float* line = depth.data() + static_cast<std::ptrdiff_t>(row) * width;
    for (int x = 0; x < width; ++x) {
      disparity[static_cast<std::size_t>(x)] =
          std::isfinite(line[x]) ? focal_baseline / line[x] : 0.0;
    }
    double reach = -std::numeric_limits<double>::infinity();  // max over x' > x of d(x') - x'
    for (int x = width - 1; x >= 0; --x) {
      const double d = disparity[static_cast<std::size_t>(x)] - x;
      if (reach > d) line[x] = none;
      reach = std::max(reach, d);
    }
  }
}

}  // namespace

void applyStereoErrors(std::vector<float>& depth, int width, int height, double fov_y,
                       const StereoDepthErrors& errors, std::uint64_t key) {
  if (errors.exact() || depth.empty()) return;  // exact, or no depth image asked for
  if (depth.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw std::invalid_argument("a depth image of " + std::to_string(depth.size()) +
                                " pixels is not " + std::to_string(width) + " x " +
                                std::to_string(height));
  }
  if (errors.baseline > 0.0) {
    const double focal = 0.5 * height / std::tan(0.5 * fov_y);  // pixels
    dropOccluded(depth, width, height, focal * errors.baseline);
  }
  const float none = std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < depth.size(); ++i) {
    if (!std::isfinite(depth[i])) continue;
    const double inverse = 1.0 / depth[i] + errors.noise_at_1m * normal(key, i);
    depth[i] = inverse > 0.0 ? static_cast<float>(errors.scale / inverse) : none;
  }
}

std::uint64_t depthNoiseKey(std::uint64_t seed, std::size_t camera, double time) {
  const auto microseconds = static_cast<std::uint64_t>(std::llround(time * 1e6));
  return mix(mix(mix(seed) ^ camera) ^ microseconds);
}

}  // namespace viewer
