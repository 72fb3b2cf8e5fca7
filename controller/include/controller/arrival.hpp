#pragma once
// When a scripted move has arrived on a robot whose arm stops short of its setpoint: the Raven-II's
// shoulder, elbow and insertion have no integrator, so friction and the weight the firmware
// misjudges hold them up to about a millimetre off, and the tool's joints take their integrators'
// time to come onto a command. A person at the pad watches the tool and makes the difference up.

#include <optional>
#include <vector>

#include "raven/arm_kinematics.hpp"

namespace controller {

/// What a scripted move waits for at its end, per arm.
struct Arrival {
  /// The wrist's axis (where the shoulder, elbow and insertion put the tool) this near where the
  /// targets put it has arrived (m).
  double tolerance = 1e-4;
  /// It has stopped where it goes once it moved slower than this over `still_window` (m/s).
  double still_speed = 1e-3;
  /// A tool joint (roll, wrist, jaws) this near its target has arrived (rad) ...
  double tool_tolerance = 0.01;
  /// ... or once it turned slower than this over `still_window` (rad/s).
  double tool_still_speed = 0.1;
  double still_window = 0.02;  ///< s
  /// How far the shoulder's, elbow's and insertion's setpoints may put the wrist past where
  /// the targets put it, to make a stopped arm's shortfall up by half of it each time it stopped
  /// (m; 0: none; the tool's joints have integrators and are only waited for).
  double most_make_up = 0.0;
  double most_wait = 0.5;  ///< the longest a move waits at its end (s)
};

/// One arm's arrival at its targets, watched a command period at a time: whether it has
/// arrived, and what its setpoints make up meanwhile.
class ArmArrival {
 public:
  /// `most_per_step`: the caps' step a period; `most_lead`: the following limit's lead, if any.
  ArmArrival(const Arrival& arrival, raven::ArmKinematics kinematics,
             const raven::ArmJoints& most_per_step, std::optional<raven::ArmJoints> most_lead,
             double period);

  /// One period, the arm at `measured` with its `targets` and `setpoint`: true once it has
  /// arrived or stopped where it goes; else `make_up` (zero or not) goes onto its setpoint.
  bool arrived(const raven::ArmJoints& targets, const raven::ArmJoints& measured,
               const raven::ArmJoints& setpoint, raven::ArmJoints& make_up);

 private:
  /// True when the last `window_` periods moved joint `i` less than `speed` allows.
  bool stopped(int i, double speed) const;
  /// The tool joints: each on its target or stopped.
  bool toolSettled(const raven::ArmJoints& targets) const;
  /// Half the wrist's shortfall on top of what `setpoint` makes up already, within the bound and
  /// the following limit: the positioning joints' change.
  raven::ArmJoints nextMakeUp(const raven::ArmJoints& targets,
                              const raven::ArmJoints& setpoint) const;

  Arrival arrival_;
  raven::ArmKinematics kinematics_;
  raven::ArmJoints most_per_step_;
  std::optional<raven::ArmJoints> most_lead_;
  std::size_t window_;                                   ///< periods in still_window
  double still_travel_;                                  ///< s: still_window in whole periods
  std::vector<raven::ArmJoints> seen_;                   ///< measured, a period apart
  std::size_t since_make_up_ = 0;                        ///< periods
  raven::ArmJoints pending_ = raven::ArmJoints::Zero();  ///< make-up still to send
};

}  // namespace controller
