#pragma once
// What a soft peg is doing, read from its nodes: where it is, whether it rests on a post,
// whether it is still whole (finite, its volume near its rest volume).

#include <Eigen/Core>

#include "ambf_like/soft_body.hpp"

namespace scenario {

/// The scene's geometry a check needs (its design values).
struct PegGeometry {
  double board_top = -0.205;
  double lifted = 0.005;  ///< a ring whose lowest node is this far above the board is off it

  bool offTheBoard(double bottom) const { return bottom > board_top + lifted; }
};

/// A snapshot of one soft peg.
struct PegState {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< mean of the nodes
  double bottom = 0.0;                               ///< lowest node z
  double volume = 0.0;                               ///< enclosed by its faces (m^3)
  double speed = 0.0;                                ///< fastest node (m/s)
  bool finite = true;
};

PegState inspect(const ambf_like::SoftBody& peg);

/// The widest angle (rad) between the bearings of the peg's nodes seen from the vertical line
/// through `axis`: a few degrees when the ring is threaded on that line, above pi when it is not.
double bearingGap(const ambf_like::SoftBody& peg, const Eigen::Vector2d& axis);

/// Threaded on the post (no bearing gap as wide as 90 degrees) and down on the board (its
/// lowest node within `tolerance` of the board top), with every node finite.
bool restsOn(const ambf_like::SoftBody& peg, const Eigen::Vector2d& post, const PegGeometry& g,
             double tolerance = 0.001);

}  // namespace scenario
