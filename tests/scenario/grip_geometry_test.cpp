// The grip's geometry: how far the outer jaw reaches into a ring's wall at a given angle, and the
// angle for a given squeeze.

#include "scenario/grip_geometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

// The peg-transfer scene's wall and grasp: a 4 mm wide, 10 mm tall tube section 5 mm under the jaw
// axis, the inner jaw 0.2 mm from it, 11 mm jaws.
const scenario::PinchedWall kWall{.half_width = 0.002,
                                  .half_height = 0.005,
                                  .pivot_above = 0.005,
                                  .gap = 0.0002,
                                  .jaw_length = 0.011};

TEST(GripGeometry, ClosedFlatTheOuterJawCrossesTheGapAndTheWholeWall) {
  EXPECT_NEAR(scenario::wallSqueeze(kWall, 0.0), 0.0042, 1e-9);
}

TEST(GripGeometry, TheDeepestReachIsTheFinestSampledOneAlongTheJaw) {
  // The closed form against 100,000 depths along the jaw (0.11 um apart): never under the best
  // of them, and over it by no more than 1e-9 m.
  for (double angle = 0.0; angle < 1.3; angle += 0.05) {
    const double t = std::tan(angle);
    double sampled = 0.0;
    for (int i = 0; i <= 100000; ++i) {
      const double d = kWall.jaw_length * i / 100000;
      const double u = (d - kWall.pivot_above - kWall.half_height) / kWall.half_height;
      if (std::abs(u) > 1.0) continue;
      const double outer = kWall.gap + kWall.half_width * (1.0 + std::sqrt(1.0 - u * u));
      sampled = std::max(sampled, outer - d * t);
    }
    const double exact = scenario::wallSqueeze(kWall, angle);
    EXPECT_GE(exact, sampled - 1e-15) << angle;
    EXPECT_LE(exact, sampled + 1e-9) << angle;
  }
}

TEST(GripGeometry, OpenWideTheOuterJawTouchesNothing) {
  EXPECT_EQ(scenario::wallSqueeze(kWall, 1.3), 0.0);
}

TEST(GripGeometry, TheSqueezeFallsAsTheJawOpens) {
  double previous = scenario::wallSqueeze(kWall, 0.0);
  for (double angle = 0.05; angle < 1.0; angle += 0.05) {
    const double squeeze = scenario::wallSqueeze(kWall, angle);
    EXPECT_LE(squeeze, previous) << angle;
    previous = squeeze;
  }
}

TEST(GripGeometry, TheAngleForASqueezeGivesThatSqueeze) {
  for (double squeeze : {0.00002, 0.0005, 0.0015, 0.003}) {
    const double angle = scenario::squeezingAngle(kWall, squeeze);
    EXPECT_GT(angle, 0.0);
    EXPECT_NEAR(scenario::wallSqueeze(kWall, angle), squeeze, 1e-6) << squeeze;
  }
  // Touching: the jaw's face tangent to the wall, at the angle whose line just meets the ellipse.
  const double touch = scenario::squeezingAngle(kWall, 1e-9);
  EXPECT_GT(scenario::wallSqueeze(kWall, touch - 0.01), 0.0);
  EXPECT_LT(scenario::wallSqueeze(kWall, touch - 0.01), 0.001);
  EXPECT_EQ(scenario::wallSqueeze(kWall, touch + 0.01), 0.0);
}

}  // namespace
