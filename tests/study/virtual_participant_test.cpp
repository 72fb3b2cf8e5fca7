// The virtual participant on a plain rate-controlled plant (the stick's deflection past a radial
// deadzone sets the tip's speed, up to a cap): it reaches its targets, a faster mapping (stick
// and speed cap) makes it overshoot more, a wide deadzone costs it time until it has learnt how
// wide it is, and a push the tip does not follow, or whose aim moved, is let go.

#include "study/virtual_participant.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace {

/// A tip the stick drives like M2 drives an arm: x right, y forward (stick y negative), z with
/// the bumper.
struct Plant {
  double gain = 0.025, cap = 0.025, deadzone = 0.15;
  double wall = 1.0;  ///< m: the tip goes no further along x (a tool against a post)
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();

  void step(const recording::GamepadState& pad, double dt) {
    const Eigen::Vector2d stick(pad.left_x, pad.left_y);
    if (stick.norm() <= deadzone) return;
    Eigen::Vector3d v = pad.left_bumper ? Eigen::Vector3d(0, 0, -stick.y())
                                        : Eigen::Vector3d(stick.x(), -stick.y(), 0);
    v *= gain;
    if (v.norm() > cap) v *= cap / v.norm();
    tip += v * dt;
    tip.x() = std::min(tip.x(), wall);
  }
};

struct Outcome {
  int overshoots = 0;
  int reached = 0;
  double time = 0.0;
};

/// One person through four targets 12 mm away (3 mm tolerance, 0.3 s dwell), at 50 Hz.
Outcome reach(Plant plant, std::uint64_t person, int trials_before = 0) {
  const auto traits = study::ParticipantTraits::draw(person);
  study::ConditionFeel feel;
  feel.gain = plant.gain;
  feel.deadzone = plant.deadzone;
  feel.trials_before = trials_before;
  study::VirtualParticipant vp(traits, feel, person + 1000);
  const std::array<Eigen::Vector3d, 4> targets{
      Eigen::Vector3d(0.012, 0, 0), Eigen::Vector3d(0.012, 0.012, 0.004),
      Eigen::Vector3d(0, 0.012, 0), Eigen::Vector3d(0, 0, -0.004)};
  Outcome out;
  bool inside = false;
  double entered = 0.0;
  const double dt = 0.02;
  for (double t = 0.0; t < 60.0 && out.reached < 4; t += dt) {
    std::array<study::ArmGoal, 2> goals;
    goals[0] = {true, targets[static_cast<std::size_t>(out.reached)], 0.003};
    plant.step(vp.act(t, goals, {plant.tip, Eigen::Vector3d::Zero()}), dt);
    const bool now = (plant.tip - goals[0].point).norm() <= 0.003;
    if (now && !inside) entered = t;
    if (!now && inside) ++out.overshoots;
    inside = now;
    if (inside && t - entered >= 0.3) {
      ++out.reached;
      inside = false;
    }
    out.time = t;
  }
  return out;
}

Outcome population(const Plant& plant, int trials_before = 0) {
  Outcome sum;
  for (std::uint64_t person = 1; person <= 12; ++person) {
    const Outcome o = reach(plant, person, trials_before);
    sum.overshoots += o.overshoots;
    sum.reached += o.reached;
    sum.time += o.time;
  }
  return sum;
}

TEST(VirtualParticipant, ReachesItsTargetsOnThePapersMapping) {
  const Outcome o = population(Plant{});
  EXPECT_EQ(o.reached, 48);
  EXPECT_LT(o.time / 12.0, 15.0);
}

TEST(VirtualParticipant, AFasterMappingMakesItOvershootMore) {
  const Outcome paper = population(Plant{});
  const Outcome faster = population(Plant{0.075, 0.075, 0.15});
  EXPECT_GT(faster.overshoots, paper.overshoots + 5)
      << paper.overshoots << " vs " << faster.overshoots;
  // With practice under the faster mapping the belief catches up: fewer overshoots.
  const Outcome practised = population(Plant{0.075, 0.075, 0.15}, 6);
  EXPECT_LT(practised.overshoots, faster.overshoots);
}

TEST(VirtualParticipant, AWideDeadzoneCostsTime) {
  const Outcome paper = population(Plant{});
  const Outcome wide = population(Plant{0.025, 0.025, 0.6});
  EXPECT_EQ(wide.reached, 48);
  EXPECT_GT(wide.time, paper.time * 1.1) << paper.time << " vs " << wide.time;
}

/// The longest time the person held the stick toward +x in one push while `blocked` said the
/// push was in vain, over `seconds` of reaching for the aim `aim(t)` on `plant`.
template <typename Blocked, typename Aim>
double longestBlindPush(std::uint64_t person, Plant plant, Blocked blocked, Aim aim,
                        double seconds) {
  study::ConditionFeel feel;
  study::VirtualParticipant vp(study::ParticipantTraits::draw(person), feel, person + 1000);
  double longest = 0.0, since = -1.0;
  const double dt = 0.002;
  for (double t = 0.0; t < seconds; t += dt) {
    std::array<study::ArmGoal, 2> goals;
    goals[0] = {true, aim(t), 0.003};
    const recording::GamepadState pad = vp.act(t, goals, {plant.tip, Eigen::Vector3d::Zero()});
    const bool pushing = pad.left_x > plant.deadzone && !pad.left_bumper;
    if (pushing && blocked(t, plant)) {
      if (since < 0.0) since = t;
      longest = std::max(longest, t - since + dt);
    } else {
      since = -1.0;
    }
    plant.step(pad, dt);
  }
  return longest;
}

TEST(VirtualParticipant, APushTheToolDoesNotFollowIsLetGo) {
  // A wall 5 mm along x, the aim 30 mm: the first push is planned for about 1.2 s, and meets the
  // wall after 0.2 s. The person sees the tip stop a delay later and lets go: pushing on would
  // only wind the robot's command up against the wall.
  for (std::uint64_t person = 1; person <= 6; ++person) {
    const auto traits = study::ParticipantTraits::draw(person);
    Plant walled;
    walled.wall = 0.005;
    const double pushed = longestBlindPush(
        person, walled, [](double, const Plant& p) { return p.tip.x() >= p.wall; },
        [](double) { return Eigen::Vector3d(0.03, 0, 0); }, 5.0);
    EXPECT_GT(pushed, 0.0) << person;  // it does push into the wall, as a person would
    // Seen stopped: the delay, the 0.1 s it judges speed over, and the tip's own slowing.
    EXPECT_LT(pushed, traits.delay + 0.25) << person;
  }
}

TEST(VirtualParticipant, APushWhoseAimMovesIsLetGo) {
  // The aim 30 mm along +x, moved to 30 mm along -x 0.3 s into the first push (a new target):
  // the push toward +x ends once the person sees the new aim, not at its planned end.
  for (std::uint64_t person = 1; person <= 6; ++person) {
    const auto traits = study::ParticipantTraits::draw(person);
    const auto aim = [](double t) { return Eigen::Vector3d(t < 0.3 ? 0.03 : -0.03, 0, 0); };
    const double pushed = longestBlindPush(
        person, Plant{}, [](double t, const Plant&) { return t >= 0.3; }, aim, 3.0);
    EXPECT_LT(pushed, traits.delay + 0.01) << person;
  }
}

TEST(VirtualParticipant, PopulationDrawsAreReproducibleAndVaried) {
  const auto a = study::ParticipantTraits::draw(3), b = study::ParticipantTraits::draw(3);
  const auto c = study::ParticipantTraits::draw(4);
  EXPECT_EQ(a.json(), b.json());
  EXPECT_NE(a.json(), c.json());
  EXPECT_GE(a.delay, 0.15);
  EXPECT_LE(a.delay, 0.35);
  EXPECT_GE(a.tremor_hz, 8.0);
  EXPECT_LE(a.tremor_hz, 12.0);
}

}  // namespace
