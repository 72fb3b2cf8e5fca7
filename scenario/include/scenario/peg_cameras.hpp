#pragma once
// The peg-transfer scene's cameras as observations: colour, depth and segmentation images of
// its named views (task_views.hpp), with segmentation ids stable across runs and scenes:
//   0 background, 1 the board's plate, 2-7 the start posts of ring1..ring6, 8-13 their target
//   posts, 14-19 the rings ring1..ring6, 20 the left arm's links, 21 the left grasper's jaws,
//   22 the right arm's links, 23 the right grasper's jaws, 24 anything else.

#include <string>
#include <vector>

#include "scenario/peg_layout.hpp"
#include "scenario/scene_variation.hpp"
#include "viewer/camera_sensor.hpp"
#include "viewer/stereo_depth.hpp"

namespace scenario {

/// The segmentation ids above.
enum PegSegment : std::uint32_t {
  kBackground = 0,
  kPlate = 1,
  kFirstStartPost = 2,
  kFirstTargetPost = 8,
  kFirstRing = 14,
  kLeftArm = 20,
  kLeftJaws = 21,
  kRightArm = 22,
  kRightJaws = 23,
  kOther = 24
};

/// How many ids there are (the largest + 1).
inline constexpr std::uint32_t kPegSegments = 25;

/// One world's cameras: built after each reset (the world is new), rendering on demand.
class PegCameras {
 public:
  /// The views seen as `look` says (its cameras' poses, lights and colours; a nominal one: as
  /// designed). Throws std::invalid_argument for an unknown view name (listing them),
  /// viewer::NoDisplay when no headless OpenGL can be made.
  PegCameras(const ambf_like::World& world, const std::vector<std::string>& views, int width,
             int height, const SceneVariation& look = {}, const PegLayout& layout = {});

  /// Per view (in the order asked), the images asked for; the depth as `look`'s stereo camera
  /// reads it, its noise drawn from the look's seed, the view and the world's time.
  std::vector<viewer::CameraImages> render(const ambf_like::World& world, bool rgb, bool depth,
                                           bool segmentation);

 private:
  std::vector<viewer::View> views_;
  viewer::Look look_;
  viewer::StereoDepthErrors depth_errors_;
  std::uint64_t seed_ = 0;
  std::unique_ptr<viewer::CameraSensor> sensor_;
};

/// The labels of a peg-transfer world's surfaces (the posts told apart by the triangles of the
/// board's mesh that rise above its top, each taken by the nearest post).
viewer::SceneLabels pegSceneLabels(const ambf_like::World& world,
                                   const viewer::SceneGeometry& geometry, const PegLayout& layout);

}  // namespace scenario
