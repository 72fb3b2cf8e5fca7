// The frequency meter and the loop's lock-step and fixed-step modes (no wall-clock asserts).

#include <gtest/gtest.h>

#include <limits>

#include "ambf_like/physics_loop.hpp"
#include "test_files.hpp"

namespace {

using Clock = ambf_like::FrequencyMeter::Clock;
using std::chrono::milliseconds;

TEST(FrequencyMeter, CountsIterationsPerOneSecondWindow) {
  ambf_like::FrequencyMeter meter;
  const auto t0 = Clock::time_point{};
  int closed = 0;
  for (int i = 0; i <= 2000; ++i) closed += meter.tick(t0 + milliseconds(i));  // 1 kHz for 2 s
  EXPECT_EQ(closed, 2);
  EXPECT_NEAR(meter.frequency(), 1000.0, 1e-9);
  for (int i = 1; i <= 250; ++i) meter.tick(t0 + milliseconds(2000 + 4 * i));  // 250 Hz for 1 s
  EXPECT_NEAR(meter.frequency(), 250.0, 1e-9);
  EXPECT_NEAR(meter.minimum(), 250.0, 1e-9);
  EXPECT_NEAR(meter.maximum(), 1000.0, 1e-9);
  EXPECT_EQ(meter.completedWindows(), 3u);
  EXPECT_EQ(meter.iterations(), 2251u);
}

TEST(FrequencyMeter, ReportsNothingBeforeTheFirstWindowCloses) {
  ambf_like::FrequencyMeter meter;
  meter.tick(Clock::time_point{});
  meter.tick(Clock::time_point{} + milliseconds(500));
  EXPECT_EQ(meter.frequency(), 0.0);
  EXPECT_EQ(meter.completedWindows(), 0u);
}

class Loop : public testing::Test {
 protected:
  void SetUp() override {
    sim_ = test_support::simulate(
        {dir_.write("m.yaml",
                    "bodies: [BODY ball]\nBODY ball: {name: ball, mass: 1, collision shape: SPHERE,"
                    " collision geometry: {radius: 0.1}, damping: {linear: 0, angular: 0}}\n")});
  }
  test_support::TempDir dir_;
  std::unique_ptr<test_support::Simulation> sim_;
};

TEST_F(Loop, LockStepAdvancesExactlyToTheExternalClock) {
  auto& world = *sim_->world;
  ambf_like::PhysicsLoop loop(world, {});
  loop.advanceTo(0.0106);
  EXPECT_EQ(world.stepCount(), 11u);  // 10.6 ms: the nearest whole 1 ms step
  loop.advanceTo(0.25);
  EXPECT_EQ(world.stepCount(), 250u);
  EXPECT_DOUBLE_EQ(world.time(), 0.25);
  loop.advanceTo(0.1);  // the past: nothing to do
  EXPECT_EQ(world.stepCount(), 250u);
  EXPECT_EQ(loop.meter().iterations(), 250u);
  // Free fall over 0.25 s with semi-implicit Euler at 1 ms: z = -g h^2 n(n+1)/2.
  EXPECT_NEAR(world.body("ball").pose().translation().z(), -9.81 * 1e-6 * 250 * 251 / 2, 1e-9);
}

TEST_F(Loop, FixedStepIterationsAdvanceOnePeriodEach) {
  auto& world = *sim_->world;
  ambf_like::LoopOptions options;
  options.paced = false;
  options.rate_hz = 250.0;  // 4 ms per iteration: four internal steps
  ambf_like::PhysicsLoop loop(world, options);
  for (int i = 0; i < 10; ++i) loop.iterate();
  EXPECT_EQ(world.stepCount(), 40u);
  EXPECT_EQ(loop.meter().iterations(), 10u);
}

TEST_F(Loop, AnIterationRunsAtMostTheWorldsMaxIterationsAsAmbfDoes) {
  auto& world = *sim_->world;
  ambf_like::LoopOptions options;
  options.paced = false;
  options.rate_hz = 1e-9;  // 1e12 steps of 1 ms per iteration, asked for
  ambf_like::PhysicsLoop loop(world, options);
  loop.iterate();
  EXPECT_EQ(world.stepCount(), static_cast<std::uint64_t>(world.settings().max_iterations));
}

TEST_F(Loop, AStepOutsideAMicrosecondToATenthOfASecondIsRefused) {
  for (double step : {1e-12, 0.0, 1.0, std::numeric_limits<double>::quiet_NaN()}) {
    SCOPED_TRACE(step);
    ambf_like::WorldOptions options;
    options.step_size = step;
    EXPECT_THROW(test_support::simulate({test_support::exampleFile("floor.yaml")}, {}, options),
                 std::invalid_argument);
  }
}

TEST_F(Loop, RejectsANonPositiveRate) {
  ambf_like::LoopOptions options;
  options.rate_hz = 0.0;
  EXPECT_THROW(ambf_like::PhysicsLoop(*sim_->world, options), std::invalid_argument);
}

}  // namespace
