// The peg transfer's goals for a person at the pad, followed by a steady hand that puts the tool
// exactly where it is asked to (no motors, no physics): a ring squeezed goes where the jaws go,
// one let go falls onto the board below it. The answers are known by construction: each ring
// ends on the post behind it after one grasp; a ring that never comes up is tried three times
// and then left; a way down held up on the post is tried again with more room from it. And the jaw
// openings the goals ask for clear what the scene's geometry says they must.

#include "study/peg_arm_goals.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "raven/design/arm_design.hpp"
#include "scenario/arm_routine.hpp"

namespace {

/// Jaws pointing down, opening along x.
Eigen::Matrix3d jawsDown() {
  Eigen::Matrix3d axes;
  axes.col(0) = Eigen::Vector3d(0, 0, -1);
  axes.col(1) = Eigen::Vector3d(1, 0, 0);
  axes.col(2) = axes.col(0).cross(axes.col(1));
  return axes;
}

/// The six rings on their start posts, upright on the board.
struct Scene {
  scenario::PegLayout layout;
  std::vector<Eigen::Vector3d> centres;

  Scene() {
    for (const auto& job : layout.jobs) centres.push_back(onBoard(job.from));
  }
  Eigen::Vector3d onBoard(const Eigen::Vector2d& at) const {
    return {at.x(), at.y(), layout.geometry.board_top + layout.ring.half_height};
  }
  std::vector<scenario::RingView> seen() const {
    std::vector<scenario::RingView> out;
    for (const Eigen::Vector3d& c : centres) {
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.translation() = c;
      out.emplace_back(bridge::Sighting{0.0, pose, std::nullopt}, layout.ring);
    }
    return out;
  }
};

/// What the steady hand did: squeezes per ring (layout order), and whether the goals ran out.
struct Hand {
  std::array<int, 6> squeezes{};
  bool done = false;
};

/// The left arm's three rings with a steady hand; `grips` false: the jaws never hold a ring.
Hand steadyHand(Scene& scene, bool grips) {
  study::PegArmGoals goals(scene.layout, {0, 1, 2});
  const double squeeze = study::PegArmGoals::squeezingGrasp(scene.layout.ring);
  Eigen::Vector3d tip(0.300, 0.079, scene.layout.geometry.board_top + 0.045);
  std::optional<std::size_t> held;
  Eigen::Vector3d held_from_tip = Eigen::Vector3d::Zero();
  Hand run;
  bool squeezing = false;
  for (double t = 0.0; t < 600.0 && !goals.done(); t += 0.02) {
    goals.observe(t, tip, jawsDown(), scene.seen());
    const study::ArmGoal goal = goals.goal();
    tip = goal.point;
    const bool closed = std::abs(goal.grasp - squeeze) < 1e-9;
    if (closed && !squeezing) {  // the jaws close on the nearest ring
      std::size_t nearest = 0;
      for (std::size_t i = 1; i < 6; ++i) {
        if ((scene.centres[i] - tip).norm() < (scene.centres[nearest] - tip).norm()) nearest = i;
      }
      ++run.squeezes[nearest];
      if (grips) held = nearest, held_from_tip = scene.centres[nearest] - tip;
    }
    if (!closed && held) {  // let go: it falls onto the board
      scene.centres[*held] = scene.onBoard(scene.centres[*held].head<2>());
      held.reset();
    }
    squeezing = closed;
    if (held) scene.centres[*held] = tip + held_from_tip;
  }
  run.done = goals.done();
  return run;
}

TEST(PegArmGoals, ASteadyHandMovesEachRingOntoThePostBehindItWithOneGrasp) {
  Scene scene;
  const Hand run = steadyHand(scene, true);
  ASSERT_TRUE(run.done);
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& job = scene.layout.jobs[i];
    EXPECT_LT((scene.centres[i].head<2>() - job.to).norm(), 0.001) << job.ring;
    EXPECT_EQ(run.squeezes[i], 1) << job.ring;
  }
  for (std::size_t i = 3; i < 6; ++i) {  // the right arm's rings were not touched
    EXPECT_EQ(scene.centres[i], scene.onBoard(scene.layout.jobs[i].from));
  }
}

TEST(PegArmGoals, ARingThatNeverComesUpIsTriedThreeTimesThenLeft) {
  Scene scene;
  const Hand run = steadyHand(scene, false);
  ASSERT_TRUE(run.done);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(run.squeezes[i], 3) << scene.layout.jobs[i].ring;
    EXPECT_EQ(scene.centres[i], scene.onBoard(scene.layout.jobs[i].from));
  }
}

TEST(PegArmGoals, ADescentHeldUpOnThePostIsTriedAgainFurtherFromIt) {
  // The first way down stops 15 mm over the grasp (a jaw on the post's top): a second later the
  // goal goes back up, and the next way down keeps 1 mm more room from the post.
  Scene scene;
  study::PegArmGoals goals(scene.layout, {0});
  const Eigen::Vector2d post = scene.layout.jobs[0].from;
  Eigen::Vector3d tip(0.300, 0.079, scene.layout.geometry.board_top + 0.045);
  std::optional<double> floor;             // while set, the tip gets no lower
  std::vector<double> descents;            // each way down: the goal's distance from the post
  std::optional<double> blocked_at, over;  // over: the first goal's height, over the ring
  for (double t = 0.0; t < 60.0 && descents.size() < 2; t += 0.02) {
    goals.observe(t, tip, jawsDown(), scene.seen());
    const study::ArmGoal goal = goals.goal();
    if (!over) over = goal.point.z();
    const bool going_down = goal.point.z() < *over - 0.01;
    if (going_down && !floor && (descents.empty() || blocked_at)) {
      descents.push_back((goal.point.head<2>() - post).norm());
      if (descents.size() == 1) floor = goal.point.z() + 0.015;
    }
    if (floor && !going_down) {  // it went back up
      blocked_at = t;
      floor.reset();
    }
    tip = goal.point;
    if (floor) tip.z() = std::max(tip.z(), *floor);
  }
  ASSERT_TRUE(blocked_at);
  ASSERT_EQ(descents.size(), 2u);
  // The inner jaw keeps 1 mm more from the post; the jaw axis goes half way between where the
  // jaws clear the post and where they still clear the tube, so it moves by 0.5 to 1 mm.
  EXPECT_GE(descents[1] - descents[0], 0.0005 - 1e-9);
  EXPECT_LE(descents[1] - descents[0], 0.001 + 1e-9);
}

TEST(PegArmGoals, TheOpeningClearsTheTubeAndThePostAndTheSqueezeReachesIntoTheWall) {
  const scenario::PegLayout layout;
  const scenario::RingDimensions& ring = layout.ring;
  const raven::design::ArmDesign jaw;
  const double open = study::PegArmGoals::openingGrasp(ring, layout.geometry.post_radius);
  const double squeeze = study::PegArmGoals::squeezingGrasp(ring);
  // The jaw axis 5 mm over the ring's top, over its centre line; each jaw half the opening from
  // the vertical. Open: the faces are outside the tube where it is widest (10 mm down), and the
  // inner jaw's back at its tip (60 % of the jaw's width) stays off the post.
  const double widest = 0.005 + ring.half_height;
  EXPECT_GT(widest * std::tan(open / 2), ring.tube_half_width);
  const double tip_back =
      jaw.jaw_length * std::sin(open / 2) + 0.6 * jaw.jaw_width * std::cos(open / 2);
  EXPECT_LT(tip_back, ring.major_radius - layout.geometry.post_radius);
  // Closed for the squeeze: each face reaches into the tube's outline (an ellipse a half-height
  // tall under the 5 mm) at most about half the scripted operator's squeeze.
  double deepest = -1.0;
  for (double d = 0.005; d <= std::min(jaw.jaw_length, 0.005 + 2 * ring.half_height); d += 1e-5) {
    const double u = (d - widest) / ring.half_height;
    deepest = std::max(deepest, ring.tube_half_width * std::sqrt(std::max(0.0, 1 - u * u)) -
                                    d * std::tan(squeeze / 2));
  }
  EXPECT_NEAR(deepest, scenario::ArmRoutine::kDefaultSqueeze / 2, 1e-5);
  EXPECT_LT(squeeze, open);
}

}  // namespace
