// The participant's pages over real HTTP (cpp-httplib's client against the server): the board
// follows the session's words, a form comes back marked until it is whole, its answers reach the
// session, a page from a closed form is turned away, and a stop ends the wait with nothing.

#include "study/questionnaire_server.hpp"

#include <gtest/gtest.h>
#include <httplib.h>

#include <future>
#include <sstream>

namespace {

/// GET / until the page holds `text` (the asking thread opens its form at its own pace); the
/// last page either way. Each try is a whole HTTP round trip, so the loop is bounded by them.
std::string pageOnceItShows(httplib::Client& client, const std::string& text) {
  std::string body;
  for (int tries = 0; tries < 10000; ++tries) {
    const auto res = client.Get("/");
    if (res && res->status == 200) body = res->body;
    if (body.find(text) != std::string::npos) break;
  }
  return body;
}

httplib::Params susAnswers(const std::string& form_id, const std::string& third) {
  httplib::Params p{{"form", form_id}};
  for (int i = 1; i <= 10; ++i) p.emplace("item" + std::to_string(i), i == 3 ? third : "4");
  return p;
}

TEST(QuestionnaireServer, AFormIsAnsweredThroughThePagesAndMarkedUntilWhole) {
  std::atomic<bool> stop{false};
  study::QuestionnaireServer server("127.0.0.1", 0, &stop);
  ASSERT_GT(server.port(), 0);
  std::ostringstream echo;
  server.board(echo) << "Trial 1 of 4: reach\rTrial 2 of 4: reach\n" << std::flush;
  EXPECT_EQ(echo.str(), "Trial 1 of 4: reach\rTrial 2 of 4: reach\n");
  httplib::Client client("127.0.0.1", server.port());
  const auto board = client.Get("/");
  ASSERT_TRUE(board);
  EXPECT_NE(board->body.find("Trial 2 of 4"), std::string::npos);
  EXPECT_EQ(board->body.find("Trial 1 of 4"), std::string::npos);  // the \r started it again

  auto asked = std::async(std::launch::async,
                          [&] { return server.ask(*study::builtinForm("sus", false), "B"); });
  const std::string form = pageOnceItShows(client, "System Usability Scale");
  ASSERT_NE(form.find("name=\"form\" value=\"1\""), std::string::npos) << form;

  auto res = client.Post("/answer", susAnswers("1", "6"));
  ASSERT_TRUE(res);
  EXPECT_NE(res->body.find("id=\"item3-problem\""), std::string::npos);  // asked again
  EXPECT_NE(res->body.find("value=\"4\" checked"), std::string::npos);   // the rest kept
  res = client.Post("/answer", susAnswers("0", "2"));                    // a page from another form
  ASSERT_TRUE(res);
  EXPECT_NE(res->body.find("already closed"), std::string::npos);
  res = client.Post("/answer", susAnswers("1", "2"));
  ASSERT_TRUE(res);
  EXPECT_NE(res->body.find("Thank you"), std::string::npos);
  const auto answers = asked.get();
  ASSERT_TRUE(answers);
  EXPECT_EQ(answers->answers, (std::vector<int>{4, 4, 2, 4, 4, 4, 4, 4, 4, 4}));
  EXPECT_DOUBLE_EQ(answers->score, 2.5 * (3 + 1 + 1 + 1 + 3 + 1 + 3 + 1 + 3 + 1));
}

TEST(QuestionnaireServer, AStopEndsTheWaitWithNothing) {
  std::atomic<bool> stop{false};
  study::QuestionnaireServer server("127.0.0.1", 0, &stop);
  auto asked = std::async(std::launch::async,
                          [&] { return server.ask(*study::builtinForm("nasa-tlx", true), "A"); });
  httplib::Client client("127.0.0.1", server.port());
  ASSERT_NE(pageOnceItShows(client, "Pair 15").find("Pair 15"), std::string::npos);
  stop = true;
  EXPECT_FALSE(asked.get());
  EXPECT_EQ(pageOnceItShows(client, "Raven-II study").find("Pair 15"), std::string::npos);
}

TEST(QuestionnaireServer, AnAddressItCannotListenOnIsNamed) {
  std::atomic<bool> stop{false};
  study::QuestionnaireServer first("127.0.0.1", 0, &stop);
  try {
    study::QuestionnaireServer second("127.0.0.1", first.port(), &stop);
    FAIL() << "two servers on one port";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("127.0.0.1:" + std::to_string(first.port())),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
