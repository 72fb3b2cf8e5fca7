#pragma once
// Our Raven-II arm as a model draft: design/arm_design.hpp's values around the kinematic chain of
// a platform profile.

#include "model_draft.hpp"
#include "raven/arm_kinematics.hpp"
#include "raven/design/arm_design.hpp"

namespace raven::model {

using design::ArmDesign;

/// The arm `arm` of `profile` as a model: a static mount and seven moving bodies placed at the
/// DH frames of the profile's home pose, so that body poses are the kinematics' frames.
ModelDraft designArm(const PlatformProfile& profile, Arm arm, const ArmDesign& design = {});

}  // namespace raven::model
