#include "study/questionnaire_server.hpp"

#include <fmt/format.h>
#include <httplib.h>

#include <chrono>
#include <stdexcept>

namespace study {

namespace {

constexpr std::size_t kBoardLines = 40;  ///< the board keeps the session's last lines
constexpr auto kStopCheck = std::chrono::milliseconds(100);
const char* const kHtml = "text/html; charset=utf-8";

/// `text` without its first lines beyond the last `lines`.
void keepLastLines(std::string& text, std::size_t lines) {
  std::size_t count = 0;
  for (std::size_t i = text.size(); i-- > 0;) {
    if (text[i] == '\n' && ++count > lines) {
      text.erase(0, i + 1);
      return;
    }
  }
}

}  // namespace

QuestionnaireServer::QuestionnaireServer(const std::string& host, int port,
                                         const std::atomic<bool>* stop)
    : http_(std::make_unique<httplib::Server>()), host_(host), stop_(stop) {
  // cpp-httplib's default lets a second server share the port (SO_REUSEPORT), which would split
  // a participant's requests between two sessions; here a port in use is refused.
  http_->set_socket_options([](socket_t sock) {
    const int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof(yes));
  });
  route();
  port_ = port == 0 ? http_->bind_to_any_port(host) : (http_->bind_to_port(host, port) ? port : -1);
  if (port_ <= 0) {
    throw std::runtime_error(
        fmt::format("the questionnaires' pages cannot listen on {}:{} (in use, or not an address "
                    "of this machine)",
                    host, port));
  }
  thread_ = std::thread([this] {
    http_->listen_after_bind();
    listened_ = true;
  });
}

QuestionnaireServer::~QuestionnaireServer() {
  // stop() ends a server that is listening and does nothing to one whose thread has not begun
  // to, which would then listen for ever: stop it once it runs.
  while (!listened_) {
    if (http_->is_running()) http_->stop();
    std::this_thread::yield();
  }
  thread_.join();
}

std::string QuestionnaireServer::url() const {
  return fmt::format("http://{}:{}/", host_ == "0.0.0.0" ? "localhost" : host_, port_);
}

void QuestionnaireServer::route() {
  http_->Get("/", [this](const httplib::Request&, httplib::Response& res) {
    const std::lock_guard lock(mutex_);
    res.set_content(page(), kHtml);
  });
  http_->Post("/answer", [this](const httplib::Request& req, httplib::Response& res) {
    Submission submitted;
    for (const auto& [key, value] : req.params) submitted[key] = value;
    res.set_content(receive(submitted), kHtml);
  });
}

std::string QuestionnaireServer::page() const {
  if (open_) return formPage(open_->form, open_->condition, open_->id);
  return boardPage(board_text_, notice_);
}

std::string QuestionnaireServer::receive(const Submission& submitted) {
  const std::lock_guard lock(mutex_);
  const auto id = submitted.find("form");
  if (!open_ || id == submitted.end() || id->second != std::to_string(open_->id)) {
    return boardPage(board_text_, "That form was already closed; the page shows what is open now.");
  }
  SubmissionReading reading = readSubmission(open_->form, submitted);
  if (!reading.answers) {
    return formPage(open_->form, open_->condition, open_->id, submitted, reading.problems);
  }
  notice_ = fmt::format("Thank you: the {} answers are kept.", open_->form.title);
  answers_ = std::move(reading.answers);
  open_.reset();
  answered_.notify_all();
  return boardPage(board_text_, notice_);
}

std::optional<QuestionnaireAnswers> QuestionnaireServer::ask(const QuestionnaireForm& form,
                                                             const std::string& condition) {
  std::unique_lock lock(mutex_);
  open_ = OpenForm{form, condition, next_id_++};
  answers_.reset();
  notice_.clear();
  while (!answers_) {
    if (stop_ && *stop_) {
      open_.reset();
      return std::nullopt;
    }
    answered_.wait_for(lock, kStopCheck);
  }
  return std::exchange(answers_, std::nullopt);
}

std::ostream& QuestionnaireServer::board(std::ostream& echo) {
  if (!board_stream_) {
    board_buffer_ = std::make_unique<BoardBuffer>(*this, echo);
    board_stream_ = std::make_unique<std::ostream>(board_buffer_.get());
  }
  return *board_stream_;
}

void QuestionnaireServer::keep(char c) {
  const std::lock_guard lock(mutex_);
  if (c == '\r') {
    const auto line_start = board_text_.rfind('\n');
    board_text_.erase(line_start == std::string::npos ? 0 : line_start + 1);
    return;
  }
  board_text_ += c;
  if (c == '\n') keepLastLines(board_text_, kBoardLines);
}

QuestionnaireServer::BoardBuffer::int_type QuestionnaireServer::BoardBuffer::overflow(int_type c) {
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  const char ch = traits_type::to_char_type(c);
  echo_.put(ch);
  server_.keep(ch);
  return c;
}

int QuestionnaireServer::BoardBuffer::sync() {
  echo_.flush();
  return 0;
}

}  // namespace study
