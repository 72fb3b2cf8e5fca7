#pragma once
// Where a participant answers the questionnaires: the terminal (here), or the pages a browser
// shows (questionnaire_server.hpp). A desk hands back a whole set of answers or nothing, so a
// session seals a questionnaire whole or asks it again when it resumes.

#include <iosfwd>
#include <optional>
#include <string>

#include "study/questionnaire.hpp"

namespace study {

/// Asks a form and hands back its scored answers.
class QuestionnaireDesk {
 public:
  virtual ~QuestionnaireDesk() = default;
  /// Asks `form` after `condition`; empty when the participant could not finish it (the input
  /// ended, the session was stopped).
  virtual std::optional<QuestionnaireAnswers> ask(const QuestionnaireForm& form,
                                                  const std::string& condition) = 0;
};

/// The terminal: each item read from `in` until it is on the scale, then the pairs (1 or 2).
class TerminalDesk : public QuestionnaireDesk {
 public:
  TerminalDesk(std::istream& in, std::ostream& out) : in_(in), out_(out) {}
  std::optional<QuestionnaireAnswers> ask(const QuestionnaireForm& form,
                                          const std::string& condition) override;

 private:
  /// The first line that is one whole number `accept` takes (`rule` shown after each other
  /// line); empty when the input ends.
  template <typename Accept>
  std::optional<int> readAnswer(const std::string& prompt, const std::string& rule, Accept accept);

  std::istream& in_;
  std::ostream& out_;
};

}  // namespace study
