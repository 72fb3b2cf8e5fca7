#pragma once
// The participant's pages, served over HTTP while a session runs, so a tablet or a second screen
// shows what the session says and takes the questionnaires' answers (cpp-httplib, one thread of
// its own). Every answer is judged here; a form comes back with what is wrong until it is whole.

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <ostream>
#include <streambuf>
#include <string>
#include <thread>

#include "study/questionnaire_desk.hpp"
#include "study/questionnaire_pages.hpp"

namespace httplib {
class Server;
}

namespace study {

/// A desk in the browser: GET / shows the open form or the board, POST /answer sends a form.
class QuestionnaireServer : public QuestionnaireDesk {
 public:
  /// Serves on `host`:`port` (0: a free port) until destroyed; `stop` (Ctrl-C) ends a wait for
  /// answers. Throws std::runtime_error naming the address when it cannot listen there.
  QuestionnaireServer(const std::string& host, int port, const std::atomic<bool>* stop);
  ~QuestionnaireServer() override;
  QuestionnaireServer(const QuestionnaireServer&) = delete;
  QuestionnaireServer& operator=(const QuestionnaireServer&) = delete;

  int port() const { return port_; }
  std::string url() const;

  /// What the session says to the participant: echoed to `echo` and kept for the board (its
  /// last lines; a carriage return starts its line again, as a terminal's countdown does).
  std::ostream& board(std::ostream& echo);

  /// Opens `form` on the page and waits for a whole, valid set of answers; empty when stopped.
  std::optional<QuestionnaireAnswers> ask(const QuestionnaireForm& form,
                                          const std::string& condition) override;

 private:
  /// The stream board() hands out: each character to the echo and to the kept text.
  class BoardBuffer : public std::streambuf {
   public:
    BoardBuffer(QuestionnaireServer& server, std::ostream& echo) : server_(server), echo_(echo) {}

   protected:
    int_type overflow(int_type c) override;
    int sync() override;

   private:
    QuestionnaireServer& server_;
    std::ostream& echo_;
  };

  /// The form being asked, if any.
  struct OpenForm {
    QuestionnaireForm form;
    std::string condition;
    int id = 0;
  };

  void route();
  void keep(char c);
  std::string page() const;  ///< under mutex_
  std::string receive(const Submission& submitted);

  std::unique_ptr<httplib::Server> http_;
  std::thread thread_;
  std::atomic<bool> listened_{false};  ///< the server's thread has stopped listening
  std::string host_;
  int port_ = 0;
  const std::atomic<bool>* stop_;

  mutable std::mutex mutex_;
  std::condition_variable answered_;
  std::string board_text_;
  std::optional<OpenForm> open_;
  std::optional<QuestionnaireAnswers> answers_;
  int next_id_ = 1;
  std::string notice_;  ///< shown once on the board (after a form is sent)

  std::unique_ptr<BoardBuffer> board_buffer_;
  std::unique_ptr<std::ostream> board_stream_;
};

}  // namespace study
