#pragma once
// A ring as a ScenePerception sees it (a pose) with its design dimensions: how high it
// reaches, where its wall is, whether it is threaded on a post and resting on the board. What
// the scripted operator and the run's judge read; the same on every perception backend.

#include <Eigen/Geometry>
#include <optional>

#include "bridge/scene_perception.hpp"

namespace scenario {

/// A ring's size (raven/design/peg_scene_design.hpp's ring values).
struct RingDimensions {
  double major_radius = 0.0;     ///< centre line of the tube
  double tube_half_width = 0.0;  ///< radially
  double half_height = 0.0;      ///< along the ring's axis
  /// Stations around the ring (the design's ring_segments): its centre line is a polygon
  /// with a vertex at each, the first on the ring frame's x axis; 0 for a smooth ring.
  int stations = 0;
  /// Stations around the tube's section, as the ring is drawn (ring_tube_segments); 0: smooth.
  int tube_stations = 0;

  double innerRadius() const { return major_radius - tube_half_width; }
};

/// The board and posts a check needs.
struct BoardGeometry {
  double board_top = 0.0;    ///< z of the board's surface (m)
  double post_radius = 0.0;  ///< the posts' radius (m)
  double post_height = 0.0;  ///< how far the posts stand above the board (m)
  double lifted = 0.005;     ///< a ring whose bottom is this far above the board is off it

  bool offTheBoard(double bottom) const { return bottom > board_top + lifted; }
};

/// One ring as seen: its frame (the ring's axis along the frame's z, its origin the ring's
/// centre) and its dimensions.
struct RingView {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  RingDimensions size;
  std::optional<double> volume_ratio;  ///< when the perception can tell

  RingView(const bridge::Sighting& sighting, const RingDimensions& dimensions)
      : pose(sighting.pose), size(dimensions), volume_ratio(sighting.volume_ratio) {}

  Eigen::Vector3d centre() const { return pose.translation(); }
  Eigen::Vector3d axis() const { return pose.linear().col(2); }
  bool finite() const { return pose.matrix().allFinite(); }
  /// The lowest and highest z of its surface, tilted as seen.
  double bottom() const;
  double top() const;
  /// The point of its centre line on the side `toward` (a horizontal direction) points to: the
  /// station nearest that side (a smooth ring: that side's point).
  Eigen::Vector3d stationToward(const Eigen::Vector2d& toward) const;
  /// How far from its centre the vertical line through `post` crosses its mid-plane (m;
  /// infinite when the ring stands on edge).
  double postOffset(const Eigen::Vector2d& post) const;
  /// The vertical post at `post` passes through its hole.
  bool threadedOn(const Eigen::Vector2d& post) const {
    return postOffset(post) < size.innerRadius();
  }
};

/// Threaded on the post at `post` and down on the board (its bottom within `tolerance` of the
/// board top).
bool restsOn(const RingView& ring, const Eigen::Vector2d& post, const BoardGeometry& geometry,
             double tolerance = 0.001);

}  // namespace scenario
