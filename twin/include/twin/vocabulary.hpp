#pragma once
// The names the twin is written in: the description's arms and joints and the platform
// interface's commands, states and limits, declared once for namespace twin.

#include "bridge/command_result.hpp"
#include "bridge/grasper_forces.hpp"
#include "bridge/joint_trajectory.hpp"
#include "bridge/operating_state.hpp"
#include "bridge/platform_command.hpp"
#include "bridge/raven_platform.hpp"
#include "bridge/raven_state.hpp"
#include "bridge/servo_limits.hpp"
#include "bridge/throttled_log.hpp"
#include "bridge/wall_pacer.hpp"
#include "raven/arm.hpp"

namespace twin {

using raven::Arm;
using raven::ArmJoints;
using raven::armName;
using raven::index;
using raven::kArms;
using raven::kJointCount;
using raven::kJointNames;
using raven::other;

using bridge::ClockKind;
using bridge::CommandResult;
using bridge::GrasperForces;
using bridge::JawForces;
using bridge::JointSample;
using bridge::JointTrajectory;
using bridge::MoveJp;
using bridge::OperatingState;
using bridge::OperatingStateMachine;
using bridge::OperatingStatus;
using bridge::PlatformCommand;
using bridge::PoseSample;
using bridge::RavenPlatform;
using bridge::RavenStateSnapshot;
using bridge::ServoCp;
using bridge::ServoCr;
using bridge::ServoJawJp;
using bridge::ServoJawJr;
using bridge::ServoJp;
using bridge::ServoJr;
using bridge::ServoLimits;
using bridge::StateCommand;
using bridge::ThrottledLog;
using bridge::WallPacer;

}  // namespace twin
