// The study's statistics against values computed independently (SciPy 1.10: ttest_rel,
// wilcoxon(method="exact"), the noncentral t) and the textbook's (Holm 1979; Cohen's tables).

#include "study/statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

const std::vector<double> kA{12.1, 14.3, 11.8, 15.2, 13.9, 12.7, 14.8, 13.1};
const std::vector<double> kB{13.0, 15.1, 12.9, 15.0, 15.2, 13.9, 15.95, 14.05};

TEST(Statistics, PairedTTestMatchesScipy) {
  const auto t = study::pairedT(kA, kB);
  EXPECT_NEAR(t.t, -5.366563145999499, 1e-9);
  EXPECT_EQ(t.df, 7);
  EXPECT_NEAR(t.p, 0.0010453728356434357, 1e-9);
  EXPECT_NEAR(t.dz, t.t / std::sqrt(8.0), 1e-12);
  EXPECT_THROW(study::pairedT({1.0}, {2.0}), std::invalid_argument);
  EXPECT_DOUBLE_EQ(study::pairedT({1, 2, 3}, {1, 2, 3}).p, 1.0);
}

TEST(Statistics, ExactSignedRankMatchesScipy) {
  const auto w = study::wilcoxonSignedRank(kA, kB);
  EXPECT_TRUE(w.exact);
  EXPECT_DOUBLE_EQ(w.w_plus, 1.0);
  EXPECT_NEAR(w.p, 0.015625, 1e-12);  // 2 x 2 / 2^8
  EXPECT_NEAR(w.rank_biserial, (1.0 - 35.0) / 36.0, 1e-12);
}

TEST(Statistics, HolmStepsDown) {
  const auto adjusted = study::holm({0.01, 0.04, 0.03});
  EXPECT_NEAR(adjusted[0], 0.03, 1e-12);
  EXPECT_NEAR(adjusted[1], 0.06, 1e-12);
  EXPECT_NEAR(adjusted[2], 0.06, 1e-12);
}

TEST(Statistics, PairedPowerMatchesTheNoncentralT) {
  EXPECT_NEAR(study::pairedTPower(0.5, 20, 0.05), 0.564504418439038, 1e-6);
  EXPECT_EQ(study::pairsNeeded(0.5, 0.05, 0.8), 34);
  EXPECT_EQ(study::pairsNeeded(0.8, 0.05, 0.8), 15);
  EXPECT_EQ(study::pairsNeeded(1.2, 0.05, 0.8), 8);
  EXPECT_EQ(study::pairsNeeded(0.0, 0.05, 0.8), -1);
}

}  // namespace
