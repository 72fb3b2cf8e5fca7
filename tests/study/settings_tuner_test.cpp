// The tuner: it spreads its first trials, then finds the cheap corner of a noisy cost, and the
// same history always proposes the same settings.

#include "study/settings_tuner.hpp"

#include <gtest/gtest.h>

#include <random>

namespace {

TEST(SettingsTuner, FindsTheMinimumOfANoisyBowl) {
  const std::vector<study::TunedParameter> box{{"divisor", 800, 4000},
                                               {"velocity_scale", 0.5, 1.0}};
  const study::SettingsTuner tuner(box, 3);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 0.3);
  // Cheapest at divisor 1500, scale 0.9; ten units of cost across the box.
  const auto cost = [&](const std::vector<double>& s) {
    const double a = (s[0] - 1500.0) / 3200.0, b = (s[1] - 0.9) / 0.5;
    return 10.0 + 10.0 * (a * a + b * b) + noise(rng);
  };
  std::vector<study::TuningObservation> history;
  for (int k = 0; k < 14; ++k) {
    const auto next = tuner.propose(history);
    ASSERT_EQ(next.size(), 2u);
    EXPECT_GE(next[0], 800.0);
    EXPECT_LE(next[0], 4000.0);
    EXPECT_GE(next[1], 0.5);
    EXPECT_LE(next[1], 1.0);
    EXPECT_EQ(next, tuner.propose(history));  // deterministic
    history.push_back({next, cost(next)});
  }
  const auto best = tuner.recommend(history);
  EXPECT_NEAR(best.settings[0], 1500.0, 500.0);
  EXPECT_NEAR(best.settings[1], 0.9, 0.12);
  EXPECT_NEAR(best.predicted_cost, 10.0, 1.0);
  EXPECT_THROW(tuner.recommend({}), std::invalid_argument);
}

}  // namespace
