// A physical pendulum written as ADF swings with the period theory predicts.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "test_files.hpp"

namespace {

TEST(Pendulum, SmallAnglePeriodWithinOnePercentOfTheory) {
  const double length = 1.0, radius = 0.05, mass = 1.0, theta0 = 0.05, g = 9.81;
  std::ostringstream adf;
  adf.precision(17);
  adf << "bodies: [BODY anchor, BODY bob]\n"
         "joints: [JOINT anchor-bob]\n"
         "BODY anchor:\n"
         "  name: anchor\n"
         "  mass: 0.0\n"
         "  collision shape: SPHERE\n"
         "  collision geometry: {radius: 0.01}\n"
         "  location: {position: {x: 0, y: 0, z: 2}}\n"
         "BODY bob:\n"
         "  name: bob\n"
         "  mass: "
      << mass
      << "\n"
         "  collision shape: SPHERE\n"
         "  collision geometry: {radius: "
      << radius
      << "}\n"
         "  damping: {linear: 0, angular: 0}\n"
         "  location:\n"
         "    position: {x: 0, y: "
      << length * std::sin(theta0) << ", z: " << 2.0 - length * std::cos(theta0)
      << "}\n"
         "    orientation: {r: "
      << theta0
      << ", p: 0, y: 0}\n"
         "JOINT anchor-bob:\n"
         "  name: anchor-bob\n"
         "  parent: BODY anchor\n"
         "  child: BODY bob\n"
         "  parent pivot: {x: 0, y: 0, z: 0}\n"
         "  parent axis: {x: 1, y: 0, z: 0}\n"
         "  child pivot: {x: 0, y: 0, z: "
      << length
      << "}\n"
         "  child axis: {x: 1, y: 0, z: 0}\n"
         "  type: revolute\n";
  test_support::TempDir dir;
  auto sim = test_support::simulate({dir.write("pendulum.yaml", adf.str())});
  auto& world = *sim->world;
  auto& joint = world.joint("anchor-bob");
  ASSERT_NEAR(joint.position(), theta0, 1e-9);

  // Upward zero crossings of the joint angle, linearly interpolated between steps.
  std::vector<double> crossings;
  double previous = joint.position();
  while (world.time() < 20.0) {
    world.step();
    const double now = joint.position();
    if (previous < 0.0 && now >= 0.0) {
      crossings.push_back(world.time() - world.stepSize() * now / (now - previous));
    }
    previous = now;
  }
  ASSERT_GE(crossings.size(), 8u);
  const double measured = (crossings.back() - crossings.front()) / double(crossings.size() - 1);
  const double pivot_inertia = 0.4 * mass * radius * radius + mass * length * length;
  const double theory = 2.0 * M_PI * std::sqrt(pivot_inertia / (mass * g * length));
  RecordProperty("period_error_percent", std::to_string(100.0 * (measured - theory) / theory));
  EXPECT_NEAR(measured, theory, 0.01 * theory);
  EXPECT_TRUE(world.isFinite());
}

}  // namespace
