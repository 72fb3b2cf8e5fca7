// The peg-transfer scene's cameras as observations: images of the asked size, segmentation ids that
// find every ring, post, arm and the board where they are, depth that agrees with the camera's
// geometry, the same world rendered twice giving the same images, a camera made while an older one
// still exists drawing after that one is gone (an environment's reset does this), and cameras
// whose look a randomised scene drew, their depth read as a stereo camera would.

#include "scenario/peg_cameras.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "headless_peg_scene.hpp"
#include "scenario/task_views.hpp"

namespace {

TEST(PegCameras, SegmentationFindsEveryRingPostAndArmAndDepthIsMetres) {
  test_support::HeadlessPegScene scene;  // only its settled world is used
  if (!scene.view) GTEST_SKIP() << "no headless OpenGL: " << scene.why;
  scenario::PegCameras cameras(*scene.world, {"overview", "left-task"}, 256, 192);
  const auto images = cameras.render(*scene.world, true, true, true);
  ASSERT_EQ(images.size(), 2u);
  const viewer::CameraImages& overview = images[0];
  EXPECT_EQ(overview.rgb.size(), 256u * 192u * 3u);
  EXPECT_EQ(overview.depth.size(), 256u * 192u);
  ASSERT_EQ(overview.segmentation.size(), 256u * 192u);
  std::set<std::uint32_t> seen(overview.segmentation.begin(), overview.segmentation.end());
  for (std::uint32_t id = scenario::kFirstRing; id < scenario::kFirstRing + 6; ++id) {
    EXPECT_TRUE(seen.count(id)) << "ring " << id - scenario::kFirstRing + 1 << " not seen";
  }
  EXPECT_TRUE(seen.count(scenario::kPlate));
  EXPECT_TRUE(seen.count(scenario::kFirstStartPost));
  EXPECT_TRUE(seen.count(scenario::kFirstTargetPost + 5));
  EXPECT_TRUE(seen.count(scenario::kLeftArm) || seen.count(scenario::kLeftJaws));
  for (std::uint32_t id : seen) EXPECT_LT(id, scenario::kPegSegments);
  // Depth: finite exactly where something was drawn, within the camera's near and far planes.
  const auto views = scenario::pegTransferViews(*scene.world);
  const viewer::Camera camera = viewer::findView(views, "overview").camera;
  for (std::size_t p = 0; p < overview.depth.size(); ++p) {
    if (overview.segmentation[p] == scenario::kBackground) {
      EXPECT_TRUE(std::isinf(overview.depth[p])) << p;
    } else {
      EXPECT_GE(overview.depth[p], camera.nearPlane() * 0.999);
      EXPECT_LE(overview.depth[p], camera.farPlane() * 1.001);
    }
  }
  // A ring's pixels lie about as far as the ring is along the camera's axis.
  const Eigen::Vector3d eye = camera.eye();
  const Eigen::Vector3d axis = (camera.target - eye).normalized();
  const double ring_depth = (scene.world->softBody("ring1").centerOfMass() - eye).dot(axis);
  double sum = 0.0;
  int n = 0;
  for (std::size_t p = 0; p < overview.depth.size(); ++p) {
    if (overview.segmentation[p] == scenario::kFirstRing) sum += overview.depth[p], ++n;
  }
  ASSERT_GT(n, 0);
  EXPECT_NEAR(sum / n, ring_depth, 0.012);
  // The same world twice: the same images.
  const auto again = cameras.render(*scene.world, true, true, true);
  EXPECT_EQ(again[0].rgb, overview.rgb);
  EXPECT_EQ(again[0].segmentation, overview.segmentation);
  EXPECT_EQ(images[1].segmentation.size(), 256u * 192u);
}

TEST(PegCameras, ANewCameraStillDrawsAfterTheOldOneIsGone) {
  test_support::HeadlessPegScene scene;
  if (!scene.view) GTEST_SKIP() << "no headless OpenGL: " << scene.why;
  auto old_cameras = std::make_unique<scenario::PegCameras>(
      *scene.world, std::vector<std::string>{"left-task"}, 64, 48);
  const std::vector<std::uint8_t> first =
      old_cameras->render(*scene.world, true, false, false)[0].rgb;
  scenario::PegCameras cameras(*scene.world, {"left-task"}, 64, 48);
  old_cameras.reset();  // its framebuffer's names are also the new context's
  const auto images = cameras.render(*scene.world, true, false, true);
  EXPECT_EQ(images[0].rgb, first);
  std::set<std::uint32_t> seen(images[0].segmentation.begin(), images[0].segmentation.end());
  EXPECT_TRUE(seen.count(scenario::kFirstRing)) << "the new camera drew no ring";
}

/// The mean of one colour channel over the pixels of segmentation id `id` (-1 if none).
double meanChannel(const viewer::CameraImages& image, std::uint32_t id, int channel) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t p = 0; p < image.segmentation.size(); ++p) {
    if (image.segmentation[p] == id)
      sum += image.rgb[3 * p + static_cast<std::size_t>(channel)], ++n;
  }
  return n ? sum / n : -1.0;
}

TEST(PegCameras, ADrawnLookMovesTheCameraAndChangesTheLightsAndColours) {
  test_support::HeadlessPegScene scene;
  if (!scene.view) GTEST_SKIP() << "no headless OpenGL: " << scene.why;
  const auto render = [&](const scenario::SceneVariation& look) {
    scenario::PegCameras cameras(*scene.world, {"left-task"}, 128, 96, look);
    return cameras.render(*scene.world, true, true, true)[0];
  };
  const viewer::CameraImages nominal = render({});
  // A nominal scene's look is the design's: the same images as cameras given none.
  EXPECT_EQ(nominal.rgb, scenario::PegCameras(*scene.world, {"left-task"}, 128, 96)
                             .render(*scene.world, true, false, false)[0]
                             .rgb);
  // Brighter lights: every surface brighter (the board's plate, the rings).
  scenario::SceneVariation brighter;
  brighter.nominal = false;
  brighter.light = 1.3;
  const viewer::CameraImages bright = render(brighter);
  EXPECT_EQ(bright.segmentation, nominal.segmentation);  // the camera did not move
  EXPECT_GT(meanChannel(bright, scenario::kPlate, 1),
            meanChannel(nominal, scenario::kPlate, 1) + 5);
  EXPECT_GT(meanChannel(bright, scenario::kFirstRing, 0),
            meanChannel(nominal, scenario::kFirstRing, 0) + 5);
  // The rings' red channel down, nothing else: the rings redden less, the plate stays.
  scenario::SceneVariation tinted;
  tinted.nominal = false;
  tinted.ring_tint = Eigen::Vector3d(0.85, 1.0, 1.0);
  const viewer::CameraImages tint = render(tinted);
  EXPECT_LT(meanChannel(tint, scenario::kFirstRing, 0),
            meanChannel(nominal, scenario::kFirstRing, 0) - 5);
  EXPECT_NEAR(meanChannel(tint, scenario::kPlate, 1), meanChannel(nominal, scenario::kPlate, 1),
              0.5);
  // A camera turned by 2 degrees and moved by 3 mm sees the same scene a few pixels over.
  scenario::SceneVariation moved;
  moved.nominal = false;
  moved.camera_yaw = 0.035;
  moved.camera_shift = Eigen::Vector3d(0.003, -0.003, 0.0);
  const viewer::CameraImages shifted = render(moved);
  EXPECT_NE(shifted.segmentation, nominal.segmentation);
  std::set<std::uint32_t> seen(shifted.segmentation.begin(), shifted.segmentation.end());
  for (std::uint32_t id = scenario::kFirstRing; id < scenario::kFirstRing + 3; ++id) {
    EXPECT_TRUE(seen.count(id)) << "ring " << id - scenario::kFirstRing + 1 << " out of sight";
  }
}

TEST(PegCameras, ADrawnDepthCameraReadsTheSceneWithTheStereoNoiseItsRangeSays) {
  test_support::HeadlessPegScene scene;
  if (!scene.view) GTEST_SKIP() << "no headless OpenGL: " << scene.why;
  scenario::SceneVariation stereo;
  stereo.nominal = false;
  stereo.seed = 9;
  stereo.depth_noise = 0.004;  // m at 1 m
  const auto depth = [&](const scenario::SceneVariation& look) {
    return scenario::PegCameras(*scene.world, {"left-task"}, 128, 96, look)
        .render(*scene.world, false, true, false)[0]
        .depth;
  };
  const std::vector<float> exact = depth({}), noisy = depth(stereo);
  EXPECT_EQ(noisy, depth(stereo));  // the same seed, view and time: the same reading
  // Each reading off by k z^2 in RMS (z about 0.2 m here: 0.16 mm), where anything is seen.
  double squares = 0.0;
  int seen = 0;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    if (!std::isfinite(exact[i])) continue;
    ASSERT_TRUE(std::isfinite(noisy[i])) << "a reading lost without a baseline, pixel " << i;
    const double sigma = stereo.depth_noise * exact[i] * exact[i];
    squares += std::pow((noisy[i] - exact[i]) / sigma, 2);
    ++seen;
  }
  ASSERT_GT(seen, 1000);
  EXPECT_NEAR(std::sqrt(squares / seen), 1.0, 0.05);
}

}  // namespace
