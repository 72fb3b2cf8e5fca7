#pragma once
// The Raven-II's control period: r2_control's real-time loop runs at 1 kHz and publishes
// ravenstate every cycle (reference/raven2-ros-interface.md). Every layer that counts robot
// cycles (the servo limits, the twin, its ROS node, the controller's command rate) reads it here.

namespace raven {

inline constexpr double kControlCycle = 0.001;               ///< s
inline constexpr double kControlRate = 1.0 / kControlCycle;  ///< cycles per second

}  // namespace raven
