// The FLS-style proficiency line on trials whose answer is known by construction.

#include "study/proficiency.hpp"

#include <gtest/gtest.h>

namespace {

study::TrialRecord trial(const std::string& who, const std::string& scheme, int repetition,
                         double seconds, bool completed = true) {
  study::TrialRecord r;
  r.participant = who;
  r.condition = scheme;
  r.task = "reach";
  r.repetition = repetition;
  r.metrics = {{"completion_time_s", seconds}, {"completed", completed ? 1.0 : 0.0}};
  r.proficiency_time = 12.0;
  return r;
}

TEST(Proficiency, TrialsWithinTheTimeAndParticipantsTwiceInARow) {
  const std::vector<study::TrialRecord> trials{
      // P1 under M2: 10 s and 9 s in a row (repetitions listed out of order), then 20 s.
      trial("P1", "M2", 2, 20.0), trial("P1", "M2", 0, 10.0), trial("P1", "M2", 1, 9.0),
      // P2 under M2: within twice, but never in a row.
      trial("P2", "M2", 0, 10.0), trial("P2", "M2", 1, 20.0), trial("P2", "M2", 2, 9.0),
      // P1 under M1: fast but not completed, then within once.
      trial("P1", "M1", 0, 5.0, false), trial("P1", "M1", 1, 11.0)};
  const nlohmann::json line = study::proficiencySummary(trials);
  EXPECT_EQ(line.at("reach").at("time_s"), 12.0);
  const auto& m2 = line.at("reach").at("schemes").at("M2");
  EXPECT_EQ(m2.at("trials"), 6);
  EXPECT_EQ(m2.at("within"), 4);
  EXPECT_EQ(m2.at("participants"), 2);
  EXPECT_EQ(m2.at("proficient"), 1);
  const auto& m1 = line.at("reach").at("schemes").at("M1");
  EXPECT_EQ(m1.at("within"), 1);
  EXPECT_EQ(m1.at("proficient"), 0);
}

TEST(Proficiency, TasksWithoutATimeAndTuningTrialsAreLeftOut) {
  study::TrialRecord untimed = trial("P1", "M2", 0, 5.0);
  untimed.proficiency_time.reset();
  study::TrialRecord tuning = trial("P1", "M2", 1, 5.0);
  tuning.tuning = true;
  EXPECT_TRUE(study::proficiencySummary({untimed, tuning}).empty());
}

}  // namespace
