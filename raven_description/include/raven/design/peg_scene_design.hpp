#pragma once
// The peg-transfer scene's design: a board with twelve posts (six in each arm's reach) and six
// tall soft rings resting on the start posts. The one source of these values: the model
// generator writes the scene's ADF files from them, and the scenario's layout reads them.

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstddef>

namespace raven::design {

/// Dimensions and placement of the board, the posts and the rings (our own design).
struct PegSceneDesign {
  double board_top = -0.205;  ///< z of the board surface in {B} (m)
  Eigen::Vector3d board_size{0.90, 0.12, 0.01};
  /// The table under the board, solid below it for collisions only: Bullet tests a soft body's
  /// node against a solid once a step, and pushes one past the solid's mid-plane out by its far
  /// side, so a node faster than half the depth per 1 ms step passes through. The 10 mm board
  /// alone lets through a ring falling at 6 m/s (a ring snapping free of a post it was pulled
  /// against reaches that); with the table 25 m/s.
  double table_depth = 0.04;
  /// The room's floor, a table's height under the board's top, for collisions only: a ring carried
  /// off the board's edge lands there instead of falling without end. The table cannot reach past
  /// the board: the arms' elbow links hang below the board's top in front of it.
  double floor_below_board = 0.75;
  Eigen::Vector3d floor_size{4.0, 4.0, 0.1};
  Eigen::Vector2d board_centre{0.0, 0.08};
  double post_radius = 0.0025;
  double post_height = 0.022;
  /// Post positions (x, y) in {B}, six per arm: a start row (y = 0.058, where the rings begin)
  /// and a target row (y = 0.100), in the part of each arm's workspace where the grasper can
  /// point straight down at every side of a ring (about 8 x 6 cm under its remote centre). The
  /// two arms' workspaces do not overlap (their remote centres are 0.6 m apart).
  std::array<Eigen::Vector2d, 12> posts{
      Eigen::Vector2d(0.266, 0.058),  Eigen::Vector2d(0.300, 0.058),
      Eigen::Vector2d(0.334, 0.058),  Eigen::Vector2d(-0.266, 0.058),
      Eigen::Vector2d(-0.300, 0.058), Eigen::Vector2d(-0.334, 0.058),
      Eigen::Vector2d(0.266, 0.100),  Eigen::Vector2d(0.300, 0.100),
      Eigen::Vector2d(0.334, 0.100),  Eigen::Vector2d(-0.266, 0.100),
      Eigen::Vector2d(-0.300, 0.100), Eigen::Vector2d(-0.334, 0.100)};
  /// The rings start on the first six posts (the start rows).
  std::size_t ring_count = 6;
  /// A tall soft ring: centre line radius, and the tube's half-width and half-height, so the
  /// grasper can pinch its wall well above the board while the post passes through its hole.
  double ring_major_radius = 0.008;
  double ring_minor_radius = 0.002;
  double ring_half_height = 0.005;
  int ring_segments = 16;      ///< 144 nodes: a station every 3.1 mm around the ring
  int ring_tube_segments = 8;  ///< around the tube, about its axis node
  /// The ring's silicone: Shore 30A (a casting silicone's), whose modulus by Ruess' relation
  /// log10(E / MPa) = 0.0235 S - 0.6403 is 1.16 MPa; silicone rubbers' Poisson's ratio and
  /// density (../shared/reference/soft-materials.md).
  double ring_youngs_modulus = 1.0e6 * std::pow(10.0, 0.0235 * 30.0 - 0.6403);
  double ring_poissons_ratio = 0.45;
  double ring_density = 1100.0;  ///< kg/m^3
  double ring_margin = 0.0005;
};

}  // namespace raven::design
