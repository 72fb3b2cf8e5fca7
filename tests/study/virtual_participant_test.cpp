// The virtual participant on a plain rate-controlled plant (the stick's deflection past a radial
// deadzone sets the tip's speed, up to a cap): it reaches its targets, a faster mapping (stick
// and speed cap) makes it overshoot more, and a wide deadzone costs it time until it has learnt
// how wide it is.

#include "study/virtual_participant.hpp"

#include <gtest/gtest.h>

namespace {

/// A tip the stick drives like M2 drives an arm: x right, y forward (stick y negative), z with
/// the bumper.
struct Plant {
  double gain = 0.025, cap = 0.025, deadzone = 0.15;
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();

  void step(const recording::GamepadState& pad, double dt) {
    const Eigen::Vector2d stick(pad.left_x, pad.left_y);
    if (stick.norm() <= deadzone) return;
    Eigen::Vector3d v = pad.left_bumper ? Eigen::Vector3d(0, 0, -stick.y())
                                        : Eigen::Vector3d(stick.x(), -stick.y(), 0);
    v *= gain;
    if (v.norm() > cap) v *= cap / v.norm();
    tip += v * dt;
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
