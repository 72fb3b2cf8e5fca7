#pragma once
// Where the outer jaw must close to for a given squeeze of a ring's wall: the grasp is commanded
// as a jaw angle (as the Raven-II's is), so the squeeze, and with it the grip, follows from the
// ring's and the jaws' geometry.

namespace scenario {

/// The wall the jaws pinch, seen in the plane of the jaws: a tube cross-section (an ellipse of
/// half-width `half_width` across the wall and `half_height` up it) whose top is `pivot_above`
/// under the jaw axis, with the inner jaw's face vertical at `gap` from its inner side.
struct PinchedWall {
  double half_width = 0.0;
  double half_height = 0.0;
  double pivot_above = 0.0;
  double gap = 0.0;
  double jaw_length = 0.0;  ///< from the jaw axis to the tips
};

/// How far (m) the outer jaw's face, turned by `angle` (rad) from the inner jaw's, reaches into
/// the wall at its deepest point along the jaw (0 when it does not touch it).
double wallSqueeze(const PinchedWall& wall, double angle);

/// The outer jaw's angle at which it reaches `squeeze` (m) into the wall (bisection on
/// wallSqueeze, which falls as the angle opens).
double squeezingAngle(const PinchedWall& wall, double squeeze);

}  // namespace scenario
