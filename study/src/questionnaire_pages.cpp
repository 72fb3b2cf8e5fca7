#include "study/questionnaire_pages.hpp"

#include <fmt/format.h>

namespace study {

namespace {

const char* const kStyle =
    "<meta charset=\"utf-8\"><meta name=\"viewport\" content=\"width=device-width, "
    "initial-scale=1\"><style>body{font-family:sans-serif;max-width:46em;margin:1em auto;"
    "padding:0 1em;font-size:1.1em}fieldset{border:1px solid #bbb;margin:.8em 0;padding:.6em}"
    "fieldset.wrong{border:2px solid #c00}.problem{color:#c00;font-weight:bold}"
    "input[type=number]{font-size:1.1em;width:5em}label{margin-right:1em;white-space:nowrap}"
    "pre{white-space:pre-wrap;font-size:1.2em}button{font-size:1.2em;padding:.4em 1.5em}"
    "</style>";

std::string itemField(std::size_t i) {
  return fmt::format("item{}", i + 1);
}
std::string pairField(std::size_t k) {
  return fmt::format("pair{}", k + 1);
}

std::string valueOf(const Submission& submitted, const std::string& field) {
  const auto it = submitted.find(field);
  return it == submitted.end() ? "" : it->second;
}

std::string fieldset(const std::string& field, const std::string& legend, const std::string& body,
                     const std::map<std::string, std::string>& problems) {
  const auto problem = problems.find(field);
  const bool wrong = problem != problems.end();
  return fmt::format("<fieldset id=\"{}-set\"{}><legend>{}</legend>{}{}</fieldset>\n", field,
                     wrong ? " class=\"wrong\"" : "", legend, body,
                     wrong ? fmt::format(" <span class=\"problem\" id=\"{}-problem\">{}</span>",
                                         field, htmlEscaped(problem->second))
                           : "");
}

/// One item: a number field for a long scale (the TLXs' 21 marks), a row of marks otherwise.
std::string itemInput(const AnswerScale& scale, const std::string& field,
                      const std::string& value) {
  if ((scale.high - scale.low) / scale.step > 10) {
    return fmt::format(
        "{} <input type=\"number\" name=\"{}\" id=\"{}\" min=\"{}\" max=\"{}\" step=\"{}\" "
        "inputmode=\"numeric\" value=\"{}\"> {} <small>({})</small>",
        htmlEscaped(scale.low_label), field, field, scale.low, scale.high, scale.step,
        htmlEscaped(value), htmlEscaped(scale.high_label), htmlEscaped(scale.rule()));
  }
  std::string marks = htmlEscaped(scale.low_label) + " ";
  for (int v = scale.low; v <= scale.high; v += scale.step) {
    marks += fmt::format(
        "<label><input type=\"radio\" name=\"{0}\" id=\"{0}-{1}\" value=\"{1}\"{2}> {1}</label>",
        field, v, value == std::to_string(v) ? " checked" : "");
  }
  return marks + " " + htmlEscaped(scale.high_label);
}

}  // namespace

std::string htmlEscaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

SubmissionReading readSubmission(const QuestionnaireForm& form, const Submission& submitted) {
  SubmissionReading reading;
  std::vector<int> answers;
  for (std::size_t i = 0; i < form.items.size(); ++i) {
    const std::string text = valueOf(submitted, itemField(i));
    const auto value = wholeNumber(text);
    if (text.empty()) {
      reading.problems[itemField(i)] = "please answer this one";
    } else if (!value || !form.scale.valid(*value)) {
      reading.problems[itemField(i)] = "please answer " + form.scale.rule();
    } else {
      answers.push_back(*value);
    }
  }
  const auto pairs = form.pairs();
  std::vector<int> choices;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const std::string text = valueOf(submitted, pairField(k));
    if (text == "1" || text == "2") {
      choices.push_back(text == "1" ? pairs[k].first : pairs[k].second);
    } else {
      reading.problems[pairField(k)] = "please choose one of the two";
    }
  }
  if (reading.problems.empty()) reading.answers = scoreAnswers(form, answers, choices);
  return reading;
}

std::string formPage(const QuestionnaireForm& form, const std::string& condition, int form_id,
                     const Submission& submitted,
                     const std::map<std::string, std::string>& problems) {
  std::string body = fmt::format(
      "<!doctype html><html><head>{}<title>{}</title></head><body>\n<h1>{}</h1>\n"
      "<p>Condition <b>{}</b>. {}</p>\n",
      kStyle, htmlEscaped(form.title), htmlEscaped(form.title), htmlEscaped(condition),
      htmlEscaped(form.instructions));
  if (!problems.empty()) {
    body += fmt::format(
        "<p class=\"problem\" id=\"problems\">{} answer{} to look at again, marked in red.</p>\n",
        problems.size(), problems.size() == 1 ? "" : "s");
  }
  body += fmt::format(
      "<form method=\"post\" action=\"/answer\" novalidate>\n"
      "<input type=\"hidden\" name=\"form\" value=\"{}\">\n",
      form_id);
  for (std::size_t i = 0; i < form.items.size(); ++i) {
    const QuestionnaireItem& item = form.items[i];
    const std::string legend =
        item.label == item.question
            ? fmt::format("{}. {}", i + 1, htmlEscaped(item.question))
            : fmt::format("{}. <b>{}</b>: {}", i + 1, htmlEscaped(item.label),
                          htmlEscaped(item.question));
    body +=
        fieldset(itemField(i), legend,
                 itemInput(form.scale, itemField(i), valueOf(submitted, itemField(i))), problems);
  }
  const auto pairs = form.pairs();
  if (!pairs.empty()) {
    body += "<h2>Which contributed more to the workload?</h2>\n";
  }
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const std::string field = pairField(k);
    const std::string chosen = valueOf(submitted, field);
    std::string options;
    for (const int side : {1, 2}) {
      const QuestionnaireItem& item = form.items[side == 1 ? pairs[k].first : pairs[k].second];
      options += fmt::format(
          "<label><input type=\"radio\" name=\"{0}\" id=\"{0}-{1}\" value=\"{1}\"{2}> {3}</label>",
          field, side, chosen == std::to_string(side) ? " checked" : "", htmlEscaped(item.label));
    }
    body += fieldset(field, fmt::format("Pair {}", k + 1), options, problems);
  }
  return body + "<button type=\"submit\" id=\"send\">Send</button>\n</form></body></html>\n";
}

std::string boardPage(const std::string& session_text, const std::string& notice) {
  return fmt::format(
      "<!doctype html><html><head>{}<meta http-equiv=\"refresh\" content=\"2\">"
      "<title>Raven-II study</title></head><body>\n<h1>Raven-II study</h1>\n{}"
      "<pre id=\"board\">{}</pre>\n<p><small>This page follows the session; the questionnaires "
      "appear here when it is time for them.</small></p></body></html>\n",
      kStyle, notice.empty() ? "" : "<p id=\"notice\"><b>" + htmlEscaped(notice) + "</b></p>\n",
      htmlEscaped(session_text));
}

}  // namespace study
