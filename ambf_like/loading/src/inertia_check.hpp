#pragma once
// Whether principal moments of inertia can be a rigid body's, for both model readers.

#include <Eigen/Core>
#include <optional>
#include <string>

namespace ambf_like::detail {

/// How far a moment may exceed the sum of the other two, as a share of the largest: a file's
/// rounding (two significant digits on a thin plate's moments reach about 5 %), not a body.
inline constexpr double kInertiaRoundingSlack = 0.1;

/// Why principal moments `moments` (kg m^2) cannot be a rigid body's, or nothing. Every body's
/// moments obey the triangle inequality, each at most the sum of the other two (I_x + I_y - I_z
/// = 2 * integral of z^2 dm >= 0 in the principal frame); a body that breaks it by more than the
/// rounding slack turns under a torque faster than any mass can, and the solver diverges.
std::optional<std::string> impossibleInertia(const Eigen::Vector3d& moments);

}  // namespace ambf_like::detail
