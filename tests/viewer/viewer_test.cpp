// The viewer renders the peg-transfer scene headless (EGL, no X server, no Xvfb): robot and rings
// where the camera puts them, a collision view that differs from the visual one, numbered
// snapshot series. Without Mesa's EGL every rendering test skips, saying so.

#include "viewer/viewer.hpp"

#include <BulletSoftBody/btSoftBody.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <memory>

#include "ambf_like/scene_loader.hpp"
#include "ambf_like/world.hpp"
#include "headless_peg_scene.hpp"
#include "test_files.hpp"
#include "test_images.hpp"
#include "viewer/scene_geometry.hpp"
#include "viewer/snapshot_schedule.hpp"
#include "viewer/visual_skin.hpp"

namespace {

const std::filesystem::path kModels = RAVEN_MODELS_DIR;
using test_support::Image;
using test_support::isBackground;
using test_support::isCollisionOrange;
using test_support::isRingRed;
using test_support::shareNear;

using Scene = test_support::HeadlessPegScene;
constexpr int kWidth = Scene::kWidth, kHeight = Scene::kHeight;

#define SKIP_WITHOUT_DISPLAY(scene) \
  if (!(scene).view) GTEST_SKIP() << "no headless OpenGL: " << (scene).why

TEST(Viewer, RendersTheRobotAndThePegsWhereTheCameraPutsThem) {
  Scene scene;
  SKIP_WITHOUT_DISPLAY(scene);
  const auto file = scene.dir.path() / "visual.png";
  scene.view->snapshot(*scene.world, file);
  const Image image = Image::read(file);
  ASSERT_EQ(image.width, kWidth);
  ASSERT_EQ(image.height, kHeight);
  const viewer::Camera& camera = scene.view->initialCamera();

  // Every ring: its centre projects onto red pixels.
  ASSERT_EQ(scene.world->softBodyCount(), 6u);
  for (std::size_t i = 0; i < scene.world->softBodyCount(); ++i) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    const auto nodes = scene.world->softBody(i).nodePositions();
    for (const auto& n : nodes) centre += n;
    centre /= static_cast<double>(nodes.size());
    const auto pixel = camera.toPixel(centre, kWidth, kHeight);
    ASSERT_TRUE(pixel) << "ring " << i << " is behind the camera";
    EXPECT_GT(shareNear(image, *pixel, 4, isRingRed), 0.2)
        << scene.world->softBody(i).name() << " at pixel " << pixel->transpose();
  }
  // Each arm: the box its moving bodies project into is mostly drawn, not background.
  for (const char* arm : {"/left/", "/right/"}) {
    Eigen::AlignedBox2d box;
    for (std::size_t b = 0; b < scene.world->bodyCount(); ++b) {
      const auto& body = scene.world->body(b);
      if (body.isStatic() || body.qualifiedName().find(arm) == std::string::npos) continue;
      if (auto p = camera.toPixel(body.pose().translation(), kWidth, kHeight)) box.extend(*p);
    }
    ASSERT_FALSE(box.isEmpty()) << arm;
    EXPECT_TRUE(
        Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(kWidth, kHeight)).contains(box))
        << arm << " leaves the frame";
    int drawn = 0, all = 0;
    for (int y = static_cast<int>(box.min().y()); y < static_cast<int>(box.max().y()); ++y) {
      for (int x = static_cast<int>(box.min().x()); x < static_cast<int>(box.max().x()); ++x) {
        ++all;
        drawn += !isBackground(image.at(x, y));
      }
    }
    EXPECT_GT(static_cast<double>(drawn) / all, 0.05) << arm;
  }
  // The frame's corners are background: the scene is framed, not cropped.
  EXPECT_TRUE(isBackground(image.at(2, 2)));
  EXPECT_TRUE(isBackground(image.at(kWidth - 3, kHeight - 3)));
}

TEST(Viewer, TheCollisionViewDiffersFromTheVisualView) {
  Scene scene;
  SKIP_WITHOUT_DISPLAY(scene);
  const auto visual_file = scene.dir.path() / "visual.png";
  const auto collision_file = scene.dir.path() / "collision.png";
  scene.view->snapshot(*scene.world, visual_file, {false, false});
  scene.view->snapshot(*scene.world, collision_file, {true, false});
  const Image visual = Image::read(visual_file), collision = Image::read(collision_file);
  int differ = 0, orange_collision = 0, orange_visual = 0, drawn = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const auto *v = visual.at(x, y), *c = collision.at(x, y);
      differ += std::abs(v[0] - c[0]) + std::abs(v[1] - c[1]) + std::abs(v[2] - c[2]) > 30;
      orange_collision += isCollisionOrange(c);
      orange_visual += isCollisionOrange(v);
      drawn += !isBackground(v);
    }
  }
  ASSERT_GT(drawn, 1000);
  EXPECT_GT(differ, drawn / 2) << "of " << drawn << " drawn pixels";
  EXPECT_GT(orange_collision, drawn / 4);
  EXPECT_LT(orange_visual, orange_collision / 10);
}

TEST(Viewer, ShowsTheRingsDeforming) {
  Scene scene;
  SKIP_WITHOUT_DISPLAY(scene);
  // Squash one ring by moving half of its nodes: the snapshot shows the change where it is.
  const auto before = scene.dir.path() / "before.png";
  const auto after = scene.dir.path() / "after.png";
  scene.view->snapshot(*scene.world, before);
  auto& ring = scene.world->softBody(0).bullet();
  for (int n = 0; n < ring.m_nodes.size(); n += 2) ring.m_nodes[n].m_x += btVector3(0, 0, 0.01);
  scene.view->snapshot(*scene.world, after);
  const Image a = Image::read(before), b = Image::read(after);
  int changed = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) changed += a.rgb[i] != b.rgb[i];
  EXPECT_GT(changed, 30);
}

TEST(Viewer, SnapshotsNeedNoDisplayAndAWindowSaysWhatItLacks) {
  const char* display = std::getenv("DISPLAY");
  const std::string saved = display ? display : "";
  unsetenv("DISPLAY");
  ambf_like::MeshLibrary meshes;
  const auto scene = ambf_like::loadLaunchFile(kModels / "raven2/launch.yaml", {});
  ambf_like::World world(scene.spec, meshes);
  test_support::TempDir dir;
  viewer::ViewerOptions options;
  options.window = false;
  try {
    viewer::Viewer view(world, options);
    view.snapshot(world, dir.path() / "headless.png");
    const Image image = Image::read(dir.path() / "headless.png");
    EXPECT_EQ(image.width, options.width);
  } catch (const viewer::NoDisplay& e) {
    ADD_FAILURE() << "headless rendering without DISPLAY: " << e.what();
  }
  options.window = true;
  try {
    viewer::Viewer view(world, options);
    ADD_FAILURE() << "a window without DISPLAY";
  } catch (const viewer::NoDisplay& e) {
    EXPECT_NE(std::string(e.what()).find("no display for a window"), std::string::npos) << e.what();
  }
  if (!saved.empty()) setenv("DISPLAY", saved.c_str(), 1);
}

TEST(Viewer, SnapshotSeriesAreNumberedBySimulatedTime) {
  Scene scene;
  SKIP_WITHOUT_DISPLAY(scene);
  viewer::SnapshotSchedule schedule(scene.dir.path() / "run.png", 0.05);
  int taken = 0;
  const double start = scene.world->time();
  while (scene.world->time() < start + 0.12) {
    taken += schedule.maybeTake(*scene.view, *scene.world);
    scene.world->step();
  }
  EXPECT_EQ(taken, 3);
  for (int n = 0; n < 3; ++n) EXPECT_TRUE(std::filesystem::exists(schedule.fileFor(n))) << n;
  EXPECT_EQ(schedule.fileFor(2).filename(), "run_0002.png");
}

TEST(VisualSkin, ReadsItsBodiesAndRefusesBadInputByFileLineAndKey) {
  test_support::TempDir dir;
  const auto good = dir.path() / "skin.yaml";
  std::ofstream(good) << "mesh path: meshes\nbodies:\n"
                         "  /raven2/left/link1: {mesh: link1_L.STL, offset: {position: {x: 0.1, "
                         "y: 0, z: 0}, orientation: {r: 0, p: 0, y: 1.5}}}\n";
  const auto skin = viewer::VisualSkin::load(good);
  ASSERT_NE(skin.find("/raven2/left/link1"), nullptr);
  EXPECT_EQ(skin.find("/raven2/left/link2"), nullptr);
  EXPECT_NEAR(skin.find("/raven2/left/link1")->offset.translation().x(), 0.1, 1e-12);
  EXPECT_EQ(skin.firstMissing(), skin.mesh_dir / "link1_L.STL");
  for (const auto& [text, expected] : std::vector<std::pair<std::string, std::string>>{
           {"mesh path: m\nbodies:\n  a: {mesh: a.STL, colour: red}\n", "skin.yaml:3"},
           {"mesh path: m\nbodies:\n  a: {mesh: a.STL, offset: {position: {x: .nan}}}\n",
            "position/x"},
           {"bodies:\n  a: {mesh: a.STL}\n", "mesh path"},
           {"mesh path: m\nbodies: [\n", "skin.yaml"}}) {
    std::ofstream(good) << text;
    try {
      viewer::VisualSkin::load(good);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const common::LoadError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
}

TEST(SceneGeometry, TessellatesEveryBodyOfTheRaven) {
  ambf_like::MeshLibrary meshes;
  const auto scene = ambf_like::loadLaunchFile(kModels / "peg_transfer/launch.yaml", {});
  ambf_like::World world(scene.spec, meshes);
  const auto geometry = viewer::SceneGeometry::of(world, meshes);
  ASSERT_EQ(geometry.bodies.size(), world.bodyCount());
  for (std::size_t i = 0; i < world.bodyCount(); ++i) {
    const auto& body = geometry.bodies[i];
    EXPECT_GT(body.collision.triangles(), 0u) << body.name;
    // The room's floor (`visible: false`) is collided with and not drawn.
    const bool visible = world.body(i).spec().visible;
    EXPECT_EQ(visible, body.name.find("floor") == std::string::npos) << body.name;
    EXPECT_EQ(body.visual.triangles() > 0u, visible) << body.name;
  }
  ASSERT_EQ(geometry.soft_bodies.size(), 6u);
  for (const auto& soft : geometry.soft_bodies) EXPECT_GT(soft.faces.size(), 20u) << soft.name;
  // The scene's bounds hold the robot and the board, not the floor's 4 m.
  EXPECT_LT(geometry.bounds.sizes().maxCoeff(), 1.5);
  EXPECT_GT(geometry.bounds.sizes().maxCoeff(), 0.2);
}

}  // namespace
