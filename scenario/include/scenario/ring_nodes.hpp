#pragma once
// What a simulated soft ring's nodes say beyond its pose: their lowest point, fastest speed and
// whether they are all finite (a study's view inside the simulator; tasks see rings through
// ring_view.hpp).

#include <Eigen/Core>

#include "ambf_like/soft_body.hpp"

namespace scenario {

/// A snapshot of one soft ring's nodes.
struct RingNodes {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< mean of the nodes
  double bottom = 0.0;                               ///< lowest node z
  double speed = 0.0;                                ///< fastest node (m/s)
  bool finite = true;
};

RingNodes inspect(const ambf_like::SoftBody& ring);

}  // namespace scenario
