#pragma once
// Whether the two arms can hand a ring over in mid-air: where each arm's tool point can go,
// sampled over its whole joint space within the limits, along the x axis that separates them.

#include <cstdint>
#include <string>

#include "raven/platform_profile.hpp"

namespace scenario {

/// How close the two arms' tool points can come along x in the controller's common frame.
struct HandoverReach {
  std::size_t samples_per_arm = 0;
  double left_min_x = 0.0;   ///< the left tool point's smallest x (m)
  double right_max_x = 0.0;  ///< the right tool point's largest x (m)

  /// The clearance between the two workspaces along x (m); below zero they overlap.
  double gap() const { return left_min_x - right_max_x; }
  /// A hand-over needs the grasper tips to meet: the workspaces closer than two jaw lengths.
  bool possible(double jaw_length) const { return gap() < 2.0 * jaw_length; }
  /// One sentence with the numbers, for a summary.
  std::string explain(double jaw_length) const;
};

/// Samples `samples` joint vectors per arm uniformly within `profile`'s limits (seeded).
HandoverReach measureHandoverReach(const raven::PlatformProfile& profile, std::size_t samples,
                                   std::uint64_t seed = 1);

}  // namespace scenario
