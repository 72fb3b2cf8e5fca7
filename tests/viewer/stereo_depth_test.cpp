// A stereo depth camera's errors on exact depth images: the noise's size against the stereo
// relation sigma_z = k z^2, the scale bias, the band one imager cannot see beside a nearer
// surface (its width f B (1/z_near - 1/z_far)), and draws that repeat by key.

#include "viewer/stereo_depth.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace stereo_depth_test {

using viewer::applyStereoErrors;
using viewer::StereoDepthErrors;

constexpr int kWidth = 256, kHeight = 192;
constexpr double kFovY = 0.6;

std::vector<float> plane(float z) {
  return std::vector<float>(static_cast<std::size_t>(kWidth * kHeight), z);
}

TEST(StereoDepth, NoiseGrowsWithTheSquareOfTheDepthAsTheStereoRelationSays) {
  const StereoDepthErrors camera{0.002, 1.0, 0.0};  // 2 mm RMS at 1 m
  for (const float z : {0.2f, 0.5f, 1.0f}) {
    std::vector<float> depth = plane(z);
    applyStereoErrors(depth, kWidth, kHeight, kFovY, camera, 42);
    const double n = static_cast<double>(depth.size());
    const double mean = std::accumulate(depth.begin(), depth.end(), 0.0) / n;
    double square = 0.0;
    for (const float d : depth) square += (d - mean) * (d - mean);
    const double rms = std::sqrt(square / n), expected = 0.002 * z * z;
    EXPECT_NEAR(rms, expected, 0.03 * expected) << "at " << z << " m";
    // Unbiased to the first order: the second order's z^3 k^2 is below a micrometre here.
    EXPECT_NEAR(mean, z, 5.0 * expected / std::sqrt(n) + z * z * z * 4e-6);
  }
}

TEST(StereoDepth, AScaleBiasMovesEveryDepthAndNothingStaysNothing) {
  std::vector<float> depth = plane(0.25f);
  depth[7] = std::numeric_limits<float>::infinity();
  applyStereoErrors(depth, kWidth, kHeight, kFovY, {0.0, 1.02, 0.0}, 1);
  EXPECT_FLOAT_EQ(depth[0], 0.255f);
  EXPECT_FLOAT_EQ(depth.back(), 0.255f);
  EXPECT_TRUE(std::isinf(depth[7]));
}

TEST(StereoDepth, TheSecondImagerLeavesABandBesideANearerSurfaceUnseen) {
  // A wall at 1 m and, in front of it at 0.5 m, a box over columns 100..139 of every row.
  std::vector<float> depth = plane(1.0f);
  for (int row = 0; row < kHeight; ++row) {
    for (int x = 100; x < 140; ++x) depth[static_cast<std::size_t>(row * kWidth + x)] = 0.5f;
  }
  const double baseline = 0.05;
  applyStereoErrors(depth, kWidth, kHeight, kFovY, {0.0, 1.0, baseline}, 1);
  // f = (H / 2) / tan(fov / 2) = 310.3 pixels; the band is f B (1/0.5 - 1/1) = 15.5 pixels
  // wide, to the box's left: columns 85..99 (84 lies 16 pixels from the box, past the band).
  const double focal = 0.5 * kHeight / std::tan(0.5 * kFovY);
  const double band = focal * baseline * (1.0 / 0.5 - 1.0 / 1.0);
  ASSERT_NEAR(band, 15.52, 0.01);
  for (int row : {0, kHeight / 2, kHeight - 1}) {
    for (int x = 0; x < kWidth; ++x) {
      const float d = depth[static_cast<std::size_t>(row * kWidth + x)];
      const bool hidden = x >= 85 && x <= 99;
      EXPECT_EQ(std::isinf(d), hidden) << "row " << row << " column " << x;
      if (!hidden) {
        EXPECT_FLOAT_EQ(d, x >= 100 && x < 140 ? 0.5f : 1.0f);
      }
    }
  }
}

TEST(StereoDepth, TheSameKeyDrawsTheSameNoiseAndExactDepthIsLeftAlone) {
  const StereoDepthErrors camera{0.002, 1.0, 0.0};
  std::vector<float> a = plane(0.3f), b = plane(0.3f), c = plane(0.3f), exact = plane(0.3f);
  applyStereoErrors(a, kWidth, kHeight, kFovY, camera, viewer::depthNoiseKey(5, 0, 1.25));
  applyStereoErrors(b, kWidth, kHeight, kFovY, camera, viewer::depthNoiseKey(5, 0, 1.25));
  applyStereoErrors(c, kWidth, kHeight, kFovY, camera, viewer::depthNoiseKey(5, 0, 1.251));
  applyStereoErrors(exact, kWidth, kHeight, kFovY, {}, 3);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);  // the next frame
  EXPECT_NE(viewer::depthNoiseKey(5, 0, 1.25), viewer::depthNoiseKey(5, 1, 1.25));
  EXPECT_NE(viewer::depthNoiseKey(5, 0, 1.25), viewer::depthNoiseKey(6, 0, 1.25));
  EXPECT_EQ(exact, plane(0.3f));
}

TEST(StereoDepth, AColourOnlyRenderHasNoDepthToSpoilAndAWrongSizeIsRefused) {
  const StereoDepthErrors camera{0.002, 1.02, 0.05};
  std::vector<float> none;
  applyStereoErrors(none, kWidth, kHeight, kFovY, camera, 1);
  EXPECT_TRUE(none.empty());
  std::vector<float> short_image(10, 0.3f);
  EXPECT_THROW(applyStereoErrors(short_image, kWidth, kHeight, kFovY, camera, 1),
               std::invalid_argument);
}

}  // namespace stereo_depth_test
