// The grip's geometry: how far the outer jaw reaches into a ring's wall at a given angle, and the
// angle for a given squeeze.

#include "scenario/grip_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

// The peg scene's wall and grasp: a 4 mm wide, 10 mm tall tube section 5 mm under the jaw
// axis, the inner jaw 0.2 mm from it, 11 mm jaws.
const scenario::PinchedWall kWall{.half_width = 0.002,
                                  .half_height = 0.005,
                                  .pivot_above = 0.005,
                                  .gap = 0.0002,
                                  .jaw_length = 0.011};

TEST(GripGeometry, ClosedFlatTheOuterJawCrossesTheGapAndTheWholeWall) {
  // Within what 400 samples along the 11 mm jaw resolve of the wall's widest point: half a
  // sample (0.014 mm) from it the ellipse is in by half_width u^2 / 2, 8e-9 m.
  EXPECT_NEAR(scenario::wallSqueeze(kWall, 0.0), 0.0042, 8e-9);
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
