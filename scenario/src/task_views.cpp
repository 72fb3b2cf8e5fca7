#include "scenario/task_views.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace scenario {

namespace {

/// Looking from the start row towards the target row, from above: both rows and each ring's
/// hole stay visible, and a ring on a target post sits behind the empty start post.
constexpr double kFromFront = -std::numbers::pi / 2;

std::size_t bodyIndex(const ambf_like::World& world, const std::string& name) {
  for (std::size_t i = 0; i < world.bodyCount(); ++i) {
    if (world.body(i).qualifiedName() == name) return i;
  }
  throw std::invalid_argument("peg-transfer views: no body " + name + " to follow");
}

viewer::View grasperView(const ambf_like::World& world, raven::Arm arm) {
  viewer::Camera c;
  c.target = Eigen::Vector3d::Zero();  // the jaw axis
  c.yaw = kFromFront + (arm == raven::Arm::Left ? 0.5 : -0.5);
  c.pitch = 0.45;
  c.distance = 0.07;
  return {std::string("grasper-") + std::string(raven::armName(arm)), c,
          bodyIndex(world, "/raven2/" + std::string(raven::armName(arm)) + "/jaw1_link")};
}

}  // namespace

viewer::Camera taskCamera(const PegLayout& layout, raven::Arm arm) {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  const auto jobs = layout.jobsOf(arm);
  for (const RingJob& job : jobs) centre += (job.from + job.to) / 2.0;
  centre /= static_cast<double>(jobs.size());
  viewer::Camera c;
  c.target = Eigen::Vector3d(centre.x(), centre.y(),
                             layout.geometry.board_top + 0.6 * layout.geometry.post_height);
  c.yaw = kFromFront;
  c.pitch = 0.75;
  c.distance = 0.20;
  return c;
}

std::vector<std::string> pegTransferViewNames() {
  return {"overview", "left-task", "right-task", "grasper-left", "grasper-right"};
}

std::vector<viewer::View> pegTransferViews(const ambf_like::World& world, const PegLayout& layout) {
  viewer::Camera overview;
  overview.target = Eigen::Vector3d(0.0, 0.079, layout.geometry.board_top + 0.08);
  overview.yaw = kFromFront;
  overview.pitch = 0.55;
  overview.distance = 1.05;
  return {{"overview", overview, std::nullopt},
          {"left-task", taskCamera(layout, raven::Arm::Left), std::nullopt},
          {"right-task", taskCamera(layout, raven::Arm::Right), std::nullopt},
          grasperView(world, raven::Arm::Left),
          grasperView(world, raven::Arm::Right)};
}

}  // namespace scenario
