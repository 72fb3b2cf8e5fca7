#include "scenario/robot_observation.hpp"

#include "scenario/observation_layout.hpp"
#include "scenario/ring_view.hpp"

namespace scenario {

namespace {

/// Item `i` of part P of the observation `o` (an arm's), as a fixed-size block.
template <const observation::Part& P>
auto itemOf(Eigen::VectorXd& o, std::size_t i) {
  return o.segment<P.item_size>(observation::item(P, i).start);
}

}  // namespace

void observeRobot(const bridge::RavenPlatform& robot, const controller::ArmPair& targets,
                  Eigen::VectorXd& o) {
  namespace obs = observation;
  for (raven::Arm arm : raven::kArms) {
    const std::size_t a = raven::slot(arm);
    itemOf<obs::kJoints>(o, a) = robot.measuredJs(arm).position;
    itemOf<obs::kTargets>(o, a) = targets[a];
    const Eigen::Isometry3d tool = robot.measuredCp(arm).pose;
    const Eigen::Quaterniond q(tool.linear());
    auto pose = itemOf<obs::kToolPoses>(o, a);
    pose.head<3>() = tool.translation();
    pose.tail<4>() << q.w(), q.x(), q.y(), q.z();
    const auto forces = robot.measuredCf(arm);
    auto wrench = itemOf<obs::kWrenches>(o, a);
    wrench.head<3>() = forces ? forces->force : Eigen::Vector3d::Zero();
    wrench.tail<3>() = forces ? forces->torque : Eigen::Vector3d::Zero();
  }
}

int ringsPlaced(const bridge::ScenePerception& scene, const PegLayout& layout) {
  int placed = 0;
  for (const RingJob& job : layout.jobs) {
    if (restsOn(RingView(scene.sight(job.ring), layout.ring), job.to, layout.geometry)) ++placed;
  }
  return placed;
}

}  // namespace scenario
