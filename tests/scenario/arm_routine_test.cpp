// The scripted operator against a scene the test scripts: a ring lifted a little and caught on its
// start post does not come along with the tool, and the operator must not chase it; a ring pushed
// off its post's axis is grasped again where the post leaves the inner jaw room; handed the pad
// mid-transfer, an operator with no memory of it takes up the step the state shows; holding a
// ring whose jaws stop off their command, it trims the outer jaw until they stand where planned.

#include "scenario/arm_routine.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <vector>

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

/// Ring `job` flat on the board at its start post, its centre `off` from the post's axis.
Eigen::Isometry3d restingAt(const scenario::PegLayout& layout, const scenario::RingJob& job,
                            const Eigen::Vector2d& off = Eigen::Vector2d::Zero()) {
  Eigen::Isometry3d resting = Eigen::Isometry3d::Identity();
  resting.translation() << job.from.x() + off.x(), job.from.y() + off.y(), 0.0;
  resting.translation().z() =
      layout.geometry.board_top - scenario::RingView({0.0, resting, 1.0}, layout.ring).bottom();
  return resting;
}

TEST(ArmRoutine, ARingCaughtOnItsPostWhenLiftedIsGraspedAgainNotChased) {
  const scenario::PegLayout layout;
  const auto profile = raven::builtinProfile("physical");
  const auto jobs = layout.jobsOf(raven::Arm::Left);
  scenario::ArmRoutine routine(raven::Arm::Left, profile, layout, jobs);
  const Eigen::Isometry3d resting = restingAt(layout, jobs[0]);
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

TEST(ArmRoutine, ARingPushedOffItsPostIsGraspedAgainWhereThePostLeavesRoom) {
  const scenario::PegLayout layout;
  const auto profile = raven::builtinProfile("physical");
  const auto jobs = layout.jobsOf(raven::Arm::Left);
  scenario::ArmRoutine routine(raven::Arm::Left, profile, layout, jobs);
  // 1 mm towards the target row: on its -y side the tube presses towards the post, leaving the
  // inner jaw 1 mm less room there and as much as on a centred ring on its -x and +x sides.
  ScriptedRing scene(jobs[0].ring, restingAt(layout, jobs[0], {0.0, 0.001}));
  const Eigen::Vector3d centre = scene.pose.translation();
  std::vector<Eigen::Vector3d> pivots;  // where each attempt went down, from the ring's centre
  raven::ArmJoints target = profile.home;
  for (int i = 0; i < 20000 && pivots.size() < 2; ++i) {
    const Phase before = routine.phase();
    target = routine.next(target, target, scene);  // the ring never comes up
    if (before == Phase::Orient && routine.phase() == Phase::Descend)
      pivots.push_back(routine.graspPivot() - centre);
  }
  ASSERT_EQ(pivots.size(), 2u);
  EXPECT_EQ(routine.regrasps()[0], 1);
  // The first grasp as always, on the side away from the target row; the second on a side
  // with room, the inner jaw's face 5.8 mm from the centre (the tube's inner face and the gap).
  EXPECT_LT(pivots[0].y(), -0.005);
  EXPECT_NEAR(pivots[0].x(), 0.0, 1e-6);
  EXPECT_NEAR(std::abs(pivots[1].x()), 0.0058, 1e-4);
  EXPECT_NEAR(pivots[1].y(), 0.0, 1e-4);
}

TEST(ArmRoutine, HandedThePadMidTransferItTakesUpTheStepTheStateShows) {
  const scenario::PegLayout layout;
  const auto profile = raven::builtinProfile("physical");
  const std::vector<scenario::RingJob> job{layout.jobsOf(raven::Arm::Left)[0]};
  const Eigen::Isometry3d resting = restingAt(layout, job[0]);
  ScriptedRing scene(job[0].ring, resting);
  // An operator who did it all, the commands where each of its steps began (the arm follows
  // every command; the ring stays on the board).
  scenario::ArmRoutine guide(raven::Arm::Left, profile, layout, job);
  std::map<Phase, raven::ArmJoints> began;
  raven::ArmJoints target = profile.home;
  for (int i = 0; i < 20000 && guide.phase() != Phase::Lift; ++i) {
    target = guide.next(target, target, scene);
    began.try_emplace(guide.phase(), target);
  }
  ASSERT_EQ(guide.phase(), Phase::Lift);
  auto takenUp = [&](const raven::ArmJoints& at) {
    scenario::ArmRoutine fresh(raven::Arm::Left, profile, layout, job);
    fresh.resume(at, scene);
    return fresh.phase();
  };
  EXPECT_EQ(takenUp(profile.home), Phase::Orient) << "far above, jaws half open";
  EXPECT_EQ(takenUp(began.at(Phase::Descend)), Phase::Descend) << "over the ring, jaws open";
  EXPECT_EQ(takenUp(began.at(Phase::Close)), Phase::Align) << "at the grasp, jaws still open";
  EXPECT_EQ(takenUp(began.at(Phase::Lift)), Phase::Close) << "at the grasp, jaws shut";
  scene.pose.translation().x() += 0.01;  // the ring 10 mm aside: the jaws shut beside it
  EXPECT_EQ(takenUp(began.at(Phase::Lift)), Phase::Open) << "let go, and grasp it again";
  EXPECT_EQ(takenUp(began.at(Phase::Close)), Phase::Retreat) << "jaws open beside it: up first";
  scene.pose = resting;

  // Lifted with the jaws: carried to the target post; over it and down, let go.
  scene.pose.translation().z() += 0.03;
  EXPECT_EQ(takenUp(began.at(Phase::Lift)), Phase::Carry);
  scene.pose.translation().head<2>() = job[0].to;
  EXPECT_EQ(takenUp(began.at(Phase::Lift)), Phase::Lower);
  scene.pose.translation().z() = resting.translation().z() + 0.003;  // off the board no longer
  EXPECT_EQ(takenUp(began.at(Phase::Lift)), Phase::Open);
  scene.pose.translation().z() = resting.translation().z();
  EXPECT_EQ(takenUp(began.at(Phase::Lift)), Phase::Done) << "its one ring is on its target post";

  // While the state shows the step it is in, the routine goes on as it was: its waits count.
  scene.pose = resting;
  scenario::ArmRoutine steady(raven::Arm::Left, profile, layout, job);
  target = profile.home;
  int steps = 0;
  for (; steps < 20000 && steady.phase() != Phase::Lift; ++steps) {
    steady.resume(target, scene);
    target = steady.next(target, target, scene);
  }
  EXPECT_EQ(steady.phase(), Phase::Lift) << "resumed at every step, it still reaches the lift";
}

/// Where the jaws stood when the carry ended, the outer jaw's motors holding it `held` (rad) more
/// closed than commanded (inside their friction band); the arm follows every other command.
struct GripAtTheEnd {
  double commanded_outer = 0.0;
  double measured_opening = 0.0;
  double widest_outer = 0.0;  ///< the outer jaw's widest command while carrying
};

GripAtTheEnd carriedWithJawsHeld(double held) {
  const scenario::PegLayout layout;
  const auto profile = raven::builtinProfile("physical");
  const std::vector<scenario::RingJob> job{layout.jobsOf(raven::Arm::Left)[0]};
  const auto kinematics = raven::ArmKinematics::of(profile, raven::Arm::Left);
  scenario::ArmRoutine routine(raven::Arm::Left, profile, layout, job);
  const Eigen::Isometry3d resting = restingAt(layout, job[0]);
  ScriptedRing scene(job[0].ring, resting);
  raven::ArmJoints target = profile.home;
  std::optional<Eigen::Vector3d> lift_start;  // the ring rides with the tool from the lift on
  GripAtTheEnd end;
  for (int i = 0; i < 20000 && routine.phase() != Phase::Lower; ++i) {
    raven::ArmJoints measured = target;
    measured(raven::kJaw2) -= held;
    target = routine.next(target, measured, scene);
    const Eigen::Vector3d tool = kinematics.toolPose(target).translation();
    if (routine.phase() == Phase::Lift && !lift_start) lift_start = tool;
    if (lift_start) scene.pose.translation() = resting.translation() + tool - *lift_start;
    end.commanded_outer = target(raven::kJaw2);
    end.measured_opening = measured(raven::kJaw1) + measured(raven::kJaw2);
    if (routine.phase() == Phase::Carry)
      end.widest_outer = std::max(end.widest_outer, end.commanded_outer);
  }
  EXPECT_EQ(routine.phase(), Phase::Lower) << "the ring was carried over its target post";
  EXPECT_EQ(routine.regrasps()[0], 0);
  return end;
}

TEST(ArmRoutine, HoldingARingItTrimsTheOuterJawUntilTheMeasuredOpeningIsTheGrasps) {
  const scenario::PegLayout layout;
  const scenario::ArmRoutine planner(raven::Arm::Left, raven::builtinProfile("physical"), layout,
                                     layout.jobsOf(raven::Arm::Left));
  const double closed = planner.jawAngleFor(scenario::ArmRoutine::kDefaultSqueeze);
  // Jaws that stand on their command (ideal servos) are left as they are.
  const GripAtTheEnd on = carriedWithJawsHeld(0.0);
  EXPECT_DOUBLE_EQ(on.commanded_outer, closed);
  EXPECT_DOUBLE_EQ(on.widest_outer, closed);
  // Held 7 mrad closed (the nominal ring4's right jaws, 0.8 N too hard): the command opens by as
  // much, and the measured opening comes to the grasp's (inner jaw at 0).
  const GripAtTheEnd tight = carriedWithJawsHeld(0.007);
  EXPECT_NEAR(tight.measured_opening, closed, 2e-4);
  EXPECT_NEAR(tight.commanded_outer, closed + 0.007, 2e-4);
  // Held further than any friction band (the reading is off, or something else holds the jaws):
  // the operator opens them at most 0.02 rad past the grasp's angle, never letting the ring go.
  const GripAtTheEnd stuck = carriedWithJawsHeld(0.05);
  EXPECT_NEAR(stuck.widest_outer, closed + 0.02, 1e-12);
  EXPECT_NEAR(stuck.measured_opening, closed + 0.02 - 0.05, 1e-12);
}

}  // namespace
