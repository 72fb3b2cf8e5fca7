#pragma once
// The peg transfer's observation (observation_layout.hpp) from what any Raven-II reports and a
// perception sees: the one definition the in-process environment and a robot over ROS share,
// with the judge of a placed ring.

#include <Eigen/Core>

#include "bridge/raven_platform.hpp"
#include "bridge/scene_perception.hpp"
#include "controller/velocity_cap.hpp"
#include "scenario/peg_layout.hpp"

namespace scenario {

/// Writes the robot's part of observation `o` (kSize values): measured joints, the controller's
/// targets, the tool poses (measured_cp) and the grasp wrenches (measured_cf, zero where the
/// robot reports none: a physical Raven-II has no grasp sensor).
void observeRobot(const bridge::RavenPlatform& robot, const controller::ArmPair& targets,
                  Eigen::VectorXd& o);

/// Rings resting threaded on their target posts, as `scene` sees them.
int ringsPlaced(const bridge::ScenePerception& scene, const PegLayout& layout);

}  // namespace scenario
