// The wide-range motion task D_II: both arms trace the requested rectangle in XY under M2 from
// pad readings, at constant height, with the readings and the robot state recorded.

#include "scenario/rectangle_task.hpp"

#include <gtest/gtest.h>

#include "recording/recording_io.hpp"
#include "test_files.hpp"

namespace {

using raven::Arm;

TEST(RectangleTask, BothArmsTraceTheRectangleAtConstantHeightAndItIsRecorded) {
  test_support::TempDir dir;
  scenario::RectangleOptions options;
  options.actuation = common::ActuationKind::Ideal;  // the mapping's geometry, to 0.1-0.3 mm
  options.rs_file = dir.path() / "d2_rs.csv";
  options.ci_file = dir.path() / "d2_ci.csv";
  const auto result = scenario::runRectangle(options);

  const auto inputs = scenario::rectangleInputs(options, controller::MappingConstants{});
  EXPECT_EQ(result.iterations, inputs.size());
  EXPECT_FALSE(result.timed_out);
  EXPECT_EQ(result.refused, 0u);
  EXPECT_EQ(result.clamped, 0u);
  for (Arm arm : raven::kArms) {
    const auto& path = result.wrist_path[raven::slot(arm)];
    const Eigen::Vector3d extent = result.extent(arm);
    EXPECT_NEAR(extent.x(), options.width, 2e-4) << raven::armName(arm);
    EXPECT_NEAR(extent.y(), options.depth, 2e-4) << raven::armName(arm);
    EXPECT_LT(extent.z(), 1e-4) << raven::armName(arm);
    // The corners in order: +x, then +y, then back; the end is the start.
    const Eigen::Vector3d start = path.front();
    const std::size_t edge_x = 60, edge_y = 40, dwell = 25;  // 0.5 mm per reading
    ASSERT_EQ(path.size(), result.iterations + 1);           // the homed pose, then one per reading
    const Eigen::Vector3d c1 = path[edge_x + dwell] - start;
    const Eigen::Vector3d c2 = path[edge_x + edge_y + 2 * dwell] - start;
    EXPECT_NEAR(c1.x(), options.width, 3e-4);
    EXPECT_NEAR(c1.y(), 0.0, 3e-4);
    EXPECT_NEAR(c2.x(), options.width, 3e-4);
    EXPECT_NEAR(c2.y(), options.depth, 3e-4);
    EXPECT_LT((path.back() - start).norm(), 3e-4) << raven::armName(arm);
  }

  EXPECT_EQ(recording::readCi(options.ci_file), inputs);
  const auto rs = recording::readRs(options.rs_file);
  EXPECT_EQ(rs.rows.size(), result.iterations);
}

TEST(RectangleTask, RefusesADeflectionInsideTheDeadzoneOrABadSize) {
  scenario::RectangleOptions options;
  options.deflection = 0.1;
  EXPECT_THROW(scenario::rectangleInputs(options, {}), std::invalid_argument);
  options.deflection = 1.0;
  options.width = std::nan("");
  EXPECT_THROW(scenario::rectangleInputs(options, {}), std::invalid_argument);
  options.width = -0.01;
  EXPECT_THROW(scenario::runRectangle(options), std::invalid_argument);
}

TEST(RectangleTask, ASmallerDeflectionTakesMoreReadingsForTheSameRectangle) {
  scenario::RectangleOptions options;
  const auto full = scenario::rectangleInputs(options, {});
  options.deflection = 0.5;
  const auto half = scenario::rectangleInputs(options, {});
  EXPECT_EQ(full.size(), 200u + 4 * 25u);
  EXPECT_EQ(half.size(), 400u + 4 * 25u);
}

}  // namespace
