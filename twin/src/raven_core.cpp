#include "twin/raven_core.hpp"

#include <spdlog/spdlog.h>

#include <cmath>
#include <sstream>

#include "bridge/command_checks.hpp"
#include "bridge/overloaded.hpp"

namespace twin {

namespace {

using raven::kJointCount;

std::string jointName(int i) {
  return std::string(raven::kJointNames[static_cast<std::size_t>(i)]);
}

}  // namespace

RavenCore::RavenCore(raven::PlatformProfile profile, ServoLimits limits, const ArmPair& measured)
    : profile_(std::move(profile)),
      limits_(limits),
      reporting_{raven::ArmKinematics(profile_.reportingArm(Arm::Left), profile_.limits),
                 raven::ArmKinematics(profile_.reportingArm(Arm::Right), profile_.limits)},
      measured_(measured) {
  for (Arm arm : raven::kArms) {
    const ArmJoints& q = measured[slot(arm)];
    arms_[slot(arm)] = ArmMotion{q, q, q, std::nullopt, 0.0};
  }
}

CommandResult RavenCore::apply(const PlatformCommand& command) {
  CommandResult result = std::visit(
      bridge::Overloaded{
          [&](StateCommand c) { return applyState(c); },
          [&](const ServoJp& c) { return servoTo(c.arm, c.position); },
          [&](const ServoJr& c) {
            return servoTo(c.arm, servoBase(c.arm) + limits_.servo_jr_delivered * c.increment);
          },
          [&](const MoveJp& c) { return moveTo(c.arm, c.goal); },
          [&](const ServoCp& c) { return servoToPose(c.arm, c.pose); },
          [&](const ServoCr& c) {
            const Eigen::Isometry3d from = reportedPose(c.arm, servoBase(c.arm));
            Eigen::Isometry3d to = Eigen::Isometry3d::Identity();
            to.translation() = from.translation() + c.increment.translation();
            to.linear() = c.increment.linear() * from.linear();
            return servoToPose(c.arm, to);
          },
          [&](const ServoJawJp& c) {
            return servoTo(c.arm, raven::withJawOpening(servoBase(c.arm), c.opening));
          },
          [&](const ServoJawJr& c) {
            ArmJoints q = servoBase(c.arm);
            q(raven::kJaw1) += 0.5 * c.increment;
            q(raven::kJaw2) += 0.5 * c.increment;
            return servoTo(c.arm, q);
          },
      },
      command);
  if (!result || !result.note.empty()) {
    const std::string message =
        (result ? "took " : "refused ") + describe(command) + ": " + result.note;
    log_.warn(ThrottledLog::kindOf(message), message, time());
  }
  return result;
}

CommandResult RavenCore::applyState(StateCommand command) {
  CommandResult result = machine_.apply(command);
  if (!result) return result;
  switch (command) {
    case StateCommand::Enable:  // the robot takes over from where the arms are
      for (Arm arm : raven::kArms) {
        const ArmJoints& q = measured_[slot(arm)];
        arms_[slot(arm)] = ArmMotion{q, q, q, std::nullopt, 0.0};
      }
      break;
    case StateCommand::Home:
      for (Arm arm : raven::kArms) {
        ArmJoints home = profile_.robotHome();
        clampToLimits(home);
        startMove(arm, home);
      }
      break;
    case StateCommand::Disable:
    case StateCommand::Pause:
    case StateCommand::Unhome:
      holdAll();
      break;
    case StateCommand::Resume:
      break;
  }
  return result;
}

std::optional<std::string> RavenCore::motionRefusal() const {
  const OperatingStatus& s = machine_.status();
  if (s.state != OperatingState::Enabled) {
    return "the robot is " + std::string(wireName(s.state)) + "; nothing moved";
  }
  if (!s.is_homed) return "the robot is not homed (send 'home' first); nothing moved";
  return std::nullopt;
}

ArmJoints RavenCore::servoBase(Arm arm) const {
  const ArmMotion& m = arms_[slot(arm)];
  return m.move ? m.setpoint : m.goal;
}

std::string RavenCore::clampToLimits(ArmJoints& q) const {
  const ArmJoints before = q;
  q = q.cwiseMax(profile_.limits.low).cwiseMin(profile_.limits.high);
  if (q == before) return {};  // every command in range: no stream built on the command path
  std::ostringstream note;
  for (int i = 0; i < kJointCount; ++i) {
    if (q(i) != before(i)) {
      note << (note.tellp() > 0 ? ", " : "clamped ") << jointName(i) << " to " << q(i) << " "
           << bridge::jointUnit(i);
    }
  }
  return note.str();
}

CommandResult RavenCore::servoTo(Arm arm, const ArmJoints& goal, bool check_jump) {
  if (auto why = motionRefusal()) return CommandResult::refused(*why);
  if (auto why = bridge::nonFiniteJoint(goal))
    return CommandResult::refused(*why + "; nothing moved");
  ArmMotion& m = arms_[slot(arm)];
  if (check_jump) {
    if (auto why = jumpRefusal(goal, m.setpoint, limits_)) {
      return CommandResult::refused(*why + "; nothing moved");
    }
  }
  ArmJoints clamped = goal;
  std::string note = clampToLimits(clamped);
  m.move.reset();
  m.goal = clamped;
  ++commands_taken_;
  if (machine_.status().is_busy && !arms_[slot(raven::other(arm))].move) machine_.setBusy(false);
  return CommandResult::ok(std::move(note));
}

CommandResult RavenCore::servoToPose(Arm arm, const Eigen::Isometry3d& pose) {
  if (auto why = motionRefusal()) return CommandResult::refused(*why);
  if (!pose.matrix().allFinite()) {
    return CommandResult::refused("the pose holds NaN or infinite values; nothing moved");
  }
  const Eigen::Matrix3d r = pose.linear();
  if (!(r.transpose() * r).isIdentity(1e-6) || r.determinant() < 0.0) {
    return CommandResult::refused("the orientation is not a rotation; nothing moved");
  }
  const ArmJoints base = servoBase(arm);
  const double step = (pose.translation() - reportedPose(arm, base).translation()).norm();
  if (step > limits_.cartesian_step) {
    std::ostringstream why;
    why << "the tool would jump " << step << " m, more than " << limits_.cartesian_step
        << " m; nothing moved";
    return CommandResult::refused(why.str());
  }
  const auto solution =
      reporting_[slot(arm)].inverse(pose, base(raven::kJaw1) + base(raven::kJaw2), base);
  if (!solution.ok) {
    return CommandResult::refused("no inverse-kinematics solution near the current joints");
  }
  return servoTo(arm, solution.joints, /*check_jump=*/false);
}

CommandResult RavenCore::moveTo(Arm arm, const ArmJoints& goal) {
  if (auto why = motionRefusal()) return CommandResult::refused(*why);
  if (auto why = bridge::nonFiniteJoint(goal))
    return CommandResult::refused(*why + "; nothing moved");
  ArmJoints clamped = goal;
  std::string note = clampToLimits(clamped);
  startMove(arm, clamped);
  ++commands_taken_;
  return CommandResult::ok(std::move(note));
}

void RavenCore::startMove(Arm arm, const ArmJoints& goal) {
  ArmMotion& m = arms_[slot(arm)];
  m.move.emplace(m.setpoint, goal, limits_.moveVelocity(), limits_.move_acceleration);
  m.move_start = time();
  m.goal = goal;
  machine_.setBusy(true);
}

void RavenCore::holdAll() {
  for (ArmMotion& m : arms_) {
    m.move.reset();
    m.goal = m.setpoint;
  }
  machine_.setBusy(false);
}

void RavenCore::fault(const std::string& why) {
  spdlog::error("robot fault: {}", why);
  machine_.fault(why);
  holdAll();
}

void RavenCore::cycle(const ArmPair& measured) {
  measured_ = measured;
  ++cycles_;
  bool moving = false;
  for (ArmMotion& m : arms_) {
    m.previous = m.setpoint;
    if (m.move) {
      const double t = time() - m.move_start;
      m.setpoint = m.move->at(t);
      if (t >= m.move->duration()) {
        m.move.reset();
      } else {
        moving = true;
      }
      continue;
    }
    for (int i = 0; i < kJointCount; ++i) {
      const double left = m.goal(i) - m.setpoint(i);
      const double clamp = limits_.per_cycle(i);
      m.setpoint(i) =
          std::abs(left) <= clamp ? m.goal(i) : m.setpoint(i) + std::copysign(clamp, left);
    }
  }
  if (machine_.status().is_busy && !moving) {
    if (machine_.homing()) {
      machine_.homingDone();
    } else {
      machine_.setBusy(false);
    }
  }
}

ArmJoints RavenCore::setpointVelocity(Arm arm) const {
  const ArmMotion& m = arms_[slot(arm)];
  return (m.setpoint - m.previous) / limits_.cycle;
}

Eigen::Isometry3d RavenCore::reportedPose(Arm arm, const ArmJoints& q) const {
  return reporting_[slot(arm)].toolPose(q);
}

}  // namespace twin
