#pragma once
// The peg-transfer scene: a board with six posts (three in each arm's reach) and six soft ring
// pegs resting on them.

#include <Eigen/Core>
#include <array>
#include <filesystem>

namespace raven::model {

/// Dimensions and placement of the board, the posts and the pegs (our own design).
struct PegSceneDesign {
  double board_top = -0.205;  ///< z of the board surface in {B} (m)
  Eigen::Vector3d board_size{0.90, 0.26, 0.01};
  Eigen::Vector2d board_centre{0.0, 0.11};
  double post_radius = 0.0025;
  double post_height = 0.022;
  /// Post positions (x, y) in {B}: three for the left arm, then three for the right. The two
  /// arms' workspaces do not overlap (their remote centres are 0.6 m apart), so every post sits
  /// in one arm's reach.
  std::array<Eigen::Vector2d, 6> posts{Eigen::Vector2d(0.30, 0.07),  Eigen::Vector2d(0.36, 0.12),
                                       Eigen::Vector2d(0.30, 0.17),  Eigen::Vector2d(-0.30, 0.07),
                                       Eigen::Vector2d(-0.36, 0.12), Eigen::Vector2d(-0.30, 0.17)};
  double peg_major_radius = 0.006;  ///< ring centre line
  double peg_minor_radius = 0.002;  ///< tube
  int peg_ring_segments = 12;       ///< 72 nodes: round enough, and six of them step at 5 kHz
  int peg_tube_segments = 6;
  double peg_mass = 0.002;
  double peg_margin = 0.0005;
};

/// Writes peg_board.yaml, pegs.yaml and meshes/peg.obj into `dir`.
void writePegScene(const PegSceneDesign& design, const std::filesystem::path& dir);

}  // namespace raven::model
