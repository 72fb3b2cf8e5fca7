#pragma once
// The participant's pages as HTML, and a submitted form read back: the board (what the session
// says: instructions, countdowns, rests), a questionnaire's form with its answers so far and
// what is wrong with them, and the thanks. Plain HTML that a tablet's browser shows as it is;
// the server judges every answer (fields named item1.., pair1..), never the browser.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "study/questionnaire.hpp"

namespace study {

/// What a participant submitted for a form: each field's text as typed.
using Submission = std::map<std::string, std::string>;

/// A submission read against its form: the scored answers when every field is right, else a
/// message per wrong or missing field (by field name).
struct SubmissionReading {
  std::optional<QuestionnaireAnswers> answers;
  std::map<std::string, std::string> problems;
};

SubmissionReading readSubmission(const QuestionnaireForm& form, const Submission& submitted);

/// The form page; `form_id` goes back with the answers, so a page left open from an earlier
/// form cannot answer this one. `submitted` and `problems` fill the fields and mark them again.
std::string formPage(const QuestionnaireForm& form, const std::string& condition, int form_id,
                     const Submission& submitted = {},
                     const std::map<std::string, std::string>& problems = {});

/// The board: the session's last lines, reloaded every two seconds.
std::string boardPage(const std::string& session_text, const std::string& notice = "");

/// Text made safe inside HTML.
std::string htmlEscaped(const std::string& text);

}  // namespace study
