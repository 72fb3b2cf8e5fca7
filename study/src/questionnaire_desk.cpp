#include "study/questionnaire_desk.hpp"

#include <fmt/format.h>

#include <istream>
#include <ostream>

namespace study {

template <typename Accept>
std::optional<int> TerminalDesk::readAnswer(const std::string& prompt, const std::string& rule,
                                            Accept accept) {
  for (;;) {
    out_ << prompt << std::flush;
    std::string line;
    if (!std::getline(in_, line)) return std::nullopt;
    if (const auto a = wholeNumber(line); a && accept(*a)) return a;
    out_ << "  please answer " << rule << '\n';
  }
}

std::optional<QuestionnaireAnswers> TerminalDesk::ask(const QuestionnaireForm& form,
                                                      const std::string& condition) {
  out_ << fmt::format("\n{} for condition {}: {}\n", form.title, condition, form.instructions)
       << fmt::format("Answer {} ({} .. {}).\n", form.scale.rule(), form.scale.low_label,
                      form.scale.high_label);
  const std::size_t count = form.items.size();
  std::vector<int> answers;
  for (std::size_t i = 0; i < count; ++i) {
    const auto a = readAnswer(
        fmt::format("  {}/{} {}: {} > ", i + 1, count, form.items[i].label, form.items[i].question),
        form.scale.rule(), [&](int v) { return form.scale.valid(v); });
    if (!a) return std::nullopt;
    answers.push_back(*a);
  }
  const auto pairs = form.pairs();
  std::vector<int> choices;
  if (!pairs.empty()) out_ << "Which contributed more to the workload? Answer 1 or 2.\n";
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto [a, b] = pairs[k];
    const auto pick = readAnswer(fmt::format("  {}/{} 1 {}, 2 {} > ", k + 1, pairs.size(),
                                             form.items[a].label, form.items[b].label),
                                 "1 or 2", [](int v) { return v == 1 || v == 2; });
    if (!pick) return std::nullopt;
    choices.push_back(*pick == 1 ? a : b);
  }
  QuestionnaireAnswers result = scoreAnswers(form, answers, choices);
  out_ << fmt::format("  score {:.1f}\n", result.score);
  return result;
}

}  // namespace study
