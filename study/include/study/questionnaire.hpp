#pragma once
// The questionnaires a participant answers after each condition, as forms: what is asked, on
// which scale, and how the answers are scored. Built in: the NASA-TLX (Hart & Staveland 1988),
// raw (Hart 2006) or weighted by its 15 pairwise comparisons; the SURG-TLX (Wilson et al.
// 2011), the same two ways; the System Usability Scale (Brooke 1996). A protocol adds its own
// Likert items. Where a form is asked (the terminal, a browser) is questionnaire_desk.hpp's.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace study {

/// The marks an item is answered with: low..high in steps of `step`.
struct AnswerScale {
  int low = 0;
  int high = 100;
  int step = 5;
  std::string low_label;   ///< what the low end means, e.g. "very low"
  std::string high_label;  ///< what the high end means

  bool valid(int answer) const;
  std::string rule() const;  ///< "0..100 in steps of 5", "1..5"
};

/// One item of a form.
struct QuestionnaireItem {
  std::string label;     ///< short, e.g. "Mental demand"
  std::string question;  ///< as the participant reads it
};

/// How a form's answers become its score.
enum class Scoring {
  Mean,  ///< the items' mean (raw TLX, Likert); with pairwise weights their weighted mean
  Sus    ///< 2.5 x (sum of odd items' a - 1 and even items' 5 - a): 0..100
};

/// One questionnaire as it is asked.
struct QuestionnaireForm {
  std::string name;  ///< "nasa-tlx", "surg-tlx", "sus" or a protocol's Likert set
  std::string title;
  std::string instructions;
  std::vector<QuestionnaireItem> items;
  AnswerScale scale;
  Scoring scoring = Scoring::Mean;
  /// After the ratings, which item of each pair contributed more to the workload (every pair
  /// once: 15 for six items); an item's weight is how often it was chosen.
  bool pairwise_weights = false;

  /// The pairs asked, in order (item indices).
  std::vector<std::pair<int, int>> pairs() const;
};

/// The built-in form `name` ("nasa-tlx", "surg-tlx", "sus"), empty for another name; `weighted`
/// asks the TLXs' pairwise comparisons (the SUS has none).
std::optional<QuestionnaireForm> builtinForm(const std::string& name, bool weighted);

/// A protocol's own Likert items: `points` marks (1..points) from "strongly disagree" to
/// "strongly agree", scored as their mean.
QuestionnaireForm likertForm(const std::string& name, const std::vector<std::string>& statements,
                             int points);

/// The whole number `text` holds (spaces around it allowed), or none: how a typed answer is read,
/// in the terminal and from a page.
std::optional<int> wholeNumber(const std::string& text);

/// One questionnaire's answers and score.
struct QuestionnaireAnswers {
  std::string name;
  std::vector<int> answers;  ///< per item, on the form's scale
  std::vector<int> weights;  ///< per item, times chosen in the pairwise comparisons; or empty
  double score = 0.0;

  nlohmann::json json() const;
  static QuestionnaireAnswers fromJson(const nlohmann::json& j);
};

/// Scores a whole set of answers. `choices` holds, per pair of form.pairs(), the item chosen
/// (one of the pair's two); empty for a form without weights. Throws std::invalid_argument
/// naming the item or the pair for a missing or bad answer.
QuestionnaireAnswers scoreAnswers(const QuestionnaireForm& form, const std::vector<int>& answers,
                                  const std::vector<int>& choices);

}  // namespace study
