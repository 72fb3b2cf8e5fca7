#pragma once
// The peg-transfer scene's layout as the scenario needs it: which ring starts on which post, where
// it goes, and the ring's and board's dimensions, all from raven_description's scene design
// (raven/design/peg_scene_design.hpp), placed where the board is seen.

#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "bridge/scene_perception.hpp"
#include "raven/arm.hpp"
#include "raven/design/peg_scene_design.hpp"
#include "scenario/ring_view.hpp"

namespace scenario {

/// One transfer: the ring `ring` from post `from` to post `to`, by `arm`.
struct RingJob {
  std::string ring;  ///< its soft body's name in the scene (ringName)
  raven::Arm arm;
  Eigen::Vector2d from, to;
};

/// The scene's name of ring `i` (0-5): ring1..ring6.
std::string ringName(std::size_t i);
/// The name scenes written before the rings were called rings give ring `i`: peg1..peg6.
std::string legacyRingName(std::size_t i);
/// Which ring (0-5) a soft body of that name is, by either name; none if no ring.
std::optional<std::size_t> ringIndexOf(const std::string& body);

/// The ring and board dimensions and the six jobs.
struct PegLayout {
  /// The design's scene where the design puts it.
  PegLayout() : PegLayout(raven::design::PegSceneDesign{}) {}
  /// The design's scene with its board at `board` (its frame: the board's top centre); by
  /// default where the design puts it.
  explicit PegLayout(const raven::design::PegSceneDesign& design,
                     const std::optional<Eigen::Isometry3d>& board = std::nullopt);
  /// The design's scene placed where `scene` sees the board, its rings named as `scene` names
  /// them (ringName, or legacyRingName in a scene written before).
  static PegLayout seen(const bridge::ScenePerception& scene,
                        const raven::design::PegSceneDesign& design = {});

  /// The board's name in the scene (raven_description's peg_board.yaml).
  static constexpr const char* kBoard = "peg_board";

  RingDimensions ring;
  BoardGeometry geometry;
  /// Ring i (ring1..ring6) from start post i to target post i + 6, by the arm on its side of the
  /// board (x > 0: the left arm): from the start row straight back to the target row.
  std::array<RingJob, 6> jobs;

  /// The jobs of one arm, in order.
  std::vector<RingJob> jobsOf(raven::Arm arm) const;
};

}  // namespace scenario
