// The questionnaires: scores as their authors define them, and answers asked again until valid.

#include "study/questionnaire.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace {

TEST(Questionnaire, ScoresFollowTheirDefinitions) {
  EXPECT_DOUBLE_EQ(study::susScore({5, 1, 5, 1, 5, 1, 5, 1, 5, 1}), 100.0);
  EXPECT_DOUBLE_EQ(study::susScore({3, 3, 3, 3, 3, 3, 3, 3, 3, 3}), 50.0);
  EXPECT_DOUBLE_EQ(study::susScore({4, 2, 4, 2, 4, 2, 4, 2, 4, 2}), 75.0);
  EXPECT_DOUBLE_EQ(study::rawTlx({10, 20, 30, 40, 50, 60}), 35.0);
  EXPECT_THROW(study::susScore({3, 3}), std::invalid_argument);
  EXPECT_THROW(study::rawTlx({10, 20, 30, 40, 50, 61}), std::invalid_argument);
}

TEST(Questionnaire, InvalidAnswersAreAskedAgain) {
  std::istringstream in("abc\n105\n55\n7\n0\n100\n50\n 25 \n60\n");
  std::ostringstream out;
  const auto tlx = study::ask("nasa-tlx", "M2", in, out);
  ASSERT_TRUE(tlx);
  EXPECT_EQ(tlx->answers, (std::vector<int>{55, 0, 100, 50, 25, 60}));
  EXPECT_NEAR(tlx->score, 290.0 / 6.0, 1e-12);
  EXPECT_NE(out.str().find("please answer 0..100 in steps of 5"), std::string::npos);
  std::istringstream short_in("3\n4\n");
  EXPECT_FALSE(study::ask("sus", "M2", short_in, out));  // the input ended: ask again later
}

}  // namespace
