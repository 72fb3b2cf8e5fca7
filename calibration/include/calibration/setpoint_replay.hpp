#pragma once
// The twin's actuation driven by a recording's own joint setpoints (jpos_d, interpolated to the
// robot's 1 ms cycle) from the state the recording began in: the motor-level model alone,
// without the controller or the simulator, in milliseconds. What the actuation fit compares.

#include "analysis/actuator_signals.hpp"
#include "twin/arm_drive.hpp"
#include "twin/motor_actuation.hpp"
#include "twin/recorded_start.hpp"

namespace calibration {

/// Where `trace` began (twin::recordedStart of its first row): the motors and the integrators
/// that make its Tau.
twin::RecordedStart traceStart(const analysis::ActuatorTrace& trace);

/// The twin's actuator signals at the recording's row times (in the recording's units).
analysis::ActuatorTrace replaySetpoints(const analysis::ActuatorTrace& recording,
                                        const twin::ArmsMechanics& mechanics);

}  // namespace calibration
