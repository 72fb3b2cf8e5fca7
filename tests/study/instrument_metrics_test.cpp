// The surgical simulators' instrument metrics on scripted cases whose answers are known by
// construction: contact episodes, the task camera's picture, excessive force from a cf file, time
// out of view and workspace range; and a ring let go 20 mm from a post in the peg-transfer scene
// counts one drop.

#include "study/instrument_metrics.hpp"

#include <BulletSoftBody/btSoftBody.h>
#include <gtest/gtest.h>

#include <cmath>

#include "ambf_like/scene_loader.hpp"
#include "harness/temp_dir.hpp"
#include "raven/platform_profile.hpp"
#include "recording/cf_recording.hpp"
#include "scenario/peg_layout.hpp"
#include "study/collision_watch.hpp"
#include "study/trial_task.hpp"
#include "study/view_watch.hpp"

namespace {

ambf_like::Contact touch(const std::string& a, const std::string& b, double z = 0.0) {
  ambf_like::Contact c;
  c.body_a = a;
  c.body_b = b;
  c.position_on_b = {0.3, 0.06, z};
  c.distance = -1e-5;
  c.normal_impulse = 1e-4;
  return c;
}

std::size_t countOf(const study::EventLog& log, const std::string& name) {
  return static_cast<std::size_t>(std::count_if(log.events().begin(), log.events().end(),
                                                [&](const auto& e) { return e.name == name; }));
}

TEST(InstrumentMetrics, OneTouchIsOneCollisionThoughItsContactsFlicker) {
  harness::TempDir dir;
  study::EventLog log(dir.path() / "events.csv");
  scenario::BoardGeometry board;
  board.board_top = -0.205;
  board.post_height = 0.022;
  study::CollisionWatch watch(board);
  const std::string left = "/raven2/left/jaw1_link", right = "/raven2/right/jaw2_link";
  const std::string plate = "/peg_transfer/peg_board";
  const double dt = 0.01;
  // 0-0.3 s the jaws of the two arms touch, losing contact for one iteration at 0.15 s; then
  // nothing; 0.6-0.7 s they touch again. 1.0-1.2 s the left tool on the board's surface,
  // 1.5-1.6 s the right tool on a post (a contact 10 mm up the post).
  for (int i = 0; i <= 200; ++i) {
    const double t = i * dt;
    std::vector<ambf_like::Contact> contacts;
    if ((t < 0.3 && i != 15) || (t >= 0.6 && t < 0.7)) contacts.push_back(touch(left, right));
    if (t >= 1.0 && t < 1.2) contacts.push_back(touch(plate, left, board.board_top));
    if (t >= 1.5 && t < 1.6) contacts.push_back(touch(right, plate, board.board_top + 0.01));
    ambf_like::Contact same_arm = touch(left, "/raven2/left/wrist_link");
    ambf_like::Contact near_miss = touch(right, plate);
    near_miss.distance = 0.0004;  // inside the margin, not touching, no impulse
    near_miss.normal_impulse = 0.0;
    ambf_like::Contact ring = touch("/peg_transfer/ring1", left);
    ring.soft = true;  // a grasp, not a collision
    contacts.insert(contacts.end(), {same_arm, near_miss, ring});
    watch.observe(t, contacts, log);
    if (t > 1.05 && t < 1.15) {
      EXPECT_TRUE(watch.touchingBoard());
    }
  }
  EXPECT_EQ(countOf(log, "tool_collision"), 2u);
  EXPECT_EQ(countOf(log, "tool_collision_end"), 2u);
  EXPECT_EQ(countOf(log, "board_collision"), 1u);
  EXPECT_EQ(countOf(log, "post_collision"), 1u);
  for (const auto& e : log.events()) {
    if (e.name == "board_collision") {
      EXPECT_EQ(e.arm, 0);
      EXPECT_NEAR(e.time, 1.0, 1e-9);
    }
    if (e.name == "post_collision") {
      EXPECT_EQ(e.arm, 1);
    }
    if (e.name == "tool_collision") {
      EXPECT_EQ(e.arm, -1);
    }
  }
  EXPECT_FALSE(watch.touchingBoard());
}

TEST(InstrumentMetrics, WithoutABoardOnlyTheArmsAreWatched) {
  harness::TempDir dir;
  study::EventLog log(dir.path() / "events.csv");
  study::CollisionWatch watch(std::nullopt);
  watch.observe(0.0, {touch("/peg_transfer/peg_board", "/raven2/left/jaw1_link")}, log);
  EXPECT_TRUE(log.events().empty());
}

TEST(InstrumentMetrics, TheTaskCameraHoldsItsWholeBallAndNothingFarOutside) {
  const Eigen::Vector3d centre(0.1, -0.2, 0.05);
  const double radius = 0.04;
  const viewer::Camera camera = study::cameraHolding(centre, radius);
  const study::ViewWatch sight(camera, 960, 540);
  const Eigen::Vector3d axis = (centre - camera.eye()).normalized();
  for (double a = 0.0; a < 2 * M_PI; a += 0.3) {
    for (double b = -1.5; b <= 1.5; b += 0.3) {
      const Eigen::Vector3d d(std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), std::sin(b));
      EXPECT_TRUE(sight.sees(centre + 0.999 * radius * d)) << d.transpose();
      // Four radii out across the line of sight is outside the picture.
      const Eigen::Vector3d across = d - d.dot(axis) * axis;
      if (across.norm() > 0.1) {
        EXPECT_FALSE(sight.sees(centre + 4.0 * radius * across.normalized())) << d.transpose();
      }
    }
  }
  harness::TempDir dir;
  study::EventLog log(dir.path() / "events.csv");
  study::ViewWatch watch(study::cameraHolding(centre, radius), 960, 540);
  const Eigen::Vector3d far = centre + Eigen::Vector3d(0.0, 0.0, 10 * radius);
  watch.observe(0.0, {centre, centre}, log);
  watch.observe(1.0, {far, centre}, log);  // the left jaws leave the picture
  watch.observe(2.5, {centre, far}, log);  // back; the right ones leave
  watch.observe(3.0, {centre, centre}, log);
  ASSERT_EQ(log.events().size(), 4u);
  EXPECT_NEAR(study::timeBetween(log.events(), "out_of_view", "in_view", 4.0), 1.5 + 0.5, 1e-12);
  // One still out at the end counts until the trial's end.
  watch.observe(3.5, {far, centre}, log);
  EXPECT_NEAR(study::timeBetween(log.events(), "out_of_view", "in_view", 4.0), 2.0 + 0.5, 1e-12);
}

TEST(InstrumentMetrics, ExcessiveForceIsTheTimeAndPeakOfAJawAboveTheThreshold) {
  harness::TempDir dir;
  const auto path = dir.path() / "t_cf.csv";
  {
    recording::CfWriter writer(path);
    for (int i = 0; i <= 100; ++i) {  // 1 s at 100 Hz
      const double t = i * 0.01;
      bridge::GrasperForces left;
      left.jaws[0].normal = {0.0, 0.0, (i > 20 && i <= 70) ? 5.0 : 1.0};  // 0.5 s at 5 N
      left.jaws[1].normal = {0.0, 0.0, (i > 40 && i <= 50) ? 7.0 : 1.0};  // the peak
      writer.write(t, {left, std::nullopt});  // the right arm without forces
    }
  }
  const recording::CfRecording cf = recording::readCf(path);
  const study::ExcessiveForce above3 = study::excessiveForce(cf, 3.0);
  EXPECT_NEAR(above3.time, 0.5, 1e-9);
  EXPECT_DOUBLE_EQ(above3.peak, 7.0);
  const study::ExcessiveForce above6 = study::excessiveForce(cf, 6.0);
  EXPECT_NEAR(above6.time, 0.1, 1e-9);
  const study::ExcessiveForce above8 = study::excessiveForce(cf, 8.0);
  EXPECT_EQ(above8.time, 0.0);
  EXPECT_EQ(above8.peak, 0.0);
}

TEST(InstrumentMetrics, WorkspaceRangeIsHalfThePathsWidestExtent) {
  EXPECT_EQ(study::workspaceRange({}), 0.0);
  EXPECT_EQ(study::workspaceRange({{0.3, 0.1, 0.2}}), 0.0);
  EXPECT_NEAR(study::workspaceRange({{0.01, 0, 0}, {-0.01, 0, 0}, {0, 0.005, 0}}), 0.01, 1e-12);
  // A stick at full tilt for 90 readings and at rest for 10: 0.5, however long it stayed where.
  std::vector<Eigen::Vector3d> stick(90, Eigen::Vector3d(0, 1, 0));
  stick.resize(100, Eigen::Vector3d::Zero());
  EXPECT_DOUBLE_EQ(study::workspaceRange(stick), 0.5);
}

TEST(InstrumentMetrics, ARingLetGoTwentyMillimetresFromAPostIsOneDrop) {
  const auto dir = raven::modelDirectory() / "peg_transfer";
  const auto scene =
      ambf_like::loadModelFiles({dir / "peg_board.yaml", dir / "rings.yaml"}, dir / "world.yaml");
  ambf_like::MeshLibrary meshes;
  ambf_like::World world(scene.spec, meshes);
  study::TaskSpec spec;
  spec.kind = study::TaskKind::PegTransfer;
  const auto task = study::makeTask(spec, 1);
  harness::TempDir out;
  study::EventLog log(out.path() / "events.csv");
  const scenario::PegLayout layout;
  // Ring 1 taken 10 mm up and let go 20 mm behind its target post (no post there).
  ambf_like::SoftBody& ring = world.softBody(layout.jobs[0].ring);
  const Eigen::Vector3d start = ring.centerOfMass();
  const Eigen::Vector2d above = layout.jobs[0].to + Eigen::Vector2d(0.0, 0.02);
  ring.bullet().translate(btVector3(above.x() - start.x(), above.y() - start.y(), 0.01));
  study::TaskView view;
  view.world = &world;
  task->begin(view, log);
  for (int i = 0; i < 3000; ++i) {  // 3 s
    world.step();
    view.time = world.time();
    task->observe(view, log);
  }
  EXPECT_EQ(countOf(log, "ring_lifted"), 1u);
  EXPECT_EQ(countOf(log, "ring_dropped"), 1u);
  EXPECT_EQ(countOf(log, "ring_placed"), 0u);
  for (const auto& e : log.events()) {
    if (e.name == "ring_dropped") {
      EXPECT_EQ(e.value, 1.0);
    }
  }
}

}  // namespace
