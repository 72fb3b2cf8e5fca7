// Counterbalancing: the Williams design puts every condition once in every position and lets
// every condition follow every other equally often.

#include "study/counterbalance.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "study/protocol.hpp"
#include "study/trial_plan.hpp"

namespace {

TEST(Counterbalance, WilliamsDesignsAreLatinAndCarryOverBalanced) {
  for (int n = 1; n <= 6; ++n) {
    const auto rows = study::williamsDesign(n);
    ASSERT_EQ(rows.size(), static_cast<std::size_t>(n % 2 == 0 ? n : 2 * n)) << n;
    std::map<std::pair<int, int>, int> follows;
    for (int position = 0; position < n; ++position) {
      std::map<int, int> seen;
      for (const auto& row : rows) ++seen[row[static_cast<std::size_t>(position)]];
      for (int c = 0; c < n; ++c) {
        EXPECT_EQ(seen[c], static_cast<int>(rows.size()) / n) << "n " << n << " pos " << position;
      }
    }
    for (const auto& row : rows) {
      EXPECT_EQ(std::set<int>(row.begin(), row.end()).size(), static_cast<std::size_t>(n));
      for (int k = 0; k + 1 < n; ++k) ++follows[{row[k], row[k + 1]}];
    }
    for (const auto& [pair, count] : follows) {
      EXPECT_EQ(count, n % 2 == 0 ? 1 : 2) << n << ": " << pair.first << "->" << pair.second;
    }
    EXPECT_EQ(follows.size(), static_cast<std::size_t>(n * (n - 1)));
  }
}

TEST(Counterbalance, PlansShareTheirTargetsAcrossConditions) {
  study::Protocol p;
  p.tasks.resize(2);
  p.tasks[0].name = "reach";
  p.tasks[1].name = "rectangle";
  for (const char* name : {"A", "B", "C"}) {
    p.conditions.emplace_back();
    p.conditions.back().name = name;
  }
  p.trials_per_condition = 2;
  const auto first = study::planTrials(p, 0), second = study::planTrials(p, 1);
  ASSERT_EQ(first.size(), 12u);
  EXPECT_NE(first.front().condition, second.front().condition);
  std::map<std::pair<std::string, int>, std::set<std::uint64_t>> seeds;
  for (const auto& t : first) seeds[{t.task, t.repetition}].insert(t.task_seed);
  for (const auto& [key, s] : seeds) EXPECT_EQ(s.size(), 1u) << key.first;
  EXPECT_NE(first[0].task_seed, first[2].task_seed);  // the next repetition draws anew
}

TEST(Counterbalance, ATaskDoneFewerTimesComesAtTheEndOfEachCondition) {
  study::Protocol p;
  p.tasks.resize(2);
  p.tasks[0].name = "reach";
  p.tasks[1].name = "peg";
  p.tasks[1].trials = 1;
  for (const char* name : {"A", "B"}) {
    p.conditions.emplace_back();
    p.conditions.back().name = name;
  }
  p.trials_per_condition = 3;
  std::vector<std::string> order;
  for (const auto& t : study::planTrials(p, 0)) {
    order.push_back(t.condition + ":" + t.task + std::to_string(t.repetition));
  }
  EXPECT_EQ(order, (std::vector<std::string>{"A:reach0", "A:reach1", "A:reach2", "A:peg0",
                                             "B:reach0", "B:reach1", "B:reach2", "B:peg0"}));
}

}  // namespace
