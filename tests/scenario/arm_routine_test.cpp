// The scripted operator against a scene the test scripts: a ring lifted a little and caught on its
// start post does not come along with the tool, and the operator must not chase it.

#include "scenario/arm_routine.hpp"

#include <gtest/gtest.h>

#include "bridge/scene_perception.hpp"
#include "raven/platform_profile.hpp"
#include "scenario/peg_layout.hpp"
#include "scenario/ring_view.hpp"

namespace {

using scenario::Phase;

/// One ring where the test puts it (`pose`); nothing else is seen.
struct ScriptedRing : bridge::ScenePerception {
  std::string ring;
  Eigen::Isometry3d pose;

  ScriptedRing(std::string name, const Eigen::Isometry3d& at) : ring(std::move(name)), pose(at) {}
  void update(double /*now*/) override {}
  bridge::Sighting sight(const std::string& name) const override {
    if (name != ring) throw bridge::PerceptionError(name + ": not in this scene");
    return {0.0, pose, 1.0};
  }
};

TEST(ArmRoutine, ARingCaughtOnItsPostWhenLiftedIsGraspedAgainNotChased) {
  const scenario::PegLayout layout;
  const auto profile = raven::builtinProfile("physical");
  const auto jobs = layout.jobsOf(raven::Arm::Left);
  scenario::ArmRoutine routine(raven::Arm::Left, profile, layout, jobs);
  // Flat on the board at its start post.
  Eigen::Isometry3d resting = Eigen::Isometry3d::Identity();
  resting.translation() << jobs[0].from.x(), jobs[0].from.y(), 0.0;
  resting.translation().z() =
      layout.geometry.board_top - scenario::RingView({0.0, resting, 1.0}, layout.ring).bottom();
  ScriptedRing scene(jobs[0].ring, resting);
  const auto kinematics = raven::ArmKinematics::of(profile, raven::Arm::Left);

  raven::ArmJoints target = profile.home;
  std::optional<Eigen::Vector3d> carry_start;
  double farthest = 0.0;  // the tool's travel from where the carry began (m)
  for (int i = 0; i < 20000 && routine.phase() != Phase::Open; ++i) {
    target = routine.next(target, target, scene);  // the arm follows every command
    if (routine.phase() == Phase::Lift) {
      // Caught on its post: it rose 8 mm with the jaws, and rises no further.
      scene.pose.translation().z() = resting.translation().z() + 0.008;
    }
    if (routine.phase() == Phase::Carry) {
      const Eigen::Vector3d tool = kinematics.toolPose(target).translation();
      if (!carry_start) carry_start = tool;
      farthest = std::max(farthest, (tool - *carry_start).head<2>().norm());
    }
  }
  ASSERT_TRUE(carry_start) << "the ring came off the board: the operator carries it";
  EXPECT_EQ(routine.phase(), Phase::Open) << "it lets go to grasp it again";
  EXPECT_EQ(routine.regrasps()[0], 1);
  // The ring's centre stays put, so the tool strays from it as far as it moves: the operator
  // stops within the 5 mm a carried ring swings on its grip, one 1 mm step more at most.
  EXPECT_LE(farthest, 0.006);
  EXPECT_GT(farthest, 0.004) << "it carried the ring for a few steps before it gave up";
}

}  // namespace
