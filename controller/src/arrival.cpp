#include "controller/arrival.hpp"

#include <algorithm>
#include <cmath>

namespace controller {

ArmArrival::ArmArrival(const Arrival& arrival, raven::ArmKinematics kinematics,
                       const raven::ArmJoints& most_per_step,
                       std::optional<raven::ArmJoints> most_lead, double period)
    : arrival_(arrival),
      kinematics_(std::move(kinematics)),
      most_per_step_(most_per_step),
      most_lead_(std::move(most_lead)),
      window_(static_cast<std::size_t>(std::max(1L, std::lround(arrival.still_window / period)))),
      still_travel_(static_cast<double>(window_) * period) {}

bool ArmArrival::stopped(int i, double speed) const {
  return seen_.size() > window_ &&
         std::abs(seen_.back()(i) - seen_[seen_.size() - 1 - window_](i)) <= speed * still_travel_;
}

bool ArmArrival::toolSettled(const raven::ArmJoints& targets) const {
  for (int i = raven::kRoll; i < raven::kJointCount; ++i) {
    if (std::abs(targets(i) - seen_.back()(i)) > arrival_.tool_tolerance &&
        !stopped(i, arrival_.tool_still_speed)) {
      return false;
    }
  }
  return true;
}

raven::ArmJoints ArmArrival::nextMakeUp(const raven::ArmJoints& targets,
                                        const raven::ArmJoints& setpoint) const {
  const raven::ArmJoints& now = seen_.back();
  raven::ArmJoints made_up = setpoint - targets;
  made_up.tail<4>().setZero();  // the tool's joints: the following limit's, not ours
  raven::ArmJoints next = made_up;
  next.head<3>() += 0.5 * (targets - now).head<3>();
  const double reach =
      (kinematics_.wristPoint(targets + next) - kinematics_.wristPoint(targets)).norm();
  if (reach > arrival_.most_make_up) next *= arrival_.most_make_up / reach;
  raven::ArmJoints change = next - made_up;
  if (most_lead_) {  // nor a lead past the following limit
    const raven::ArmJoints lead = setpoint - now;
    for (int i = raven::kShoulder; i <= raven::kInsertion; ++i) {
      const double bound = (*most_lead_)(i);
      const double room = std::max(0.0, bound - std::abs(lead(i)));
      if (change(i) * lead(i) > 0.0) change(i) = std::clamp(change(i), -room, room);
    }
  }
  return change.isZero(1e-6) ? raven::ArmJoints::Zero() : change;
}

bool ArmArrival::arrived(const raven::ArmJoints& targets, const raven::ArmJoints& measured,
                         const raven::ArmJoints& setpoint, raven::ArmJoints& make_up) {
  seen_.push_back(measured);
  make_up.setZero();
  const bool tool = toolSettled(targets);
  // The positioning joints, by where they put the wrist.
  const Eigen::Vector3d wrist = kinematics_.wristPoint(measured);
  if ((kinematics_.wristPoint(targets) - wrist).norm() <= arrival_.tolerance) {
    pending_.setZero();
    return tool;
  }
  if (!pending_.isZero(0.0)) {  // making the last shortfall up, a capped step a period
    make_up = pending_.cwiseMax(-most_per_step_).cwiseMin(most_per_step_);
    pending_ -= make_up;
    since_make_up_ = 0;
    return false;
  }
  // Stopped: moved less than the still speed over the last window since its last make-up (an
  // encoder count a cycle reads as a speed; over an operator's iteration it does not).
  if (++since_make_up_ <= window_ ||
      (wrist - kinematics_.wristPoint(seen_[seen_.size() - 1 - window_])).norm() >
          arrival_.still_speed * still_travel_) {
    return false;  // on its way
  }
  pending_ = nextMakeUp(targets, setpoint);
  return pending_.isZero(0.0) && tool;  // else made up from the next period on
}

}  // namespace controller
