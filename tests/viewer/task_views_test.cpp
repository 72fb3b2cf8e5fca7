// The peg-transfer scene's named views, rendered headless (no X server, no Xvfb): each view draws
// the scene; in the task views every ring covers enough pixels to count, and a ring on a target
// post is told from a ring on a start post by where its colour lands.

#include "scenario/task_views.hpp"

#include <BulletSoftBody/btSoftBody.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "ambf_like/scene_loader.hpp"
#include "ambf_like/world.hpp"
#include "headless_peg_scene.hpp"
#include "scenario/peg_layout.hpp"
#include "test_files.hpp"
#include "test_images.hpp"
#include "viewer/viewer.hpp"

namespace {

using test_support::Image;
using test_support::isBackground;
using test_support::isRingRed;
using test_support::shareNear;

/// A ring 20 mm across seen from 0.2 m covers about 2,000 pixels of a 640x400 task view; a
/// third of that still counts as a ring a person can see.
constexpr int kMinRingPixels = 500;
/// Height of a resting ring's middle above the board's top (its 10 mm height, resting on it).
constexpr double kRingMiddle = 0.005;
constexpr double kBoardTop = -0.205;

/// The shipped scene settled, its named views and a headless viewer.
struct PegScene : test_support::HeadlessPegScene {
  std::vector<viewer::View> views = scenario::pegTransferViews(*world);

  Image shoot(const std::string& name) {
    const auto file = dir.path() / (name + ".png");
    view->snapshot(*world, file, {}, viewer::findView(views, name));
    return Image::read(file);
  }
};

/// The square on screen about a post at a resting ring's middle height, as wide as the ring.
struct PostBox {
  Eigen::Vector2d centre;
  int half = 0;
};

PostBox boxAt(const Image& image, const viewer::Camera& camera, const Eigen::Vector2d& post) {
  const Eigen::Vector3d middle(post.x(), post.y(), kBoardTop + kRingMiddle);
  const auto centre = camera.toPixel(middle, image.width, image.height);
  const auto rim = camera.toPixel(middle + Eigen::Vector3d(0.010, 0, 0), image.width, image.height);
  if (!centre || !rim) return {};
  return {*centre, static_cast<int>((*rim - *centre).norm())};
}

/// Ring-coloured pixels in the box about a post.
int ringPixelsAt(const Image& image, const viewer::Camera& camera, const Eigen::Vector2d& post) {
  const PostBox box = boxAt(image, camera, post);
  const int side = 2 * box.half + 1;
  return static_cast<int>(
      std::lround(shareNear(image, box.centre, box.half, isRingRed) * side * side));
}

/// The same as a share of the box.
double ringShareAt(const Image& image, const viewer::Camera& camera, const Eigen::Vector2d& post) {
  const PostBox box = boxAt(image, camera, post);
  const int side = 2 * box.half + 1;
  return static_cast<double>(ringPixelsAt(image, camera, post)) / (side * side);
}

TEST(TaskViews, EveryNamedViewIsRenderedHeadless) {
  PegScene scene;
  if (!scene.view) GTEST_SKIP() << "no headless OpenGL: " << scene.why;
  ASSERT_EQ(scene.views.size(), scenario::pegTransferViewNames().size());
  for (const std::string& name : scenario::pegTransferViewNames()) {
    const Image image = scene.shoot(name);
    ASSERT_EQ(image.width, PegScene::kWidth) << name;
    int drawn = 0;
    for (int y = 0; y < PegScene::kHeight; ++y) {
      for (int x = 0; x < PegScene::kWidth; ++x) drawn += !isBackground(image.at(x, y));
    }
    // The task views look down on the board; a grasper view has the jaws against the sky.
    const bool grasper = name.starts_with("grasper");
    EXPECT_GT(drawn, PegScene::kWidth * PegScene::kHeight / (grasper ? 20 : 10))
        << name << ": mostly empty";
  }
  EXPECT_THROW(viewer::findView(scene.views, "ceiling"), std::invalid_argument);
}

TEST(TaskViews, TheOverviewShowsAllSixRings) {
  PegScene scene;
  if (!scene.view) GTEST_SKIP() << "no headless OpenGL: " << scene.why;
  const Image image = scene.shoot("overview");
  const viewer::Camera camera = viewer::findView(scene.views, "overview").camera;
  for (const scenario::RingJob& job : scenario::PegLayout{}.jobs) {
    EXPECT_GT(ringShareAt(image, camera, job.from), 0.15) << job.ring << " on its start post";
  }
}

TEST(TaskViews, RingsOnTargetPostsAreToldFromRingsOnStartPosts) {
  PegScene scene;
  if (!scene.view) GTEST_SKIP() << "no headless OpenGL: " << scene.why;
  const scenario::PegLayout layout;
  // Ring pixels of the least visible ring, before and after.
  int fewest = PegScene::kWidth * PegScene::kHeight;
  for (raven::Arm arm : raven::kArms) {
    const std::string view = std::string(raven::armName(arm)) + "-task";
    const viewer::Camera camera = viewer::findView(scene.views, view).camera;
    // Before: each ring on its start post, enough of it drawn to count; the target posts bare.
    Image image = scene.shoot(view);
    int ring_pixels = 0;
    for (int y = 0; y < PegScene::kHeight; ++y) {
      for (int x = 0; x < PegScene::kWidth; ++x) ring_pixels += isRingRed(image.at(x, y));
    }
    EXPECT_GT(ring_pixels, 3 * kMinRingPixels) << view;
    for (const scenario::RingJob& job : layout.jobsOf(arm)) {
      fewest = std::min(fewest, ringPixelsAt(image, camera, job.from));
      EXPECT_GT(ringPixelsAt(image, camera, job.from), kMinRingPixels) << view << " " << job.ring;
      EXPECT_LT(ringShareAt(image, camera, job.to), 0.01) << view << " " << job.ring;
    }
    // After: the same rings moved onto their target posts, as a finished transfer leaves them.
    for (const scenario::RingJob& job : layout.jobsOf(arm)) {
      const Eigen::Vector2d shift = job.to - job.from;
      scene.world->softBody(job.ring).bullet().translate(btVector3(shift.x(), shift.y(), 0.0));
    }
    image = scene.shoot(view);
    for (const scenario::RingJob& job : layout.jobsOf(arm)) {
      EXPECT_LT(ringShareAt(image, camera, job.from), 0.01) << view << " " << job.ring;
      fewest = std::min(fewest, ringPixelsAt(image, camera, job.to));
      EXPECT_GT(ringPixelsAt(image, camera, job.to), kMinRingPixels) << view << " " << job.ring;
    }
  }
  RecordProperty("fewest_ring_pixels", fewest);
}

TEST(TaskViews, AGrasperViewFollowsItsJaws) {
  PegScene scene;
  if (!scene.view) GTEST_SKIP() << "no headless OpenGL: " << scene.why;
  for (raven::Arm arm : raven::kArms) {
    const auto& view = viewer::findView(scene.views, "grasper-" + std::string(raven::armName(arm)));
    ASSERT_TRUE(view.follow_body);
    std::vector<Eigen::Isometry3d> poses;
    for (std::size_t i = 0; i < scene.world->bodyCount(); ++i) {
      poses.push_back(scene.world->body(i).pose());
    }
    const viewer::Camera camera = view.at(poses);
    // The jaw's own origin lands in the middle of the picture.
    const auto jaw =
        camera.toPixel(poses[*view.follow_body].translation(), PegScene::kWidth, PegScene::kHeight);
    ASSERT_TRUE(jaw);
    EXPECT_NEAR(jaw->x(), PegScene::kWidth / 2.0, 1.0);
    EXPECT_NEAR(jaw->y(), PegScene::kHeight / 2.0, 1.0);
    EXPECT_NE(scene.world->body(*view.follow_body).qualifiedName().find(raven::armName(arm)),
              std::string::npos);
  }
}

}  // namespace
