#pragma once
// How much of the commanded motion reached the physical robot: its servo_jr subscriber keeps
// one message, so now and then an increment is lost before its control loop sees it
// (bridge::ServoLimits::servo_jr_delivered). Measured by comparing the robot's logged joint
// setpoints with a twin's that received every increment of the same inputs from the same start.

#include <vector>

#include "analysis/actuator_signals.hpp"

namespace calibration {

/// The median, over the trials and the moving positioning joints (shoulder, elbow, insertion of
/// both arms), of the least-squares slope of the robot's setpoint displacement (jpos_d from its
/// first row) on the twin's. `twin[i]` replays `physical[i]` from its start; in 0.5..1.
double measureServoDelivery(const std::vector<analysis::ActuatorTrace>& twin,
                            const std::vector<analysis::ActuatorTrace>& physical);

}  // namespace calibration
