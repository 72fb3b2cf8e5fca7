// The questionnaires: scores as their authors define them (raw and weighted TLX, SUS, Likert),
// answers asked again until valid in the terminal, and a submitted page read back field by field.

#include "study/questionnaire.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "study/questionnaire_desk.hpp"
#include "study/questionnaire_pages.hpp"

namespace {

study::QuestionnaireForm form(const std::string& name, bool weighted = false) {
  return *study::builtinForm(name, weighted);
}

/// The pairwise choices that give each item of six the weight 5 - its index: item i wins
/// against every later item.
std::vector<int> firstAlwaysWins(const study::QuestionnaireForm& f) {
  std::vector<int> choices;
  for (const auto& [a, b] : f.pairs()) choices.push_back(a);
  return choices;
}

TEST(Questionnaire, ScoresFollowTheirDefinitions) {
  const auto sus = form("sus");
  EXPECT_DOUBLE_EQ(study::scoreAnswers(sus, {5, 1, 5, 1, 5, 1, 5, 1, 5, 1}, {}).score, 100.0);
  EXPECT_DOUBLE_EQ(study::scoreAnswers(sus, {3, 3, 3, 3, 3, 3, 3, 3, 3, 3}, {}).score, 50.0);
  EXPECT_DOUBLE_EQ(study::scoreAnswers(sus, {4, 2, 4, 2, 4, 2, 4, 2, 4, 2}, {}).score, 75.0);
  const std::vector<int> ratings{10, 20, 30, 40, 50, 60};
  EXPECT_DOUBLE_EQ(study::scoreAnswers(form("nasa-tlx"), ratings, {}).score, 35.0);
  EXPECT_DOUBLE_EQ(study::scoreAnswers(form("surg-tlx"), ratings, {}).score, 35.0);
  // Weighted: 15 pairs, weights 5, 4, 3, 2, 1, 0; (50 + 80 + 90 + 80 + 50 + 0) / 15.
  for (const char* name : {"nasa-tlx", "surg-tlx"}) {
    const auto weighted = form(name, true);
    ASSERT_EQ(weighted.pairs().size(), 15u);
    const auto answers = study::scoreAnswers(weighted, ratings, firstAlwaysWins(weighted));
    EXPECT_EQ(answers.weights, (std::vector<int>{5, 4, 3, 2, 1, 0}));
    EXPECT_NEAR(answers.score, 350.0 / 15.0, 1e-12);
  }
  const auto likert = study::likertForm("comfort", {"a", "b", "c"}, 7);
  EXPECT_DOUBLE_EQ(study::scoreAnswers(likert, {1, 4, 7}, {}).score, 4.0);
  EXPECT_FALSE(study::builtinForm("tlx", false));
}

TEST(Questionnaire, ABadAnswerIsRefusedNamingItsItem) {
  try {
    study::scoreAnswers(form("nasa-tlx"), {10, 20, 30, 40, 50, 61}, {});
    FAIL() << "61 is not on the TLX's scale";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("item 6 (Frustration)"), std::string::npos) << e.what();
  }
  EXPECT_THROW(study::scoreAnswers(form("sus"), {3, 3}, {}), std::invalid_argument);
  const auto weighted = form("nasa-tlx", true);
  std::vector<int> choices = firstAlwaysWins(weighted);
  choices[0] = 5;  // the first pair is items 0 and 1
  EXPECT_THROW(study::scoreAnswers(weighted, {0, 0, 0, 0, 0, 0}, choices), std::invalid_argument);
}

TEST(Questionnaire, TheTerminalAsksAgainUntilAnAnswerIsValid) {
  std::istringstream in("abc\n105\n55\n7\n0\n100\n50\n 25 \n60\n");
  std::ostringstream out;
  study::TerminalDesk desk(in, out);
  const auto tlx = desk.ask(form("nasa-tlx"), "M2");
  ASSERT_TRUE(tlx);
  EXPECT_EQ(tlx->answers, (std::vector<int>{55, 0, 100, 50, 25, 60}));
  EXPECT_NEAR(tlx->score, 290.0 / 6.0, 1e-12);
  EXPECT_NE(out.str().find("please answer 0..100 in steps of 5"), std::string::npos);
  std::istringstream short_in("3\n4\n");
  study::TerminalDesk short_desk(short_in, out);
  EXPECT_FALSE(short_desk.ask(form("sus"), "M2"));  // the input ended: ask again later
}

TEST(Questionnaire, TheTerminalAsksThePairsOfAWeightedTlx) {
  std::string typed = "10\n20\n30\n40\n50\n60\n3\n";  // "3" is neither of a pair's two
  for (int k = 0; k < 15; ++k) typed += "1\n";
  std::istringstream in(typed);
  std::ostringstream out;
  study::TerminalDesk desk(in, out);
  const auto tlx = desk.ask(form("surg-tlx", true), "M1");
  ASSERT_TRUE(tlx);
  EXPECT_EQ(tlx->weights, (std::vector<int>{5, 4, 3, 2, 1, 0}));
  EXPECT_NE(out.str().find("please answer 1 or 2"), std::string::npos);
}

TEST(QuestionnairePages, ASubmissionIsReadFieldByField) {
  const auto sus = form("sus");
  study::Submission sent;
  for (int i = 1; i <= 10; ++i) sent["item" + std::to_string(i)] = "4";
  sent["item3"] = "9";  // off the scale
  sent.erase("item7");  // skipped
  auto reading = study::readSubmission(sus, sent);
  EXPECT_FALSE(reading.answers);
  ASSERT_EQ(reading.problems.size(), 2u);
  EXPECT_EQ(reading.problems.at("item3"), "please answer 1..5");
  EXPECT_EQ(reading.problems.at("item7"), "please answer this one");
  const std::string page = study::formPage(sus, "B", 7, sent, reading.problems);
  EXPECT_NE(page.find("id=\"item3-problem\""), std::string::npos);
  EXPECT_NE(page.find("name=\"form\" value=\"7\""), std::string::npos);
  sent["item3"] = " 2 ";
  sent["item7"] = "5";
  reading = study::readSubmission(sus, sent);
  ASSERT_TRUE(reading.answers) << reading.problems.begin()->second;
  EXPECT_EQ(reading.answers->answers, (std::vector<int>{4, 4, 2, 4, 4, 4, 5, 4, 4, 4}));
}

TEST(QuestionnairePages, TextIsEscaped) {
  const auto likert = study::likertForm("own", {"<script>alert('x')</script> & more"}, 5);
  const std::string page = study::formPage(likert, "A&B", 1);
  EXPECT_EQ(page.find("<script>"), std::string::npos);
  EXPECT_NE(page.find("&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; more"),
            std::string::npos);
  EXPECT_NE(page.find("A&amp;B"), std::string::npos);
}

}  // namespace
