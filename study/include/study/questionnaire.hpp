#pragma once
// The questionnaires a participant answers after each condition, asked in the terminal: the
// NASA-TLX's six scales (Hart & Staveland 1988; unweighted, "raw TLX", Hart 2006) and the
// System Usability Scale's ten items (Brooke 1996), each with its score.

#include <iosfwd>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace study {

/// One questionnaire's answers and score.
struct QuestionnaireAnswers {
  std::string name;          ///< "nasa-tlx" or "sus"
  std::vector<int> answers;  ///< TLX: 0..100 in steps of 5; SUS: 1..5
  double score = 0.0;        ///< raw TLX (mean of the six, 0-100), SUS (0-100)

  nlohmann::json json() const;
  static QuestionnaireAnswers fromJson(const nlohmann::json& j);
};

/// Raw TLX: the mean of the six scales. Throws std::invalid_argument for a bad answer.
double rawTlx(const std::vector<int>& answers);
/// SUS: 2.5 x (sum over odd items of (a - 1) + sum over even items of (5 - a)).
double susScore(const std::vector<int>& answers);

/// Asks questionnaire `name` on `out`, reading answers from `in`; an answer out of range is
/// asked again. Empty when `in` ends first (the session stops and asks again on resume).
std::optional<QuestionnaireAnswers> ask(const std::string& name, const std::string& condition,
                                        std::istream& in, std::ostream& out);

}  // namespace study
