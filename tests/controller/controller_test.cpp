// The controller core on the in-process twin: C_V's step counts, a property test that no
// command stream exceeds a cap or a limit whatever the pad does, and modes O1, O4 and O5.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <optional>
#include <random>

#include "controller/dual_platform_controller.hpp"
#include "random_pad.hpp"
#include "twin/twin_platform.hpp"
#include "twin_fixtures.hpp"

namespace {

using controller::ArmPair;
using raven::Arm;
using raven::ArmJoints;
using recording::GamepadState;

/// A platform that passes everything to another; the fakes below change one call each.
class Forwarding : public bridge::RavenPlatform {
 public:
  explicit Forwarding(bridge::RavenPlatform& inner) : inner_(inner) {}
  bridge::CommandResult send(const bridge::PlatformCommand& c) override { return inner_.send(c); }
  bridge::OperatingStatus operatingStatus() const override { return inner_.operatingStatus(); }
  bridge::JointSample measuredJs(Arm a) const override { return inner_.measuredJs(a); }
  bridge::JointSample setpointJs(Arm a) const override { return inner_.setpointJs(a); }
  bridge::PoseSample measuredCp(Arm a) const override { return inner_.measuredCp(a); }
  bridge::PoseSample setpointCp(Arm a) const override { return inner_.setpointCp(a); }
  std::optional<bridge::RavenStateSnapshot> ravenState() const override {
    return inner_.ravenState();
  }
  bridge::ClockKind clockKind() const override { return inner_.clockKind(); }
  double now() const override { return inner_.now(); }
  void advance(double s) override { inner_.advance(s); }

 protected:
  bridge::RavenPlatform& inner_;
};

/// A platform that passes everything to another and keeps every servo_jr increment it saw.
class CommandLog final : public Forwarding {
 public:
  using Forwarding::Forwarding;
  bridge::CommandResult send(const bridge::PlatformCommand& c) override {
    if (const auto* jr = std::get_if<bridge::ServoJr>(&c)) {
      servo_jr.push_back(*jr);
      sent_at.push_back(inner_.now());
    }
    return inner_.send(c);
  }

  std::vector<bridge::ServoJr> servo_jr;
  std::vector<double> sent_at;  ///< each servo_jr's platform time
};

/// The twin, but its raven_state reports the left wrist's motor pushing up with 1 N m, past the
/// following limit's torque bound: a wrist whose integrator wound up while something held it
/// down on its lower stop (traced in a learning episode, docs/learning.md).
class WoundWrist final : public Forwarding {
 public:
  using Forwarding::Forwarding;
  std::optional<bridge::RavenStateSnapshot> ravenState() const override {
    auto state = inner_.ravenState();
    if (state)
      state->tau[static_cast<std::size_t>(bridge::ravenStateIndex(Arm::Left, raven::kWrist))] = 1.0;
    return state;
  }
};

TEST(FollowingLimitTorque, ASetpointDrawnBackStopsAtTheJointsLimit) {
  // The bound draws the wrist's setpoint down, away from the torque, a capped step a command;
  // at the lower limit the robot's own clamp holds its setpoint, so drawing on relieves nothing.
  // Before the fix the controller's targets ran on past the limit, each step twice as long as
  // the last (-2.3 to -31 rad in six steps).
  auto twin = test_support::readyTwin();
  WoundWrist wound(*twin);
  controller::ControllerOptions options;
  controller::FollowingLimit limit;
  limit.lead.setConstant(1e9);
  limit.torque.setConstant(1e9);
  limit.torque(raven::kWrist) = 0.366;
  limit.give.setConstant(0.01);
  options.following_limit = limit;
  controller::DualPlatformController control({{"twin", &wound}}, options);
  const auto& limits = test_support::physicalProfile().limits;
  ArmPair target = control.commanded();
  target[0](raven::kWrist) = limits.low(raven::kWrist);
  int longest = 0;
  for (int step = 0; step < 6; ++step) {
    longest = std::max(longest, control.moveTo(target).steps);
    ASSERT_GE(control.commanded()[0](raven::kWrist), limits.low(raven::kWrist)) << "step " << step;
    ASSERT_GE(twin->setpointJs(Arm::Left).position(raven::kWrist),
              limits.low(raven::kWrist) - 1e-9);
  }
  EXPECT_EQ(control.commanded()[0](raven::kWrist), limits.low(raven::kWrist))
      << "drawn back to the limit, and held there";
  EXPECT_LE(control.moveTo(target).steps, longest) << "no step grows past the first move";
}

TEST(VelocityCap, AtLeastTenStepsMoreWhenAJointWouldExceedItsCap) {
  const controller::VelocityCaps caps;
  const ArmPair start{ArmJoints::Zero(), ArmJoints::Zero()};
  ArmPair next = start;
  next[0](raven::kShoulder) = 0.001;  // well under 10 steps' worth (1.745e-3)
  EXPECT_EQ(controller::planMove(start, next, caps, 0.002).steps, 10);
  next[1](raven::kInsertion) = 0.002;  // 0.02 m/s * 2 ms = 4e-5 per step: int(50) + 1
  const auto plan = controller::planMove(start, next, caps, 0.002);
  EXPECT_EQ(plan.steps, 51);
  EXPECT_EQ(plan.at(plan.steps)[1], next[1]);
  EXPECT_LE(plan.increment(1)[1](raven::kInsertion), 4e-5);
  // At 1 kHz the same speed caps give twice the steps.
  EXPECT_EQ(controller::planMove(start, next, caps, 0.001).steps, 101);
}

// A move whose first command comes half a period after the previous one: that command carries
// half a step, one more command ends the move, and the commands add up to the move.
TEST(VelocityCap, AShortFirstCommandCarriesItsShareAndOneMoreFinishes) {
  const controller::VelocityCaps caps;
  const ArmPair start{ArmJoints::Zero(), ArmJoints::Zero()};
  ArmPair next = start;
  next[0](raven::kInsertion) = 0.002;
  const auto whole = controller::planMove(start, next, caps, 0.002);
  const auto plan = controller::planMove(start, next, caps, 0.002, 0.5);
  EXPECT_EQ(plan.steps, whole.steps);
  EXPECT_EQ(plan.commands(), whole.commands() + 1);
  EXPECT_DOUBLE_EQ(plan.increment(1)[0](raven::kInsertion),
                   0.5 * whole.increment(1)[0](raven::kInsertion));
  EXPECT_DOUBLE_EQ(plan.increment(2)[0](raven::kInsertion),
                   whole.increment(1)[0](raven::kInsertion));
  EXPECT_DOUBLE_EQ(plan.increment(plan.commands())[0](raven::kInsertion),
                   0.5 * whole.increment(1)[0](raven::kInsertion));
  ArmJoints sum = ArmJoints::Zero();
  for (int k = 1; k <= plan.commands(); ++k) sum += plan.increment(k)[0];
  EXPECT_NEAR(sum(raven::kInsertion), 0.002, 1e-15);
  EXPECT_EQ(plan.at(plan.commands())[0], next[0]);
  EXPECT_THROW(controller::planMove(start, next, caps, 0.002, 0.0), std::invalid_argument);
}

TEST(ControllerProperty, NoCommandStreamExceedsACapOrALimitWhateverThePadDoes) {
  auto twin = test_support::readyTwin();
  CommandLog log(*twin);
  controller::DualPlatformController control({{"twin", &log, controller::CommandStyle::ServoJr}},
                                             {});
  const ArmJoints cap = controller::VelocityCaps{}.perStep(control.period());
  const auto& limits = test_support::physicalProfile().limits;
  std::mt19937_64 random(7);
  std::size_t clamped = 0;
  GamepadState pad;
  for (int i = 0; i < 240; ++i) {
    // Random readings, and adversarial ones held for 40 iterations to drive into the limits.
    if (i % 40 == 0 || i >= 200) pad = test_support::randomPad(random, /*adversarial=*/i < 200);
    const auto report = control.manual(pad);
    clamped += report.clamped;
    ASSERT_EQ(report.refused, 0u) << report.refusal;
    for (const auto& q : control.commanded()) {
      ASSERT_TRUE((q.array() >= limits.low.array()).all() &&
                  (q.array() <= limits.high.array()).all())
          << q.transpose();
    }
  }
  ASSERT_FALSE(log.servo_jr.empty());
  for (const auto& command : log.servo_jr) {
    ASSERT_TRUE((command.increment.cwiseAbs().array() <= cap.array() * (1.0 + 1e-12)).all())
        << command.increment.transpose();
  }
  for (Arm arm : raven::kArms) {  // the robot's own setpoints stayed inside too
    const ArmJoints q = twin->setpointJs(arm).position;
    EXPECT_TRUE((q.array() >= limits.low.array()).all() &&
                (q.array() <= limits.high.array()).all());
  }
  EXPECT_GT(clamped, 0u) << "the adversarial pads should have hit a limit";
}

/// Every servo_jr in `log` moved no joint faster than the caps over the time since that arm's
/// previous command (a period, or one robot cycle after a pad change cut a period short).
void expectWithinCapsOverTheirOwnTime(const CommandLog& log) {
  const raven::ArmJoints per_second = controller::VelocityCaps{}.per_second;
  std::array<std::optional<double>, 2> previous;
  for (std::size_t i = 0; i < log.servo_jr.size(); ++i) {
    auto& last = previous[raven::slot(log.servo_jr[i].arm)];
    if (last) {
      const ArmJoints cap = per_second * (log.sent_at[i] - *last);
      ASSERT_TRUE(
          (log.servo_jr[i].increment.cwiseAbs().array() <= cap.array() * (1.0 + 1e-9) + 1e-15)
              .all())
          << "command " << i << " at " << log.sent_at[i] << " s, " << log.sent_at[i] - *last
          << " s after the previous: " << log.servo_jr[i].increment.transpose();
    }
    last = log.sent_at[i];
  }
}

// The live pad is read after every robot cycle: a new reading ends the iteration there, even
// mid-period, so the next command already follows it; a steady pad runs the same whole
// iterations as without it.
TEST(LivePad, ANewReadingEndsTheIterationAndTheNextCommandFollowsIt) {
  auto steady_twin = test_support::readyTwin();
  auto live_twin = test_support::readyTwin();
  CommandLog steady_log(*steady_twin), live_log(*live_twin);
  controller::DualPlatformController steady({{"twin", &steady_log}}, {});
  controller::DualPlatformController live({{"twin", &live_log}}, {});
  ASSERT_DOUBLE_EQ(live.period(), 0.002) << "the paper's 500 Hz: two robot cycles a period";
  GamepadState idle;
  GamepadState pushed;
  pushed.left_x = 1.0;
  // A steady live pad: the same iterations, command for command.
  const controller::LivePad same = [&] { return std::optional<GamepadState>(idle); };
  for (int i = 0; i < 3; ++i) {
    const auto whole = steady.manual(idle);
    const auto read_every_cycle = live.manual(idle, same);
    EXPECT_EQ(read_every_cycle.steps, whole.steps);
    EXPECT_FALSE(read_every_cycle.cut_short);
  }
  ASSERT_EQ(live_log.servo_jr.size(), steady_log.servo_jr.size());
  for (std::size_t i = 0; i < live_log.servo_jr.size(); ++i) {
    EXPECT_EQ(live_log.servo_jr[i].arm, steady_log.servo_jr[i].arm) << i;
    EXPECT_EQ(live_log.servo_jr[i].increment, steady_log.servo_jr[i].increment) << i;
  }
  EXPECT_DOUBLE_EQ(live_twin->now(), steady_twin->now());
  // The stick is pushed before the third read of an idle iteration: one cycle into its
  // second period.
  int reads = 0;
  const controller::LivePad pushed_at_third_read = [&] {
    return std::optional<GamepadState>(++reads >= 3 ? pushed : idle);
  };
  const double cut_from = live_twin->now();
  const auto cut = live.manual(idle, pushed_at_third_read);
  EXPECT_TRUE(cut.cut_short);
  EXPECT_EQ(cut.steps, 2);
  EXPECT_NEAR(live_twin->now() - cut_from, 0.003, 1e-12) << "a period and one cycle";
  const std::size_t before = live_log.servo_jr.size();
  const auto next = live.manual(pushed, [&] { return std::optional<GamepadState>(pushed); });
  EXPECT_GE(next.steps, 11) << "at least ten whole steps under C_V, the first in two halves";
  ASSERT_EQ(live_log.servo_jr.size(), before + 2 * static_cast<std::size_t>(next.steps));
  // (each command: the left arm's, then the right arm's)
  const ArmJoints first = live_log.servo_jr[before].increment;
  const ArmJoints whole = live_log.servo_jr[before + 2].increment;
  const ArmJoints last = live_log.servo_jr[live_log.servo_jr.size() - 2].increment;
  EXPECT_FALSE(first.isZero()) << "the first command after the push moves";
  EXPECT_TRUE(first.isApprox(0.5 * whole)) << "one cycle after the last: half a step\n"
                                           << first.transpose() << "\n"
                                           << whole.transpose();
  EXPECT_TRUE(last.isApprox(0.5 * whole)) << "and the other half ends the move";
  expectWithinCapsOverTheirOwnTime(live_log);
  // An unplugged pad ends the iteration too, one cycle in.
  const auto unplugged = live.manual(pushed, [] { return std::optional<GamepadState>(); });
  EXPECT_TRUE(unplugged.cut_short);
  EXPECT_EQ(unplugged.steps, 1);
}

// Pads that change at random cycles, at the paper's 500 Hz and at 1 kHz, saturated and
// slammed: no command moves a joint faster than C_V over the time since the one before.
TEST(ControllerProperty, ALivePadChangingMidPeriodNeverExceedsTheCaps) {
  for (double rate : {500.0, 1000.0}) {
    auto twin = test_support::readyTwin();
    CommandLog log(*twin);
    controller::ControllerOptions options;
    options.rate = rate;
    controller::DualPlatformController control({{"twin", &log}}, options);
    std::mt19937_64 random(11);
    std::bernoulli_distribution changes(0.2);
    GamepadState pad = test_support::randomPad(random, true);
    int cut = 0;
    const controller::LivePad live = [&] {
      if (changes(random)) pad = test_support::randomPad(random, true);
      return std::optional<GamepadState>(pad);
    };
    for (int i = 0; i < 300; ++i) {
      const GamepadState reading = pad;  // (the live pad moves on while the iteration runs)
      const auto report = control.manual(reading, live);
      ASSERT_EQ(report.refused, 0u) << report.refusal;
      cut += report.cut_short;
    }
    EXPECT_GT(cut, 100) << "most iterations were cut short, at " << rate << " Hz";
    expectWithinCapsOverTheirOwnTime(log);
  }
}

TEST(ControllerProperty, UnderM1NoCommandMovesTheOtherArm) {
  for (Arm selected : raven::kArms) {
    auto twin = test_support::readyTwin();
    CommandLog log(*twin);
    controller::ControllerOptions options;
    options.scheme = selected == Arm::Left ? controller::MappingScheme::M1Left
                                           : controller::MappingScheme::M1Right;
    controller::DualPlatformController control({{"twin", &log, controller::CommandStyle::ServoJr}},
                                               options);
    const ArmJoints other_start = twin->setpointJs(raven::other(selected)).position;
    std::mt19937_64 random(23);
    GamepadState pad;
    for (int i = 0; i < 150; ++i) {
      if (i % 5 == 0) {
        pad = test_support::randomPad(random, /*adversarial=*/i % 2 == 0);
        // Every input but the one that would select the other arm (A's re-read included).
        if (selected == Arm::Left)
          pad.start = false;
        else
          pad.back = false;
      }
      ASSERT_EQ(control.manual(pad).refused, 0u);
    }
    std::size_t selected_moves = 0;
    for (const auto& command : log.servo_jr) {
      if (command.arm == selected) {
        selected_moves += !command.increment.isZero();
      } else {
        ASSERT_TRUE(command.increment.isZero()) << command.increment.transpose();
      }
    }
    EXPECT_GT(selected_moves, 0u);
    EXPECT_EQ(twin->setpointJs(raven::other(selected)).position, other_start);
  }
}

TEST(ControllerModes, O1HomesUnderTheCaps) {
  auto twin = test_support::readyTwin();
  controller::DualPlatformController control(
      {{"twin", twin.get(), controller::CommandStyle::ServoJr}}, {});
  const auto report = control.home();
  // From the firmware's home (roll 0) to the controller's (roll -pi/4) at 15 deg/s: 3 s.
  EXPECT_NEAR(report.steps, 1500, 1);
  twin->advance(0.1);
  for (Arm arm : raven::kArms) {
    EXPECT_LT((twin->measuredJs(arm).position - test_support::physicalProfile().home)
                  .cwiseAbs()
                  .maxCoeff(),
              1e-5);
  }
}

TEST(ControllerModes, O5DancesEveryJointWithinTheCaps) {
  auto twin = test_support::readyTwin();
  CommandLog log(*twin);
  controller::DualPlatformController control({{"twin", &log, controller::CommandStyle::ServoJr}},
                                             {});
  control.home();
  control.beginMode();
  ArmJoints travelled = ArmJoints::Zero();
  ArmJoints previous = control.commanded()[0];
  for (int i = 0; i < 400; ++i) {
    control.sineDance();
    travelled += (control.commanded()[0] - previous).cwiseAbs();
    previous = control.commanded()[0];
  }
  EXPECT_GT(travelled.minCoeff(), 0.01) << "every joint moves: " << travelled.transpose();
  const ArmJoints cap = controller::VelocityCaps{}.perStep(control.period());
  for (const auto& command : log.servo_jr) {
    ASSERT_TRUE((command.increment.cwiseAbs().array() <= cap.array() * (1.0 + 1e-12)).all());
  }
}

TEST(ControllerModes, O4FollowsRecordedJointsOnTheRecordingsClock) {
  auto twin = test_support::readyTwin();
  controller::DualPlatformController control(
      {{"twin", twin.get(), controller::CommandStyle::ServoJr}}, {});
  control.beginMode();
  const double t0 = twin->now();
  ArmPair target = control.commanded();
  for (int row = 1; row <= 50; ++row) {
    target[0](raven::kShoulder) += 0.0005;  // a slow recorded motion, rows 40 ms apart
    target[1](raven::kInsertion) -= 0.0001;
    control.replayJoints(target, 0.04 * row);
  }
  EXPECT_NEAR(twin->now() - t0, 2.0, 0.002) << "the rows' own timing was kept";
  twin->advance(0.05);
  EXPECT_NEAR(twin->measuredJs(Arm::Left).position(raven::kShoulder), target[0](0), 1e-5);
  EXPECT_NEAR(twin->measuredJs(Arm::Right).position(raven::kInsertion), target[1](2), 1e-6);
}

}  // namespace
