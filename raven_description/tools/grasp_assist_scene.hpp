#pragma once
// The grasp assist as AMBF builds such things (SRC grasps its needle so): on each jaw a proximity
// sensor looking out of its gripping face and a constraint actuator, in a model of their own that
// the peg-transfer scene loads after the arms only when the assist is asked for.

#include <filesystem>

#include "arm_design.hpp"
#include "raven/platform_profile.hpp"

namespace raven::model {

/// Writes `file`: for each arm and jaw, SENSOR <arm>_<jaw>_sensor (rays from just inside the
/// jaw's face out to `reach` beyond it, over its length and thickness) and ACTUATOR
/// <arm>_<jaw>_gripper, both on BODY /raven2/<arm>/<jaw>_link.
void writeGraspAssist(const PlatformProfile& profile, const ArmDesign& design, double reach,
                      const std::filesystem::path& file);

}  // namespace raven::model
