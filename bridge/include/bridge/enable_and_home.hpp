#pragma once
// Bringing a Raven-II to ready the way an operator does: enable it, send the robot's own
// `home`, and let platform time pass until it reports enabled and homed.

#include <functional>

#include "bridge/raven_platform.hpp"

namespace bridge {

/// Enables `robot` (unless it is) and homes it, advancing 10 ms at a time. Returns at once when
/// it is already ready. Throws std::runtime_error naming the state reached when `timeout`
/// seconds of platform time pass first, or when `keep_going` (if given) returns false.
void enableAndHome(RavenPlatform& robot, double timeout,
                   const std::function<bool()>& keep_going = {});

}  // namespace bridge
